"""A campaign file read and checked before anything runs (thrustsched.sweep).

    spec = load_spec("data/campaigns/hcw_quick.json")
    spec.kind, spec.grid, spec.zipped, spec.monte_carlo

A campaign file (JSON; data/campaigns/README.md describes it):

    {"name": "hcw_quick",
     "base": "../scenarios/hcw_table41_1d.json",       # a path (relative to this file) or a scenario object
     "job": {"kind": "solve", "solver": {"max_nodes": 2000}},   # or {"kind": "simulate", "cycles": 2}
     "grid": {"operations.min_burn_s": [300, 600]},              # product of the lists
     "zip": {"initial_state.hcw_position_m": [[1000, 0, 0], [2000, 0, 0], [500, 0, 0]]},  # side by side
     "monte_carlo": {"samples": 4, "seed": 7,
                     "fields": {"initial_state.hcw_velocity_m_s[1]": {"normal": [0, 0.001]}}}}

Every error is a CampaignError (a ValueError) naming the field path and the
value; the command line turns it into exit 2.
"""
from __future__ import annotations

import json
import math
import os
import re
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple, Union

PathLike = Union[str, "os.PathLike[str]"]

KINDS = ("solve", "simulate")
DISTRIBUTIONS = {"normal": 2, "uniform": 2, "choice": None}
# Solves inside a campaign stop on a node budget and the gap, not on the wall
# clock, so that a task's result does not depend on the machine's load.
DEFAULT_SOLVER = {"threads": 1, "max_nodes": 100000}
_TOP_KEYS = {"name", "description", "base", "job", "grid", "zip", "monte_carlo"}
_JOB_KEYS = {"kind", "cycles", "solver", "plots"}
_MC_KEYS = {"samples", "seed", "fields"}
_TOKEN = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


class CampaignError(ValueError):
    """A campaign file that cannot run: the message names the path and value."""


def _fail(path: str, message: str) -> None:
    raise CampaignError(f"{path}: {message}")


def _show(value: Any) -> str:
    return json.dumps(value)[:80]


def parse_field_path(path: str) -> List[Union[str, int]]:
    """"a.b[1].c" -> ["a", "b", 1, "c"] (CampaignError when malformed)."""
    tokens: List[Union[str, int]] = []
    pos = 0
    while pos < len(path):
        if path[pos] == "." and tokens and pos + 1 < len(path):
            pos += 1
        m = _TOKEN.match(path, pos)
        if m is None or m.end() == pos:
            _fail(path, f"not a field path (keys joined by '.', list indices as [i]) at character {pos}")
        tokens.append(m.group(1) if m.group(1) is not None else int(m.group(2)))
        pos = m.end()
    if not tokens or not isinstance(tokens[0], str):
        _fail(path or '""', "not a field path (it must start with a scenario section)")
    return tokens


def set_field(scenario: dict, path: str, value: Any) -> None:
    """Sets scenario[path] (creating the last key of an existing section); a
    missing section or an index out of range is a CampaignError."""
    tokens = parse_field_path(path)
    node: Any = scenario
    for depth, tok in enumerate(tokens[:-1]):
        where = _prefix(tokens, depth + 1)
        if isinstance(tok, int):
            if not isinstance(node, list) or tok >= len(node):
                _fail(path, f"{where}: no such list element in the base scenario")
            node = node[tok]
        else:
            if not isinstance(node, dict) or tok not in node:
                _fail(path, f"{where}: no such section in the base scenario")
            node = node[tok]
    last = tokens[-1]
    if isinstance(last, int):
        if not isinstance(node, list) or last >= len(node):
            _fail(path, "no such list element in the base scenario")
        node[last] = value
    else:
        if not isinstance(node, dict):
            _fail(path, f"{_prefix(tokens, len(tokens) - 1)} is not a section")
        node[last] = value


def _prefix(tokens: List[Union[str, int]], n: int) -> str:
    out = ""
    for t in tokens[:n]:
        out += f"[{t}]" if isinstance(t, int) else (f".{t}" if out else t)
    return out


@dataclass
class MonteCarlo:
    samples: int
    seed: int
    fields: List[Tuple[str, str, Any]]  # (field path, distribution, its arguments)


