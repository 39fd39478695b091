"""Results of solves and checks, with pandas DataFrames and matplotlib plots.

    res = thrustsched.solve(scn)
    res.status, res.objective, res.check.operational_ok
    res.schedule      # DataFrame: schedule.csv's columns
    res.trajectory    # DataFrame: trajectory.csv's columns
    res.plot()        # {"window": Figure, "timeline": Figure, "outputs": Figure}
"""
from __future__ import annotations

import io
import json
import math
from typing import Any, Dict, Optional

import numpy as np

from . import _core


class Report(dict):
    """A dict (summary.json's "check" object) whose keys are also attributes:
    ``report.operational_ok == report["operational_ok"]``."""

    def __getattr__(self, name: str) -> Any:
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(self.keys()) + list(super().__dir__())


def _nan(v: Any) -> float:
    return float("nan") if v is None else float(v)


def _read_csv(text: str, utc_columns=()):
    import pandas as pd

    if not text:
        return pd.DataFrame()
    df = pd.read_csv(io.StringIO(text))
    for c in utc_columns:
        if c in df.columns:
            df[c] = pd.to_datetime(df[c], utc=True)
    return df


class _ScheduleView:
    """Shared by SolveResult and CheckResult: DataFrames and plots of a checked schedule."""

    _checked: "_core.CheckedSchedule"
    _info: Optional[Any]  # ParsedScenario, or None for array problems
    _problem: Optional[Any]  # ArrayProblem for array problems

    def _init_view(self):
        self._schedule_df = None
        self._trajectory_df = None

    @property
    def schedule(self):
        """pandas.DataFrame with schedule.csv's columns: thruster, start_s, end_s,
        duration_s (+ start_utc, end_utc as UTC timestamps, dir_r, dir_t, dir_n,
        delta_v_m_s for GEO models); impulses.csv's columns (thruster, node,
        time_s, delta_v_m_s) for impulsive scenarios."""
        if self._schedule_df is None:
            self._schedule_df = _read_csv(self._checked.schedule_csv(), ("start_utc", "end_utc"))
        return self._schedule_df

    @property
    def trajectory(self):
        """pandas.DataFrame with trajectory.csv's columns (the checker's
        re-propagation at every sample; GEO: with the nonlinear replay).
        Empty if the schedule was not checked."""
        if self._trajectory_df is None:
            self._trajectory_df = _read_csv(self._checked.trajectory_csv(), ("utc",))
        return self._trajectory_df

    def _window_spec(self):
        """(column names of the two windowed outputs in the trajectory, half widths, unit)."""
        if self._info is not None:
            info = self._info
            if info.model_type == "geo":
                return ["lin_dlon_deg", "lin_lat_deg"], list(info.window_half_widths)[::-1], "deg"
            return list(info.window_outputs), list(info.window_half_widths), info.window_unit
        p = self._problem
        return ["out_" + o for o in p.window_outputs], list(p.window_half_widths), ""

    def _thruster_names(self):
        if self._info is not None:
            return list(self._info.thruster_names)
        return list(self._problem.thruster_names)

    def plot(self) -> Dict[str, Any]:
        """matplotlib figures: "window" (the trajectory in the window), "timeline"
        (firings per thruster) and "outputs" (windowed outputs against time, with
        the window). Returns {name: Figure}; close them with plt.close(fig)."""
        from . import _plot

        cols, half, unit = self._window_spec()
        return _plot.plot_all(self.trajectory, self.schedule, self._thruster_names(), cols, half, unit,
                              getattr(self._info, "name", "problem"))


