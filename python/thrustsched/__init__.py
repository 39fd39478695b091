"""thrustsched: minimum-fuel firing schedules for spacecraft with on-off thrusters (MILP, CBC).

    import thrustsched as ts
    scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_2d.json"))  # a shipped scenario
    res = ts.solve(scn, time_limit_s=60, threads=2)     # GIL released while CBC runs
    res.status, res.objective, res.gap, res.check.operational_ok
    res.schedule, res.trajectory                          # pandas DataFrames
    res.plot()                                            # matplotlib figures
    ts.check(scn, res.schedule).passed                    # the independent checker
    ts.export(scn, "two_days.mps")                        # MPS / LP for other solvers

Also: ts.ScheduleProblem (your own Phi, Gamma, drift as numpy arrays),
ts.dynamics (the shipped models and their discretisation), ts.milp (build,
solve and write MILPs; extend a schedule MILP from ts.build), ts.simulate
(the year loop), ts.transfer (orbit raising: minimum time, Lyapunov
feedback, two impulses; data/scenarios/transfer/README.md), ts.fleet (several
spacecraft in one MILP: a file with a "fleet" section), ts.sweep (campaigns: sweeps and Monte Carlo runs on
Dask; data/campaigns/README.md), ts.data_path (the shipped scenarios and
campaigns, found from the package, whatever the working directory). Every
object is the C++ library's (thrustsched._core); the CLI's documentation
(data/scenarios/README.md) describes the scenario fields and the output
columns.
"""
from . import _core
from . import dynamics, milp, sweep
from ._api import build, check, export, solve
from ._data import data_path
from ._fleet import FleetResult, fleet
from ._problem import BuiltSchedule, ScheduleProblem
from ._results import CheckResult, Report, SolveResult
from ._scenario import Scenario, ScenarioError
from ._simulate import SimulationResult, simulate
from ._transfer import TransferResult, transfer

ThrusterSet = _core.dynamics.ThrusterSet
__version__ = _core.__version__
solver_version = _core.solver_version

__all__ = [
    "Scenario", "ScenarioError", "solve", "check", "export", "build", "simulate", "transfer", "fleet",
    "FleetResult",
    "SolveResult", "CheckResult", "Report", "SimulationResult", "TransferResult", "ScheduleProblem",
    "BuiltSchedule",
    "ThrusterSet", "dynamics", "milp", "sweep", "data_path", "solver_version", "__version__",
]
