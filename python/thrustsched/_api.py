"""solve, check, export and build, for scenarios and array problems.

    res = solve(Scenario.load("data/scenarios/hcw_table41_1d.json"), time_limit_s=60)
    check(scn, res.schedule).passed
    export(scn, "day.mps")
    b = build(scn); b.add_constraint(b.on("+T", 5) == 0); b.solve()
"""
from __future__ import annotations

import os
import sys
from typing import Any, Callable, Dict, Optional, Sequence, Union

import numpy as np

from . import _core
from ._results import CheckResult, SolveResult
from ._scenario import PathLike, Scenario, as_scenario

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
        if phase == "root_lp":
            print(f"  [{t:.2f} s] root LP relaxation: {d.get('lp_iterations')} iterations", file=sys.stderr,
                  flush=True)
            return
        gap = d.get("gap")
        gap_s = "n/a" if gap is None or gap != gap else f"{100 * gap:.3g}%"
        print(f"  [{t:.2f} s] {phase}: incumbent {d.get('objective'):.6g}, bound {d.get('best_bound'):.6g}, "
              f"gap {gap_s}, {d.get('nodes')} nodes{' (new incumbent)' if d.get('new_incumbent') else ''}",
              file=sys.stderr, flush=True)

    return show


def _callback(progress: ProgressArg):
    if progress is None or progress is False:
        return None
    if progress is True:
        return _progress_printer()
    if callable(progress):
        return progress
    raise TypeError("progress: expected None, True or a callable taking a dict")


def solve(problem: Any, *, time_limit_s: Optional[float] = None, relative_gap: Optional[float] = None,
          threads: Optional[int] = None, max_nodes: Optional[int] = None, search: Optional[bool] = None,
          diagnosis_time_limit_s: Optional[float] = None, log_level: Optional[int] = None,
          random_seed: Optional[int] = None, scheme: Optional[str] = None, formulation: Optional[str] = None,
          encoding: Optional[str] = None, check: bool = True, progress: ProgressArg = None,
          progress_interval_s: float = 1.0) -> SolveResult:
    """Builds, solves and checks a schedule, as ``thrustsched solve`` does.

    problem: a Scenario (or a dict, or a scenario file path), a
    ScheduleProblem (numpy arrays), or a BuiltSchedule (from :func:`build`,
    possibly with your own rows).

    Keywords override the scenario's ``solver`` section (unset: the file's
    values): time_limit_s (wall clock), relative_gap, threads (CBC threads),
    max_nodes (a node budget: the same result on every run with threads=1),
    search (the problem-aware search; False hands the whole MILP to CBC),
    diagnosis_time_limit_s, log_level, random_seed; scheme, formulation,
    encoding (the transcription). check=False skips the independent checker.
    progress: None (silent), True (plain lines on stderr after 3 s), or a
    callable receiving dicts (phase, wall_seconds, objective, best_bound, gap,
    nodes, new_incumbent), called in this thread with the GIL.

    The GIL is released while the C++ code runs (other Python threads run,
    and several solves may run at once in threads: each has its own model,
    solver and CBC child process). Ctrl-C (in the main thread) stops the
    solve within about a second and returns the best schedule found (status
    "feasible", ``interrupted`` True); a second Ctrl-C raises
    KeyboardInterrupt. Infeasible and no-solution are statuses, not
    exceptions. A bad scenario raises ScenarioError (a ValueError) with the
    CLI's message.
    """
    from ._problem import BuiltSchedule, ScheduleProblem

    settings = dict(time_limit_s=time_limit_s, relative_gap=relative_gap, threads=threads, max_nodes=max_nodes,
                    search=search, log_level=log_level, random_seed=random_seed, check=check,
                    progress_interval_s=progress_interval_s, callback=_callback(progress))
    if isinstance(problem, BuiltSchedule):
        if scheme or formulation or encoding:
            raise ValueError("scheme, formulation, encoding: the schedule is already built")
        return problem.solve(diagnosis_time_limit_s=diagnosis_time_limit_s, **settings)
    if isinstance(problem, ScheduleProblem):
        if scheme:
            raise ValueError("scheme: an array problem is already discretised")
        if diagnosis_time_limit_s is not None:
            raise ValueError("diagnosis_time_limit_s: not used by array problems")
        out = problem._core.solve(formulation=formulation, encoding=encoding, **settings)
        return SolveResult(out, None, problem._core)
    scn = as_scenario(problem)
    parsed = scn.parsed()
    out = _core.solve_scenario(parsed, diagnosis_time_limit_s=diagnosis_time_limit_s, scheme=scheme,
                               formulation=formulation, encoding=encoding, **settings)
    return SolveResult(out, parsed)


