"""Bring your own dynamics (ScheduleProblem from numpy arrays) and schedule
MILPs you extend (BuiltSchedule).

    d = thrustsched.dynamics.Hcw(7.2921159e-5).discretise(grid_s, thrusters)
    p = ScheduleProblem(d["phi"], d["gamma"], drift=d["drift"], grid_s=d["grid_s"],
                        initial_state=x0, output_matrix=C, thrusters=thrusters,
                        window={"outputs": [1, 2], "half_widths": [36800, 36800]},
                        rules={"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300})
    res = thrustsched.solve(p)
"""
from __future__ import annotations

import json
import os
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core, milp
from ._arguments import ProgressArg, progress_callback, schedule_columns
from ._results import CheckResult, SolveResult

ThrusterSet = _core.dynamics.ThrusterSet


class ScheduleProblem:
    """A minimum-fuel on-off scheduling problem from numpy arrays:

        x_{j+1} = Phi[j] x_j + Gamma[j] u_j + drift[j],   u_j in {0, 1}^m,   y_j = C x_j

    on the grid t_0 < ... < t_N (``grid_s``, N + 1 times in s), transcribed by
    the same MILP builder, rule encodings and solver as the shipped models.

    phi [N, n, n], gamma [N, n, m] (column i: what thruster i does when on for
    the whole interval), drift [N, n] (default zeros), output_matrix [p, n]
    (or [N + 1, p, n], one per node), initial_state [n].
    thrusters: a ThrusterSet (its order is Gamma's column order; it gives the
    names and the cost: L1 = (F/m) ||d_i||_1 per second on, as the thesis
    metric), or a list of names with thrust_n, mass_kg, isp_s and optional
    directions_rtn ([m, 3]; default +R for all, i.e. a cost of F/m per
    second on).
    window: {"outputs": [indices or output names], "half_widths": [...],
    "enforce_from_s", "soft", "soft_penalty", "margin"}: |y_k| <= half width
    at the grid nodes j >= 1.
    rules: the scenario file's "operations" fields (max_simultaneous,
    min_burn_s, max_burn_s, min_off_same_s, min_gap_other_s,
    max_burns_per_thruster, allow_burn_across_end), checked with the same
    messages.
    terminal: None, {"kind": "fixed", "target": [...]} or {"kind": "box",
    "target": [...], "tolerance": [...]}.
    state_scale: characteristic magnitudes of the states (default ones):
    the MILP's state columns and rows are scaled by them, as the shipped
    models' scales do (pass the same scale to get the same MILP).

    What the arrays cannot give (there is no continuous-time model behind
    them): impulsive mode, window points between nodes, station-keeping
    terminal sets; the checker judges the rules in continuous time and the
    window at the grid nodes through the arrays.
    """

    def __init__(self, phi, gamma, *, grid_s, initial_state, output_matrix, thrusters,
                 drift=None, window: Optional[Mapping[str, Any]] = None,
                 rules: Optional[Mapping[str, Any]] = None, objective: str = "l1",
                 burn_start_penalty: float = 0.0, terminal: Optional[Mapping[str, Any]] = None,
                 state_scale=None, state_names: Optional[Sequence[str]] = None,
                 output_names: Optional[Sequence[str]] = None, forced_off: Sequence = (),
                 thrust_n: Optional[float] = None, mass_kg: Optional[float] = None,
                 isp_s: Optional[float] = None, directions_rtn=None):
        if not isinstance(thrusters, ThrusterSet):
            names = [str(n) for n in thrusters]
            if thrust_n is None or mass_kg is None or isp_s is None:
                raise ValueError("thrusters: with a list of names, give thrust_n, mass_kg and isp_s "
                                 "(or pass a ThrusterSet)")
            d = np.zeros((len(names), 3)) if directions_rtn is None else np.asarray(directions_rtn, float)
            if directions_rtn is None:
                d[:, 0] = 1.0
            thrusters = ThrusterSet(names, d, thrust_n, mass_kg, isp_s)
        window = dict(window or {})
        unknown = set(window) - {"outputs", "half_widths", "enforce_from_s", "soft", "soft_penalty", "margin"}
        if unknown:
            raise ValueError(f"window.{sorted(unknown)[0]}: unknown field (accepted: outputs, half_widths, "
                             "enforce_from_s, soft, soft_penalty, margin)")
        out_names = list(output_names) if output_names is not None else None
        outputs = []
        for o in window.get("outputs", []):
            if isinstance(o, str):
                if out_names is None or o not in out_names:
                    raise ValueError(f"window.outputs: {o!r} is not an output name ({out_names})")
                outputs.append(out_names.index(o))
            else:
                outputs.append(int(o))
        terminal = dict(terminal or {"kind": "free"})
        forced = [(str(n), float(a), float(b)) for (n, a, b) in forced_off]
        self._core = _core.ArrayProblem(
            np.asarray(phi, float), np.asarray(gamma, float), np.asarray(grid_s, float).tolist(),
            np.asarray(initial_state, float), np.asarray(output_matrix, float), thrusters,
            drift=None if drift is None else np.asarray(drift, float),
            window_outputs=outputs, window_half_widths=[float(w) for w in window.get("half_widths", [])],
            window_enforce_from_s=window.get("enforce_from_s"), window_soft=bool(window.get("soft", False)),
            window_soft_penalty=float(window.get("soft_penalty", 1e3)), window_margin=float(window.get("margin", 0.0)),
            rules_json=json.dumps(dict(rules or {})), objective=objective, burn_start_penalty=burn_start_penalty,
            terminal=str(terminal.get("kind", "free")),
            terminal_target=None if terminal.get("target") is None else np.asarray(terminal["target"], float),
            terminal_tolerance=None if terminal.get("tolerance") is None else np.asarray(terminal["tolerance"], float),
            state_scale=None if state_scale is None else np.asarray(state_scale, float),
            state_names=None if state_names is None else list(state_names),
            output_names=out_names, forced_off=forced)
        self.thrusters = thrusters

    @classmethod
    def from_discretisation(cls, discretisation: Mapping[str, Any], **kwargs) -> "ScheduleProblem":
        """From the dict of ``model.discretise(...)`` (phi, gamma, drift, grid_s)."""
        d = discretisation
        return cls(d["phi"], d["gamma"], drift=d.get("drift"), grid_s=d["grid_s"], **kwargs)

    num_intervals = property(lambda self: self._core.num_intervals)
    num_states = property(lambda self: self._core.num_states)
    grid_s = property(lambda self: self._core.grid_s)
    thruster_names = property(lambda self: list(self._core.thruster_names))
    state_names = property(lambda self: list(self._core.state_names))
    output_names = property(lambda self: list(self._core.output_names))

    def solve(self, *, time_limit_s=None, relative_gap=None, threads=None, max_nodes=None, search=None,
              log_level=None, random_seed=None, formulation=None, encoding=None, check=True,
              progress: ProgressArg = None, progress_interval_s=1.0, scheme=None,
              diagnosis_time_limit_s=None) -> SolveResult:
        """Builds, solves and checks (the keywords of thrustsched.solve)."""
        if scheme:
            raise ValueError("scheme: an array problem is already discretised")
        if diagnosis_time_limit_s is not None:
            raise ValueError("diagnosis_time_limit_s: not used by array problems")
        out = self._core.solve(formulation=formulation, encoding=encoding, time_limit_s=time_limit_s,
                               relative_gap=relative_gap, threads=threads, max_nodes=max_nodes, search=search,
                               log_level=log_level, random_seed=random_seed, check=check,
                               progress_interval_s=progress_interval_s, callback=progress_callback(progress))
        return SolveResult(out, None, self._core)

    def check(self, schedule) -> CheckResult:
        """The checker on a schedule (as thrustsched.check): the rules in
        continuous time, the window at the grid nodes through the arrays.
        schedule: a DataFrame (thruster, start_s, end_s), a list of dicts, a
        SolveResult or a schedule.csv path."""
        if isinstance(schedule, (str, os.PathLike)):
            import pandas as pd

            schedule = pd.read_csv(os.fspath(schedule))
        names, a, b = schedule_columns(schedule, False)
        return CheckResult(self._core.check(names, a, b), None, self._core)

    def build(self, *, scheme=None, formulation=None, encoding=None) -> "BuiltSchedule":
        """The schedule MILP, to extend and solve (as thrustsched.build)."""
        if scheme:
            raise ValueError("scheme: an array problem is already discretised")
        return BuiltSchedule(self._core.build(formulation, encoding), None, self._core)

    def __repr__(self) -> str:
        return (f"ScheduleProblem({self.num_intervals} intervals, {self.num_states} states, "
                f"thrusters {self.thruster_names})")


