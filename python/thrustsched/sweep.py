"""Campaigns: parameter sweeps and Monte Carlo runs of solves or year
simulations, on a local pool of worker processes or a Dask cluster.

    import thrustsched as ts
    outcome = ts.sweep.run("data/campaigns/hcw_quick.json", out="out/hcw_quick")   # one worker per core
    outcome = ts.sweep.run(spec, out="out/c", client=Client("tcp://HOST:8786"))     # an existing cluster
    outcome = ts.sweep.run(spec, out="out/c", resume=True)                           # only what is missing
    tasks = ts.sweep.tasks("data/campaigns/hcw_quick.json")                          # what would run

The command line (``thrustsched-sweep``, or ``python3 -m thrustsched.sweep``):

    thrustsched-sweep campaign.json --out out/campaign [--workers N | --scheduler tcp://HOST:8786]
                      [--resume | --force] [--dry-run] [--emit-tasks tasks.txt] [--quiet]

Exit codes: 0 every task finished (infeasible and no-solution are results),
1 some tasks failed (named on stderr and in report.md), 2 a bad campaign
file or option (the field path and value named, nothing run), 4 interrupted
(Ctrl-C: the finished tasks are on disk, --resume runs the rest). The
campaign file and the out folder are described in data/campaigns/README.md.
"""
from __future__ import annotations

import argparse
import math
import os
import shlex
import sys
from typing import Any, List, Optional, Union

from ._campaign_run import (EXIT_BAD_INPUT, EXIT_INTERRUPTED, CampaignOutcome, run_campaign)
from ._campaign_spec import CampaignError, CampaignSpec, PathLike, load_spec
from ._campaign_task_run import task_paths
from ._campaign_tasks import Task, expand

__all__ = ["run", "tasks", "load", "emit_tasks", "CampaignError", "CampaignSpec", "CampaignOutcome", "Task",
           "main"]


def load(spec: Union[PathLike, dict, CampaignSpec]) -> CampaignSpec:
    """A campaign file (or dict) read and checked: CampaignError names the field."""
    return spec if isinstance(spec, CampaignSpec) else load_spec(spec)


def tasks(spec: Union[PathLike, dict, CampaignSpec]) -> List[Task]:
    """The campaign's tasks, each scenario checked by the scenario parser."""
    return expand(load(spec))


def run(spec: Union[PathLike, dict, CampaignSpec], out: PathLike, *, client: Any = None,
        workers: Optional[int] = None, resume: bool = False, force: bool = False,
        progress: bool = True) -> CampaignOutcome:
    """Runs the campaign into out (results.csv, report.md, one folder per
    task). client: a dask.distributed Client; else ``workers`` local worker
    processes (default one per core; 1 runs the tasks one after the other
    without Dask). A task's result does not depend on the worker or the load:
    solves stop on a node budget and the gap (job.solver; the scenario's
    wall-clock limit is dropped unless job.solver sets one)."""
    return run_campaign(load(spec), os.fspath(out), client=client, workers=workers, resume=resume,
                        force=force, progress=progress)


