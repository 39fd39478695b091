"""Fleets (several spacecraft in one MILP) from Python.

    res = fleet(data_path("scenarios/fleet/di_swap.json"))
    res.status, res.objective              # "optimal", 3.0
    res.summary["members"][1]["burns"]     # summary.json as a dict
    res.pairs                              # DataFrame of fleet.csv (pairwise minimum distances)
    res.schedules["b"], res.trajectories["b"]   # per member, the single-scenario CSV columns
"""
from __future__ import annotations

import io
import json
import os
from collections.abc import Mapping
from typing import Any, Callable, Dict, List, Optional, Union

from . import _core
from ._scenario import PathLike, _document_text


class FleetResult:
    """A fleet solve's results, the CLI's files without the folder:
    ``summary`` (summary.json as a dict: ``status``, ``objective``,
    ``best_bound``, ``gap``, ``members`` with each one's consumption, burns
    and check, ``pairs``, ``coupling_residuals``; data/scenarios/README.md,
    "Fleet files"), ``pairs`` (fleet.csv as a DataFrame), ``schedules`` and
    ``trajectories`` (dicts member name -> DataFrame, empty without
    schedules), ``interrupted``."""

    def __init__(self, summary: Dict[str, Any], fleet_csv: str, schedules: List[str],
                 trajectories: List[str], interrupted: bool):
        import pandas as pd

        self.summary = summary
        self.interrupted = bool(interrupted)
        self.pairs = pd.read_csv(io.StringIO(fleet_csv))
        names = [m["name"] for m in summary["members"]]
        self.schedules = {n: pd.read_csv(io.StringIO(t)) for n, t in zip(names, schedules)}
        self.trajectories = {n: pd.read_csv(io.StringIO(t)) for n, t in zip(names, trajectories)}

    @property
    def status(self) -> str:
        return self.summary["status"]

    @property
    def objective(self) -> float:
        v = self.summary.get("objective")
        return float("nan") if v is None else float(v)

    @property
    def has_schedule(self) -> bool:
        return self.status in ("optimal", "feasible")

    def __repr__(self) -> str:
        return (f"FleetResult({self.summary['name']!r}, {self.status}, objective={self.objective:.8g}, "
                f"{len(self.summary['members'])} members)")


def fleet(scenario: Union[PathLike, Mapping], *, time_limit_s: Optional[float] = None,
          relative_gap: Optional[float] = None, threads: Optional[int] = None,
          progress: Optional[Callable[[Dict[str, Any]], None]] = None,
          base_dir: Optional[PathLike] = None) -> FleetResult:
    """Solves a fleet scenario (a file with a ``"fleet"`` section) as
    ``thrustsched solve`` does and returns a :class:`FleetResult` (no files
    written).

    ``scenario`` is the file's path or its content as a dict; member
    scenarios given as paths are read relative to the file's folder (a
    dict: ``base_dir``, default the working directory). ``time_limit_s``,
    ``relative_gap`` and ``threads`` override the fleet's ``solver``
    section. A bad field raises :class:`ScenarioError` (a ``ValueError``)
    with the CLI's message. The GIL is released while CBC runs; the first
    Ctrl-C stops the solve and returns the best schedules found
    (``interrupted``), the second raises KeyboardInterrupt. ``progress(dict)``
    receives the solver's progress reports."""
    text, source = _document_text(scenario, "fleet scenario", "fleet")
    if base_dir is not None:
        folder = os.fspath(base_dir)
    else:
        folder = os.path.dirname(source) if source else os.getcwd()
    source = source or ""
    if progress is not None and not callable(progress):
        raise TypeError(f"fleet: progress must be callable, got {type(progress).__name__}")
    summary, fleet_csv, schedules, trajectories, interrupted = _core.fleet(
        text, source, folder, time_limit_s, relative_gap, threads, progress)
    return FleetResult(json.loads(summary), fleet_csv, schedules, trajectories, interrupted)
