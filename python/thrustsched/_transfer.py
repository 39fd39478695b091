"""Orbit transfers (``thrustsched transfer``) from Python.

    res = transfer(data_path("scenarios/transfer/gto_geo_caillau_60n.json"))
    res.summary["duration_h"]        # 14.800364 (summary.json as a dict)
    res.trajectory                   # DataFrame of trajectory.csv
    res.orbit                        # DataFrame of orbit.csv (Cartesian states)
    res.summary["final_state"]       # a station-keeping scenario's initial_state
    transfer(path, progress=print)   # continuation steps; Ctrl-C returns the best so far (res.interrupted)
"""
from __future__ import annotations

import io
import json
from collections.abc import Mapping
from typing import Any, Callable, Dict, Optional, Union

from . import _core
from ._scenario import PathLike, _document_text


class TransferResult:
    """A transfer's results, the CLI's files without the folder:
    ``summary`` (summary.json as a dict: ``status``, ``duration_s``/``_h``/``_d``,
    ``propellant_kg``, ``final_elements``, ``errors``, ``convergence``,
    ``final_state``, ...; fields in data/scenarios/transfer/README.md),
    ``trajectory`` (trajectory.csv: time, equinoctial elements, a, e, i,
    mass, thrust command in QSW) and ``orbit`` (orbit.csv: position,
    velocity and mass), both pandas DataFrames."""

    def __init__(self, summary: Dict[str, Any], trajectory_csv: str, orbit_csv: str):
        self.summary = summary
        self._trajectory_csv = trajectory_csv
        self._orbit_csv = orbit_csv
        self._trajectory = None
        self._orbit = None

    @property
    def status(self) -> str:
        return self.summary["status"]

    @property
    def converged(self) -> bool:
        return self.summary["status"] == "converged"

    @property
    def interrupted(self) -> bool:
        """A Ctrl-C stopped the transfer: the result is the best one so far
        (the last converged continuation step, or the feedback up to there)."""
        return bool(self.summary.get("interrupted", False))

    @property
    def trajectory(self):
        if self._trajectory is None:
            import pandas as pd

            self._trajectory = pd.read_csv(io.StringIO(self._trajectory_csv))
        return self._trajectory

    @property
    def orbit(self):
        if self._orbit is None:
            import pandas as pd

            self._orbit = pd.read_csv(io.StringIO(self._orbit_csv))
        return self._orbit

    def __repr__(self) -> str:
        s = self.summary
        return (f"TransferResult({s['method']}, {s['status']}, {s['duration_h']:.6g} h, "
                f"propellant {s['propellant_kg']:.6g} kg)")


def transfer(scenario: Union[PathLike, Mapping], method: Optional[str] = None,
             progress: Optional[Callable[[Dict[str, Any]], None]] = None) -> TransferResult:
    """Runs an orbit transfer as ``thrustsched transfer`` does (minimum time by
    shooting, Lyapunov feedback or two impulses) and returns a
    :class:`TransferResult` (no files written).

    ``scenario`` is a transfer scenario file's path or its content as a dict
    (``{"name": ..., "transfer": {...}}``, data/scenarios/transfer/README.md);
    ``method`` (``"minimum_time"``, ``"feedback"``, ``"two_impulse"``)
    overrides the scenario's. A bad field raises :class:`ScenarioError` (a
    ``ValueError``) with the CLI's message (field path and value). The GIL
    is released while the transfer runs. The first Ctrl-C stops it and
    returns the best result so far (``status`` ``"interrupted"``: the last
    converged thrust of the continuation,
    ``summary["convergence"]["continuation_thrust_reached_n"]``, or the
    feedback up to where it stopped); the second raises KeyboardInterrupt.
    ``progress(dict)``, if given, is called with ``{"phase": "continuation",
    "thrust_n", "converged", "duration_s"}`` after every continuation step,
    ``{"phase": "switch", ...}`` after every try of the feedback's optimal
    end and ``{"phase": "stopping", "message"}`` on the first Ctrl-C."""
    text, source = _document_text(scenario, "transfer scenario", "transfer")
    if source is None:
        source = getattr(scenario, "path", None) or ""
    if method is not None and not isinstance(method, str):
        raise TypeError(f"transfer: method must be a string, got {type(method).__name__}")
    if progress is not None and not callable(progress):
        raise TypeError(f"transfer: progress must be callable, got {type(progress).__name__}")
    summary, trajectory, orbit, _ = _core.transfer(text, source, method, progress)
    return TransferResult(json.loads(summary), trajectory, orbit)
