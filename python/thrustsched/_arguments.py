"""Arguments shared by the scenario functions (_api) and the array problems
(_problem): the progress argument and schedule tables. Both modules import
this one; it imports neither, so they do not import each other.

    cb = progress_callback(True)                         # None, True or a callable
    names, start_s, end_s = schedule_columns(df, impulsive=False)
"""
from __future__ import annotations

import sys
from typing import Any, Callable, Dict, List, Tuple, Union

import numpy as np

from ._results import SolveResult

ProgressArg = Union[None, bool, Callable[[Dict[str, Any]], Any]]


def _progress_printer(delay_s: float = 3.0) -> Callable[[Dict[str, Any]], None]:
    """Plain progress lines on stderr once the solve has run for delay_s (the CLI's)."""

    def show(d: Dict[str, Any]) -> None:
        phase = d.get("phase")
        if phase in ("announce", "stopping"):
            print(f"thrustsched: {d.get('message')}", file=sys.stderr, flush=True)
            return
        t = d.get("wall_seconds", 0.0)
        if t < delay_s:
            return
        stage = f"{d['stage']}: " if d.get("stage") else ""
        if d.get("stage_begins"):
            print(f"  [{t:.2f} s] {stage}begins; incumbent {d.get('objective'):.6g}, bound {d.get('best_bound'):.6g}",
                  file=sys.stderr, flush=True)
            return
        if phase == "root_lp":
            print(f"  [{t:.2f} s] {stage}root LP relaxation: {d.get('lp_iterations')} iterations", file=sys.stderr,
                  flush=True)
            return
        gap = d.get("gap")
        gap_s = "n/a" if gap is None or gap != gap else f"{100 * gap:.3g}%"
        print(f"  [{t:.2f} s] {stage}{phase}: incumbent {d.get('objective'):.6g}, bound {d.get('best_bound'):.6g}, "
              f"gap {gap_s}, {d.get('nodes')} nodes{' (new incumbent)' if d.get('new_incumbent') else ''}",
              file=sys.stderr, flush=True)

    return show


def progress_callback(progress: ProgressArg):
    """The callable the C++ solve calls: None (silent), the plain printer
    (True) or the caller's callable."""
    if progress is None or progress is False:
        return None
    if progress is True:
        return _progress_printer()
    if callable(progress):
        return progress
    raise TypeError("progress: expected None, True or a callable taking a dict")


def schedule_columns(schedule: Any, impulsive: bool) -> Tuple[List[str], List[float], List[float]]:
    """(thrusters, a, b) from a DataFrame, a SolveResult, a list of dicts or a
    dict of columns: (start_s, end_s), or for impulsive scenarios (node,
    delta_v_m_s)."""
    if isinstance(schedule, SolveResult):
        schedule = schedule.schedule
    keys = ("thruster", "node", "delta_v_m_s") if impulsive else ("thruster", "start_s", "end_s")
    if isinstance(schedule, (list, tuple)):
        cols = {k: [row[k] for row in schedule] for k in keys}
    else:
        try:
            cols = {k: schedule[k] for k in keys}
        except KeyError as e:
            raise ValueError(f"schedule: missing column {e.args[0]!r} (needs {', '.join(keys)})") from None
    return ([str(t) for t in cols[keys[0]]], np.asarray(cols[keys[1]], dtype=float).tolist(),
            np.asarray(cols[keys[2]], dtype=float).tolist())
