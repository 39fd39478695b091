"""A campaign's tasks: the base scenario with one combination of the swept
values each, checked by the scenario parser, with an id that identifies the
result (thrustsched.sweep).

    tasks = expand(load_spec("data/campaigns/hcw_quick.json"))
    tasks[0].index, tasks[0].id, tasks[0].params, tasks[0].scenario
    tasks[0].command("out/c/scenarios/ID.json", "out/c/tasks/ID")   # the `thrustsched ...` line

Order: the grid's product (first field slowest), then the zipped lists, then
the Monte Carlo samples. Sample k of a seed draws from its own generator
(numpy's PCG64 seeded with [seed, k]), so a sample does not depend on the
others or on the order tasks run in.
"""
from __future__ import annotations

import copy
import hashlib
import itertools
import json
from dataclasses import dataclass
from typing import Any, Dict, List

from ._campaign_spec import CampaignError, CampaignSpec, set_field


@dataclass
class Task:
    index: int  # 0-based position in the campaign
    id: str  # hash of the resolved scenario, the job and the program version
    params: Dict[str, Any]  # swept field path -> value
    scenario: dict  # the resolved scenario (job solver settings applied)
    kind: str
    cycles: Any = None
    plots: bool = False

    def command(self, scenario_file: str, out_dir: str, program: str = "thrustsched",
                resume: bool = False) -> List[str]:
        """The command line that runs this task (its scenario saved as
        scenario_file) into out_dir."""
        cmd = [program, self.kind, scenario_file, "--out", out_dir, "--quiet"]
        if not self.plots:
            cmd.append("--no-plots")
        if self.kind == "solve":
            cmd += ["--no-report", "--force"]
        else:
            if self.cycles is not None:
                cmd += ["--cycles", str(self.cycles)]
            cmd.append("--resume" if resume else "--force")
        return cmd


def task_id(scenario: dict, kind: str, cycles: Any, plots: bool, version: str) -> str:
    """16 hex digits of SHA-256 over the canonical JSON of what decides the result."""
    what = {"scenario": scenario, "kind": kind, "cycles": cycles, "plots": plots, "version": version}
    text = json.dumps(what, sort_keys=True, separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def _combinations(spec: CampaignSpec) -> List[Dict[str, Any]]:
    grids = [[(path, v) for v in values] for path, values in spec.grid]
    grid_part = [dict(c) for c in itertools.product(*grids)] if grids else [{}]
    if spec.zipped:
        n = len(spec.zipped[0][1])
        zip_part = [{path: values[k] for path, values in spec.zipped} for k in range(n)]
    else:
        zip_part = [{}]
    mc_part = _samples(spec) if spec.monte_carlo else [{}]
    return [{**g, **z, **m} for g in grid_part for z in zip_part for m in mc_part]


def _samples(spec: CampaignSpec) -> List[Dict[str, Any]]:
    import numpy as np

    mc = spec.monte_carlo
    out = []
    for k in range(mc.samples):
        rng = np.random.Generator(np.random.PCG64([mc.seed, k]))
        draw: Dict[str, Any] = {}
        for path, kind, args in mc.fields:
            if kind == "normal":
                draw[path] = float(rng.normal(args[0], args[1]))
            elif kind == "uniform":
                draw[path] = float(rng.uniform(args[0], args[1]))
            else:
                draw[path] = copy.deepcopy(args[int(rng.integers(len(args)))])
        out.append(draw)
    return out


def expand(spec: CampaignSpec, version: str = None, validate: bool = True) -> List[Task]:
    """The tasks, each scenario checked by the C++ parser (validate=True):
    a CampaignError names the task, its swept values and the parser's message."""
    if version is None:
        from . import _core

        version = _core.__version__
    tasks = []
    for index, params in enumerate(_combinations(spec)):
        scenario = copy.deepcopy(spec.base)
        for path, value in params.items():
            set_field(scenario, path, copy.deepcopy(value))
        _apply_solver(scenario, spec)
        if validate:
            _validate(scenario, spec, index, params)
        tasks.append(Task(index=index, id=task_id(scenario, spec.kind, spec.cycles, spec.plots, version),
                          params=params, scenario=scenario, kind=spec.kind, cycles=spec.cycles,
                          plots=spec.plots))
    return tasks


def _apply_solver(scenario: dict, spec: CampaignSpec) -> None:
    if spec.kind != "solve":
        return
    from ._campaign_spec import DEFAULT_SOLVER

    solver = scenario.setdefault("solver", {})
    if not isinstance(solver, dict):
        return  # the parser names it
    if "time_limit_s" not in spec.solver:
        solver.pop("time_limit_s", None)  # a wall-clock limit would make results load-dependent
    solver.update({**DEFAULT_SOLVER, **spec.solver})


def _validate(scenario: dict, spec: CampaignSpec, index: int, params: Dict[str, Any]) -> None:
    from . import _core
    from ._scenario import Scenario

    text = json.dumps(scenario)
    try:
        if spec.kind == "simulate":
            _core.parse_simulation(text, f"task {index}")
        else:
            Scenario.from_dict(scenario, validate=True)
    except ValueError as e:
        swept = ", ".join(f"{p} = {json.dumps(v)}" for p, v in params.items()) or "the base scenario"
        raise CampaignError(f"task {index} ({swept}): {e}") from None