class SolveResult(_ScheduleView):
    """What :func:`thrustsched.solve` returns.

    Attributes: ``status`` ("optimal", "feasible", "infeasible", "unbounded",
    "no_solution", "error": infeasible and no-solution are statuses, not
    exceptions), ``objective``, ``best_bound``, ``gap`` (NaN when unknown),
    ``check`` (the checker's verdict, a :class:`Report`, None when there is no
    schedule), ``schedule`` and ``trajectory`` (DataFrames), ``summary``
    (summary.json's content), ``interrupted`` (Ctrl-C stopped the solve: the
    best schedule found is kept, status "feasible"), ``min_time`` (scenarios
    with ``"objective": "min_time"``: summary.json's "min_time" object, with
    ``arrival_time_s`` and ``arrival_bound_s``; None otherwise).
    """

    def __init__(self, outcome: "_core.SolveOutcome", info=None, problem=None):
        self._outcome = outcome
        self._checked = outcome.checked
        self._info = info
        self._problem = problem
        self.summary: Dict[str, Any] = json.loads(outcome.summary_json)
        self._init_view()

    status = property(lambda self: self._outcome.status)
    objective = property(lambda self: float(self._outcome.objective))
    best_bound = property(lambda self: float(self._outcome.best_bound))
    gap = property(lambda self: float(self._outcome.gap))
    nodes = property(lambda self: int(self._outcome.nodes))
    detail = property(lambda self: self._outcome.detail)
    interrupted = property(lambda self: bool(self._outcome.interrupted))
    has_schedule = property(lambda self: bool(self._outcome.has_schedule))
    solve_seconds = property(lambda self: float(self._outcome.solve_seconds))
    total_seconds = property(lambda self: float(self._outcome.total_seconds))

    @property
    def check(self) -> Optional[Report]:
        c = self.summary.get("check")
        return Report(c) if isinstance(c, dict) else None

    @property
    def min_time(self) -> Optional[Dict[str, Any]]:
        m = self.summary.get("min_time")
        return m if isinstance(m, dict) else None

    @property
    def consumption_l1_m_s(self) -> float:
        return _nan(self.summary.get("consumption_l1_m_s"))

    @property
    def delta_v_m_s(self) -> float:
        return _nan(self.summary.get("delta_v_m_s"))

    @property
    def propellant_kg(self) -> float:
        return _nan(self.summary.get("propellant_kg"))

    @property
    def states(self) -> np.ndarray:
        """States of the discrete model at the grid nodes, [N + 1, n] (empty without a schedule)."""
        return self._outcome.states

    @property
    def outputs(self) -> np.ndarray:
        """Model outputs at the grid nodes, [N + 1, p]."""
        return self._outcome.outputs

    @property
    def pattern(self) -> np.ndarray:
        """On-off pattern, thrusters x intervals (0/1)."""
        return self._outcome.pattern

    @property
    def x(self) -> np.ndarray:
        """The MILP's column values (empty without a solution)."""
        return self._outcome.x

    def __repr__(self) -> str:
        s = f"SolveResult(status={self.status!r}"
        if self.has_schedule:
            n = self.summary.get("n_impulses", self.summary.get("n_burns"))
            what = "impulses" if "n_impulses" in self.summary else "burns"
            s += f", objective={self.objective:.8g}, gap={self.gap:.3g}, {what}={n}"
            if self.check is not None:
                s += f", check_passed={self.check.get('passed')}"
        return s + ")"


class CheckResult(_ScheduleView):
    """What :func:`thrustsched.check` returns: ``passed``, ``operational_ok``,
    ``findings``, ``report`` (summary.json's "check" object), ``schedule`` and
    ``trajectory`` DataFrames, ``plot()``."""

    def __init__(self, checked: "_core.CheckedSchedule", info=None, problem=None):
        self._checked = checked
        self._info = info
        self._problem = problem
        self.report = Report(json.loads(checked.check_json()))
        self._init_view()

    passed = property(lambda self: bool(self.report["passed"]))
    operational_ok = property(lambda self: bool(self.report["operational_ok"]))
    findings = property(lambda self: list(self.report["findings"]))

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self.report[name]
        except KeyError:
            raise AttributeError(name) from None

    def __bool__(self) -> bool:
        return self.passed

    def __repr__(self) -> str:
        return f"CheckResult(passed={self.passed}, operational_ok={self.operational_ok}, findings={len(self.findings)})"