class BuiltSchedule:
    """A schedule MILP (from :func:`thrustsched.build`), to extend and solve again.

        b = thrustsched.build(scn)
        b.add_constraint(b.on("+T", 10) == 0)                  # a forbidden slot
        v = b.add_variable(0, 1e4, "continuous", "slack")
        b.add_constraint(b.output_expr(100, 1) - v <= 30000)  # a keep-out row on y at node 100
        b.add_objective_term(v, 1e-3)
        res = b.solve(time_limit_s=60)

    Handles: ``on(thruster, interval)`` (binary, thruster by name or index),
    ``state(node, c)`` (scaled column, x = S x~), ``state_expr(node, c)`` and
    ``output_expr(node, k)`` (linear expressions in the model's units; sparse
    formulation), ``interval_at(t_s)``. Expressions are built with
    :mod:`thrustsched.milp` (``+``, ``*``, ``<=``, ``==``, ``milp.quicksum``).
    Every edit refreezes the MILP (add many rows with ``add_constraints``).
    Once modified, ``solve`` hands the whole MILP to CBC (the problem-aware
    search rebuilds restricted MILPs from the problem and would not see your
    rows; pass search=True to use it anyway). The result's check is the
    problem's (your rows are not part of it). Not thread-safe: do not edit
    it while one of its solves runs.
    """

    def __init__(self, core, info, problem):
        self._core = core
        self._info = info
        self._problem = problem

    # -- handles ---------------------------------------------------------------
    def on(self, thruster: Union[str, int], interval: int) -> "milp.Variable":
        """The binary "thruster on in interval j" (thruster by name or index)."""
        return self._core.on(thruster, interval)

    @property
    def on_columns(self) -> np.ndarray:
        """Column indices of the on-off binaries, thrusters x intervals."""
        return self._core.on_columns

    def state(self, node: int, component: int) -> "milp.Variable":
        """The scaled column of a state component at a node (x = S x~; sparse formulation)."""
        return self._core.state(node, component)

    def state_expr(self, node: int, component: int) -> "milp.LinearExpr":
        """A state component at a node in the model's units (sparse formulation)."""
        return self._core.state_expr(node, component)

    def output_expr(self, node: int, output: int) -> "milp.LinearExpr":
        """Model output k (y = C x) at a node in its units (sparse formulation)."""
        return self._core.output_expr(node, output)

    def interval_at(self, t_s: float) -> int:
        """Index of the grid interval holding t (s)."""
        return self._core.interval_at(t_s)

    # -- edits (each refreezes the MILP) -------------------------------------------
    def add_variable(self, lower: float = 0.0, upper: float = float("inf"), type: str = "continuous",
                     name: str = "") -> "milp.Variable":
        return self._core.add_variable(lower, upper, type, name)

    def add_constraint(self, constraint: "milp.BoundedLinearExpr", name: str = "") -> int:
        """Adds a row (made with <=, >=, ==); returns its index."""
        return self._core.add_constraint(constraint, name)

    def add_constraints(self, constraints: Sequence["milp.BoundedLinearExpr"], prefix: str = "") -> None:
        """Adds rows named prefix[k], refreezing once."""
        self._core.add_constraints(list(constraints), prefix)

    def set_bounds(self, variable: "milp.Variable", lower: float, upper: float) -> None:
        self._core.set_bounds(variable, lower, upper)

    def add_objective_term(self, variable: "milp.Variable", coefficient: float) -> None:
        """Adds coefficient * variable to the objective (minimised, in its units: m/s or kg)."""
        self._core.add_objective_term(variable, coefficient)

    # -- facts ------------------------------------------------------------------------
    modified = property(lambda self: bool(self._core.modified))
    lp = property(lambda self: self._core.lp, doc="A copy of the frozen MILP (milp.LpData).")
    num_rows = property(lambda self: self._core.num_rows)
    num_columns = property(lambda self: self._core.num_columns)
    num_binaries = property(lambda self: self._core.num_binaries)
    num_nonzeros = property(lambda self: self._core.num_nonzeros)
    objective_step = property(lambda self: self._core.objective_step)
    formulation = property(lambda self: self._core.formulation)
    state_scale = property(lambda self: self._core.state_scale)
    grid_s = property(lambda self: self._core.grid_s)
    thruster_names = property(lambda self: list(self._core.thruster_names))

    def variable_name(self, variable: "milp.Variable") -> str:
        return self._core.variable_name(variable)

    def solve(self, *, time_limit_s=None, relative_gap=None, threads=None, max_nodes=None, search=None,
              diagnosis_time_limit_s=None, log_level=None, random_seed=None, check=True, progress=None,
              progress_interval_s=1.0, callback=None) -> SolveResult:
        """Solves (see thrustsched.solve for the keywords)."""
        cb = callback if callback is not None else progress_callback(progress)
        out = self._core.solve(time_limit_s, relative_gap, threads, max_nodes, search, diagnosis_time_limit_s,
                               log_level, random_seed, check, progress_interval_s, cb)
        return SolveResult(out, self._info, self._problem)

    def write(self, path, obfuscate_names: bool = False) -> None:
        """Writes MPS (.mps) or LP (.lp), with your rows."""
        self._core.write(os.fspath(path), obfuscate_names)

    def __repr__(self) -> str:
        return (f"BuiltSchedule({self._core.num_binaries} binaries, {self._core.num_columns} columns, "
                f"{self._core.num_rows} rows, {self._core.formulation}, modified={self._core.modified})")