def emit_tasks(spec: Union[PathLike, dict, CampaignSpec], out: PathLike, path: PathLike) -> List[str]:
    """Writes each task's scenario under out/scenarios/ and one
    ``thrustsched solve|simulate ...`` command per line to path (for a Slurm
    job array or GNU parallel, on machines that share out); returns the
    lines. ``run(..., resume=True)`` afterwards collects the runs those
    commands finished into results.csv and runs only the others."""
    from ._campaign_results import write_json_atomic

    from ._campaign_run import prepare_out

    out = os.fspath(out)
    spec = load(spec)
    all_tasks = expand(spec)
    prepare_out(out, spec, all_tasks, resume=True, force=False)
    lines = []
    for t in all_tasks:
        paths = task_paths(out, t.id)
        os.makedirs(os.path.dirname(paths["scenario"]), exist_ok=True)
        write_json_atomic(paths["scenario"], t.scenario)
        lines.append(" ".join(shlex.quote(a) for a in t.command(paths["scenario"], paths["dir"])))
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return lines


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="thrustsched-sweep",
                                description="Run a campaign of thrustsched solves or year simulations "
                                            "(a grid, zipped lists or Monte Carlo samples over scenario "
                                            "fields) on local worker processes or a Dask cluster.")
    p.add_argument("campaign", help="campaign file (JSON; data/campaigns/README.md)")
    p.add_argument("--out", required=True, help="the campaign's folder")
    p.add_argument("--workers", type=int, default=None,
                   help="local worker processes (default: one per core; 1: no Dask, one task after the other)")
    p.add_argument("--scheduler", default=None, help="address of an existing Dask scheduler (tcp://HOST:8786)")
    p.add_argument("--resume", action="store_true", help="continue the campaign in --out: only what is missing runs")
    p.add_argument("--force", action="store_true", help="start over in a folder holding an earlier campaign")
    p.add_argument("--dry-run", action="store_true", help="print the tasks and what would run; run nothing")
    p.add_argument("--emit-tasks", metavar="FILE", default=None,
                   help="write one `thrustsched ...` command per task to FILE (Slurm arrays, GNU parallel); run nothing")
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    return p


def _dry_run(spec: CampaignSpec, out: str) -> None:
    from ._campaign_task_run import finished_row

    ts = expand(spec)
    finished = {t.id: row for t in ts for row in [finished_row(out, t.id)] if row is not None}
    print(f"campaign {spec.name}: {len(ts)} {spec.kind} tasks over {', '.join(spec.parameters) or 'nothing'}; "
          f"{len(finished)} finished in {out}")
    for t in ts:
        swept = ", ".join(f"{p}={v}" for p, v in t.params.items())
        print(f"  {t.index:4d} {t.id} {'done ' if t.id in finished else 'to run'} {swept}")
    # Collected runs (--emit-tasks) have no wall time of their own (NaN).
    walls = sorted(w for w in (r.get("wall_s") for r in finished.values())
                   if isinstance(w, float) and math.isfinite(w))
    if walls:
        median = walls[len(walls) // 2]
        todo = len(ts) - len(finished)
        print(f"estimated cost: {todo} tasks x {median:.3g} s (median of the finished ones) = "
              f"{todo * median / 3600:.3g} core-hours")
    else:
        print("estimated cost: unknown until a task has run (a year of GEO cycles is ~25 core-minutes, "
              "a GEO week ~1, an HCW day ~0.02)")


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(argv)
    if args.resume and args.force:
        print("thrustsched-sweep: --resume and --force exclude each other", file=sys.stderr)
        return EXIT_BAD_INPUT
    if args.workers is not None and args.workers < 1:
        print(f"thrustsched-sweep: --workers: must be >= 1, got {args.workers}", file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        spec = load_spec(args.campaign)
        if args.dry_run:
            _dry_run(spec, args.out)
            return 0
        if args.emit_tasks:
            lines = emit_tasks(spec, args.out, args.emit_tasks)
            print(f"{len(lines)} commands in {args.emit_tasks}")
            return 0
        client = None
        if args.scheduler:
            from distributed import Client

            try:
                client = Client(args.scheduler, timeout="20s")
            except (OSError, TimeoutError) as e:
                raise CampaignError(f"--scheduler {args.scheduler}: cannot connect ({e})") from None
        outcome = run_campaign(spec, args.out, client=client, workers=args.workers, resume=args.resume,
                               force=args.force, progress=not args.quiet)
    except CampaignError as e:
        print(f"thrustsched-sweep: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        return EXIT_INTERRUPTED
    done = len(outcome.rows) - len(outcome.failed)
    print(f"campaign {spec.name}: {done} of {len(outcome.tasks)} tasks finished, {len(outcome.failed)} failed, "
          f"{outcome.wall_s:.1f} s; {os.path.join(args.out, 'results.csv')}, {os.path.join(args.out, 'report.md')}")
    for r in outcome.failed:
        print(f"thrustsched-sweep: task {r['task']} ({r['task_id']}) failed: {r['error']}", file=sys.stderr)
    return outcome.exit_code


if __name__ == "__main__":
    sys.exit(main())