def _schedule_columns(schedule: Any, impulsive: bool):
    """(thrusters, a, b) from a DataFrame, a SolveResult, a list of dicts or a dict of columns."""
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


def check(problem: Any, schedule: Any) -> CheckResult:
    """The independent checker on any schedule, as ``thrustsched check``.

    problem: a Scenario (dict, file path) or a ScheduleProblem. schedule: a
    DataFrame with columns thruster, start_s, end_s (impulsive scenarios:
    thruster, node, delta_v_m_s), a list of such dicts, a SolveResult, or a
    path to schedule.csv / impulses.csv (read by the CLI's reader).
    For scenarios: operational rules in continuous time, adaptive linear
    re-propagation, the nonlinear replay for GEO; for array problems: the
    rules and the arrays propagated through the on-off pattern.
    """
    from ._problem import ScheduleProblem

    if isinstance(problem, ScheduleProblem):
        if isinstance(schedule, (str, os.PathLike)):
            import pandas as pd

            schedule = pd.read_csv(os.fspath(schedule))
        names, a, b = _schedule_columns(schedule, False)
        return CheckResult(problem._core.check(names, a, b), None, problem._core)
    scn = as_scenario(problem)
    parsed = scn.parsed()
    if isinstance(schedule, (str, os.PathLike)):
        path = os.fspath(schedule)
        if parsed.impulsive:
            names, a, b = _core.read_impulses_csv(parsed, path)
        else:
            names, a, b = _core.read_schedule_csv(parsed, path)
    else:
        names, a, b = _schedule_columns(schedule, parsed.impulsive)
    if parsed.impulsive:
        return CheckResult(_core.check_scenario_impulses(parsed, names, a, b), parsed)
    return CheckResult(_core.check_scenario(parsed, names, a, b), parsed)


def export(problem: Any, path: PathLike, *, obfuscate_names: bool = False, scheme: Optional[str] = None,
           formulation: Optional[str] = None, encoding: Optional[str] = None) -> Dict[str, Any]:
    """Writes the scenario's MILP as free MPS (``.mps``) or CPLEX LP (``.lp``),
    as ``thrustsched export``: binaries named on_<thruster index>_<interval>,
    objective in m/s (kg for "propellant"), minimisation. Returns the model's
    size (n_binaries, n_columns, n_rows, n_nonzeros, ...). A BuiltSchedule
    (with your rows) is written by its own ``write``."""
    from ._problem import BuiltSchedule

    if isinstance(problem, BuiltSchedule):
        problem.write(path, obfuscate_names=obfuscate_names)
        return {"path": os.fspath(path), "n_rows": problem.num_rows, "n_columns": problem.num_columns}
    scn = as_scenario(problem)
    return dict(_core.export_scenario(scn.parsed(), os.fspath(path), obfuscate_names, scheme, formulation,
                                      encoding))


def build(problem: Any, *, scheme: Optional[str] = None, formulation: Optional[str] = None,
          encoding: Optional[str] = None):
    """The schedule MILP of a scenario (or ScheduleProblem), to extend with
    your own variables and rows (see :class:`BuiltSchedule`) and solve."""
    from ._problem import BuiltSchedule, ScheduleProblem

    if isinstance(problem, ScheduleProblem):
        if scheme:
            raise ValueError("scheme: an array problem is already discretised")
        return BuiltSchedule(problem._core.build(formulation, encoding), None, problem._core)
    scn = as_scenario(problem)
    parsed = scn.parsed()
    return BuiltSchedule(_core.build_scenario(parsed, scheme, formulation, encoding), parsed, None)
