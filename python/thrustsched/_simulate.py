"""The year loop (``thrustsched simulate``) from Python, with a progress bar.

    run = simulate(Scenario.load("data/scenarios/year/year_anzel4_fixed.json"), cycles=2, out="out/year")
    run.cycles          # DataFrame of cycles.csv
    run.year            # year.json
"""
from __future__ import annotations

import json
import os
import sys
from typing import Any, Callable, Dict, Optional, Union

from . import _core
from ._scenario import PathLike, Scenario, as_scenario


class SimulationResult:
    """A year run's files (the CLI's): ``out`` (the folder), ``year``
    (year.json as a dict), ``cycles`` (cycles.csv as a DataFrame),
    ``interrupted`` (Ctrl-C stopped it: the finished cycles are saved;
    ``simulate(..., resume=True)`` continues), ``exit_code`` (the CLI's)."""

    def __init__(self, out: str, exit_code: int, interrupted: bool):
        self.out = out
        self.exit_code = exit_code
        self.interrupted = interrupted
        self.year: Dict[str, Any] = {}
        path = os.path.join(out, "year.json")
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                self.year = json.load(f)
        self._cycles = None

    @property
    def cycles(self):
        if self._cycles is None:
            import pandas as pd

            self._cycles = pd.read_csv(os.path.join(self.out, "cycles.csv"))
        return self._cycles

    @property
    def trajectory(self):
        import pandas as pd

        return pd.read_csv(os.path.join(self.out, "trajectory.csv"))

    def __repr__(self) -> str:
        return f"SimulationResult(out={self.out!r}, cycles={len(self.cycles)}, interrupted={self.interrupted})"


def _progress(kind: Union[bool, Callable, None]) -> Optional[Callable[[Dict[str, Any]], None]]:
    if kind is None or kind is False:
        return None
    if callable(kind) and kind is not True:
        return kind
    try:
        from tqdm.auto import tqdm  # type: ignore
    except ImportError:
        tqdm = None
    state: Dict[str, Any] = {"bar": None}

    def line(d: Dict[str, Any]) -> str:
        return (f"cycle {d['cycle']} ({d['done']}/{d['target']}): {d['status']}"
                f"{'' if d['fallback'] == 'none' else ' (fallback ' + d['fallback'] + ')'}, "
                f"{d['consumption_l1_m_s']:.4g} m/s, solve {d['solve_seconds']:.3g} s, "
                f"max |lat| {d['max_abs_lat_deg']:.3g} |lon| {d['max_abs_lon_deg']:.3g} deg")

    def show(d: Dict[str, Any]) -> None:
        if d.get("phase") != "cycle":
            if d.get("message"):
                print(f"thrustsched: {d['message']}", file=sys.stderr, flush=True)
            return
        if tqdm is None:
            print(line(d), file=sys.stderr, flush=True)
            return
        if state["bar"] is None:
            state["bar"] = tqdm(total=d["target"], initial=d["done"] - 1, unit="cycle")
        state["bar"].update(1)
        state["bar"].set_postfix_str(f"{d['consumption_l1_m_s']:.3g} m/s, {d['status']}")
        if d["done"] >= d["target"]:
            state["bar"].close()

    return show


def simulate(scn_year: Any, cycles: Optional[int] = None, out: Optional[PathLike] = None,
             resume: bool = True, force: bool = False, plots: bool = True,
             progress: Union[bool, Callable, None] = True) -> SimulationResult:
    """``thrustsched simulate``: a long GEO station-keeping run of chained cycle
    MILPs closed through the nonlinear model (the scenario's "long_horizon"
    section, data/scenarios/README.md).

    cycles: stop once this many cycles (in total) are done (None: all).
    out: the run folder (default out/<scenario file stem>); every finished
    cycle is written at once (cycles.csv, cycles/, checkpoint.json, year.json).
    resume: continue from out/checkpoint.json when there is one (the CLI's
    --resume; without a checkpoint it starts at cycle 1). force: start over in
    a folder holding an earlier run. plots: run gnuplot for the SVG plots.
    progress: True (a tqdm bar when tqdm is installed, plain lines on stderr
    otherwise), False, or a callable receiving one dict per finished cycle.
    Ctrl-C stops the running cycle's solve (not recorded) and returns with
    ``interrupted`` True; a second Ctrl-C raises KeyboardInterrupt.
    """
    scn = as_scenario(scn_year)
    source = scn.path or "scenario.json"
    if out is None:
        out = os.path.join("out", os.path.splitext(os.path.basename(source))[0])
    out = os.fspath(out)
    code, interrupted = _core.simulate(scn.to_json(indent=None), source, out, cycles, resume, force, plots,
                                       True, _progress(progress))
    return SimulationResult(out, code, interrupted)