@dataclass
class CampaignSpec:
    name: str
    base: dict
    base_source: str  # the base scenario's file, or "inline"
    kind: str
    cycles: Optional[int] = None
    solver: Dict[str, Any] = field(default_factory=dict)
    plots: bool = False
    grid: List[Tuple[str, list]] = field(default_factory=list)
    zipped: List[Tuple[str, list]] = field(default_factory=list)
    monte_carlo: Optional[MonteCarlo] = None
    source: str = "campaign"

    @property
    def parameters(self) -> List[str]:
        """The swept field paths, in the order of the columns of results.csv."""
        mc = [f for f, _, _ in self.monte_carlo.fields] if self.monte_carlo else []
        return [p for p, _ in self.grid] + [p for p, _ in self.zipped] + mc

    @property
    def task_count(self) -> int:
        n = 1
        for _, values in self.grid:
            n *= len(values)
        if self.zipped:
            n *= len(self.zipped[0][1])
        if self.monte_carlo:
            n *= self.monte_carlo.samples
        return n


def load_spec(spec: Union[PathLike, dict]) -> CampaignSpec:
    """Reads a campaign file (or an already-parsed dict; relative base paths
    are then relative to the working directory)."""
    if isinstance(spec, dict):
        return parse_spec(spec, source="campaign", directory=os.getcwd())
    path = os.fspath(spec)
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except FileNotFoundError:
        raise CampaignError(f"campaign file {path}: no such file") from None
    except json.JSONDecodeError as e:
        raise CampaignError(f"campaign file {path}: not JSON ({e})") from None
    return parse_spec(data, source=path, directory=os.path.dirname(os.path.abspath(path)))


def parse_spec(data: Any, source: str, directory: str) -> CampaignSpec:
    if not isinstance(data, dict):
        _fail(source, f"a campaign is a JSON object, got {_show(data)}")
    unknown = sorted(set(data) - _TOP_KEYS)
    if unknown:
        _fail(unknown[0], f"unknown campaign field (known: {', '.join(sorted(_TOP_KEYS))})")
    name = data.get("name", os.path.splitext(os.path.basename(source))[0])
    if not isinstance(name, str) or not name:
        _fail("name", f"a non-empty string, got {_show(name)}")
    base, base_source = _read_base(data.get("base"), directory)
    spec = CampaignSpec(name=name, base=base, base_source=base_source, kind="solve", source=source)
    _read_job(data.get("job", {}), spec)
    spec.grid = _read_lists(data.get("grid", {}), "grid")
    spec.zipped = _read_lists(data.get("zip", {}), "zip")
    lengths = {len(v) for _, v in spec.zipped}
    if len(lengths) > 1:
        _fail("zip", f"the zipped lists differ in length ({', '.join(f'{p}: {len(v)}' for p, v in spec.zipped)})")
    if "monte_carlo" in data:
        spec.monte_carlo = _read_monte_carlo(data["monte_carlo"])
    seen: Dict[str, str] = {}
    for group, paths in (("grid", [p for p, _ in spec.grid]), ("zip", [p for p, _ in spec.zipped]),
                         ("monte_carlo.fields", [f for f, _, _ in spec.monte_carlo.fields] if spec.monte_carlo else [])):
        for p in paths:
            if p in seen:
                _fail(f"{group}.{p}", f"the field is swept twice (also in {seen[p]})")
            seen[p] = group
            set_field(json.loads(json.dumps(spec.base)), p, None)  # the path exists in the base
    return spec


def _read_base(base: Any, directory: str) -> Tuple[dict, str]:
    if base is None:
        _fail("base", "missing: a scenario file path (relative to the campaign file) or a scenario object")
    if isinstance(base, dict):
        return _absolute_files(json.loads(json.dumps(base)), directory), "inline"
    if not isinstance(base, str):
        _fail("base", f"a scenario file path or a scenario object, got {_show(base)}")
    path = base if os.path.isabs(base) else os.path.normpath(os.path.join(directory, base))
    try:
        with open(path, encoding="utf-8") as f:
            scenario = json.load(f)
    except FileNotFoundError:
        _fail("base", f"{base}: no such file ({path})")
    except json.JSONDecodeError as e:
        _fail("base", f"{path}: not JSON ({e})")
    if not isinstance(scenario, dict):
        _fail("base", f"{path}: a scenario is a JSON object")
    return _absolute_files(scenario, os.path.dirname(path)), path


def _absolute_files(node: Any, directory: str) -> Any:
    """Files a scenario names ("file": "x.opm") are relative to the scenario;
    a task's copy lives elsewhere, so they become absolute."""
    if isinstance(node, dict):
        for k, v in node.items():
            if k == "file" and isinstance(v, str) and not os.path.isabs(v):
                node[k] = os.path.normpath(os.path.join(directory, v))
            else:
                _absolute_files(v, directory)
    elif isinstance(node, list):
        for v in node:
            _absolute_files(v, directory)
    return node


