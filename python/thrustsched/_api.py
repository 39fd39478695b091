"""solve, check, export and build, for scenarios and array problems.

    res = solve(Scenario.load("data/scenarios/hcw_table41_1d.json"), time_limit_s=60)
    check(scn, res.schedule).passed
    export(scn, "day.mps")
    b = build(scn); b.add_constraint(b.on("+T", 5) == 0); b.solve()
"""
from __future__ import annotations

import os
from typing import Any, Dict, Optional

from . import _core
from ._arguments import ProgressArg, progress_callback, schedule_columns
from ._problem import BuiltSchedule, ScheduleProblem
from ._results import CheckResult, SolveResult
from ._scenario import PathLike, as_scenario


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
    values): time_limit_s (wall clock, the solve and the infeasibility
    diagnosis together: data/scenarios/README.md, section 1.1), relative_gap,
    threads (CBC threads),
    max_nodes (a node budget: the same result on every run with threads=1),
    search (the problem-aware search; False hands the whole MILP to CBC),
    diagnosis_time_limit_s, log_level, random_seed; scheme, formulation,
    encoding (the transcription). check=False skips the independent checker.
    progress: None (silent), True (plain lines on stderr after 3 s), or a
    callable receiving dicts (phase, wall_seconds, objective, best_bound, gap,
    nodes, new_incumbent; stage: the search's phase, empty outside it, and
    stage_begins: True on the one report announcing it), called in this
    thread with the GIL.

    The GIL is released while the C++ code runs (other Python threads run,
    and several solves may run at once in threads: each has its own model,
    solver and CBC child process). Ctrl-C (in the main thread) stops the
    solve within about a second and returns the best schedule found (status
    "feasible", ``interrupted`` True); a second Ctrl-C raises
    KeyboardInterrupt. Infeasible and no-solution are statuses, not
    exceptions. A bad scenario raises ScenarioError (a ValueError) with the
    CLI's message.
    """
    if isinstance(problem, (BuiltSchedule, ScheduleProblem)):
        if isinstance(problem, BuiltSchedule) and (scheme or formulation or encoding):
            raise ValueError("scheme, formulation, encoding: the schedule is already built")
        extra = {} if isinstance(problem, BuiltSchedule) else dict(scheme=scheme, formulation=formulation,
                                                                    encoding=encoding)
        return problem.solve(time_limit_s=time_limit_s, relative_gap=relative_gap, threads=threads,
                             max_nodes=max_nodes, search=search, diagnosis_time_limit_s=diagnosis_time_limit_s,
                             log_level=log_level, random_seed=random_seed, check=check, progress=progress,
                             progress_interval_s=progress_interval_s, **extra)
    settings = dict(time_limit_s=time_limit_s, relative_gap=relative_gap, threads=threads, max_nodes=max_nodes,
                    search=search, log_level=log_level, random_seed=random_seed, check=check,
                    progress_interval_s=progress_interval_s, callback=progress_callback(progress))
    scn = as_scenario(problem)
    parsed = scn.parsed()
    out = _core.solve_scenario(parsed, diagnosis_time_limit_s=diagnosis_time_limit_s, scheme=scheme,
                               formulation=formulation, encoding=encoding, **settings)
    return SolveResult(out, parsed)


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
    if isinstance(problem, ScheduleProblem):
        return problem.check(schedule)
    scn = as_scenario(problem)
    parsed = scn.parsed()
    if isinstance(schedule, (str, os.PathLike)):
        path = os.fspath(schedule)
        if parsed.impulsive:
            names, a, b = _core.read_impulses_csv(parsed, path)
        else:
            names, a, b = _core.read_schedule_csv(parsed, path)
    else:
        names, a, b = schedule_columns(schedule, parsed.impulsive)
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
    if isinstance(problem, ScheduleProblem):
        return problem.build(scheme=scheme, formulation=formulation, encoding=encoding)
    scn = as_scenario(problem)
    parsed = scn.parsed()
    return BuiltSchedule(_core.build_scenario(parsed, scheme, formulation, encoding), parsed, None)