def _read_job(job: Any, spec: CampaignSpec) -> None:
    if not isinstance(job, dict):
        _fail("job", f"an object, got {_show(job)}")
    unknown = sorted(set(job) - _JOB_KEYS)
    if unknown:
        _fail(f"job.{unknown[0]}", f"unknown job field (known: {', '.join(sorted(_JOB_KEYS))})")
    spec.kind = job.get("kind", "solve")
    if spec.kind not in KINDS:
        _fail("job.kind", f"{_show(spec.kind)} is not one of {', '.join(KINDS)}")
    if "cycles" in job:
        c = job["cycles"]
        if spec.kind != "simulate":
            _fail("job.cycles", "only for \"kind\": \"simulate\"")
        if isinstance(c, bool) or not isinstance(c, int) or c < 1:
            _fail("job.cycles", f"an integer >= 1, got {_show(c)}")
        spec.cycles = c
    solver = job.get("solver", {})
    if not isinstance(solver, dict):
        _fail("job.solver", f"an object (scenario \"solver\" fields), got {_show(solver)}")
    if spec.kind == "simulate" and solver:
        _fail("job.solver", "a year run's solves are set in the scenario's long_horizon section (cycle_*)")
    spec.solver = dict(solver)
    plots = job.get("plots", False)
    if not isinstance(plots, bool):
        _fail("job.plots", f"true or false, got {_show(plots)}")
    spec.plots = plots


def _read_lists(section: Any, where: str) -> List[Tuple[str, list]]:
    if not isinstance(section, dict):
        _fail(where, f"an object of field path -> list of values, got {_show(section)}")
    out = []
    for path, values in section.items():
        parse_field_path(path)
        if not isinstance(values, list):
            _fail(f"{where}.{path}", f"a list of values, got {_show(values)}")
        if not values:
            _fail(f"{where}.{path}", "an empty list: the campaign would have no task")
        for v in values:
            _check_finite(v, f"{where}.{path}")
        out.append((path, values))
    return out


def _check_finite(value: Any, path: str) -> None:
    if isinstance(value, float) and not math.isfinite(value):
        _fail(path, f"{value} is not a finite number")
    if isinstance(value, list):
        for v in value:
            _check_finite(v, path)
    if isinstance(value, dict):
        for v in value.values():
            _check_finite(v, path)


def _read_monte_carlo(mc: Any) -> MonteCarlo:
    if not isinstance(mc, dict):
        _fail("monte_carlo", f"an object, got {_show(mc)}")
    unknown = sorted(set(mc) - _MC_KEYS)
    if unknown:
        _fail(f"monte_carlo.{unknown[0]}", f"unknown field (known: {', '.join(sorted(_MC_KEYS))})")
    samples, seed = mc.get("samples"), mc.get("seed")
    if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
        _fail("monte_carlo.samples", f"an integer >= 1, got {_show(samples)}")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        _fail("monte_carlo.seed", f"an integer >= 0 (the same seed gives the same samples), got {_show(seed)}")
    fields = mc.get("fields")
    if not isinstance(fields, dict) or not fields:
        _fail("monte_carlo.fields", f"an object of field path -> distribution, got {_show(fields)}")
    out = []
    for path, dist in fields.items():
        where = f"monte_carlo.fields.{path}"
        parse_field_path(path)
        if not isinstance(dist, dict) or len(dist) != 1:
            _fail(where, f"one distribution: {{\"normal\": [mean, sd]}}, {{\"uniform\": [low, high]}} "
                         f"or {{\"choice\": [values]}}, got {_show(dist)}")
        kind, args = next(iter(dist.items()))
        if kind not in DISTRIBUTIONS:
            _fail(where, f"unknown distribution {_show(kind)} (known: {', '.join(DISTRIBUTIONS)})")
        if not isinstance(args, list) or not args:
            _fail(f"{where}.{kind}", f"a list, got {_show(args)}")
        n = DISTRIBUTIONS[kind]
        if n is not None:
            if len(args) != n or not all(isinstance(a, (int, float)) and not isinstance(a, bool)
                                         and math.isfinite(a) for a in args):
                _fail(f"{where}.{kind}", f"{n} finite numbers, got {_show(args)}")
            if kind == "normal" and args[1] < 0:
                _fail(f"{where}.normal", f"a standard deviation >= 0, got {args[1]}")
            if kind == "uniform" and args[1] < args[0]:
                _fail(f"{where}.uniform", f"low <= high, got {_show(args)}")
        out.append((path, kind, args))
    return MonteCarlo(samples=samples, seed=seed, fields=out)
