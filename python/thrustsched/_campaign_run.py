"""Runs a campaign's tasks: serially, on a local Dask cluster of worker
processes, or on an existing Dask cluster (thrustsched.sweep).

    outcome = run_campaign(load_spec("data/campaigns/hcw_quick.json"), "out/hcw_quick", workers=2)
    outcome.rows, outcome.failed, outcome.exit_code

The out folder holds one campaign: campaign.json (what was asked),
scenarios/ID.json (each task's resolved scenario), tasks/ID/ (each task's
CLI run folder), rows/ID.json (each finished task's row: written before the
task is reported, the mark that --resume skips it), results.csv, report.md.
A folder holding an earlier campaign is refused unless resume (continue it:
only what is missing runs) or force (start over) is given.
"""
from __future__ import annotations

import dataclasses
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional

from ._campaign_results import failed_row, write_json_atomic, write_results_csv
from ._campaign_spec import CampaignError, CampaignSpec
from ._campaign_task_run import (TaskCrashed, TaskInterrupted, finished_row, read_attempts, run_task,
                                 task_paths)
from ._campaign_tasks import Task, expand

CAMPAIGN_FILE = "campaign.json"
_OWN = ("campaign.json", "scenarios", "tasks", "rows", "attempts", "results.csv", "report.md", "plots")
EXIT_OK, EXIT_FAILED_TASKS, EXIT_BAD_INPUT, EXIT_INTERRUPTED = 0, 1, 2, 4


@dataclass
class CampaignOutcome:
    out: str
    spec: CampaignSpec
    tasks: List[Task]
    rows: List[Dict[str, Any]] = field(default_factory=list)
    failed: List[Dict[str, Any]] = field(default_factory=list)
    skipped: int = 0  # finished before (resume)
    interrupted: bool = False
    wall_s: float = 0.0

    @property
    def exit_code(self) -> int:
        if self.interrupted:
            return EXIT_INTERRUPTED
        return EXIT_FAILED_TASKS if self.failed else EXIT_OK


def prepare_out(out: str, spec: CampaignSpec, tasks: List[Task], resume: bool, force: bool) -> None:
    record = os.path.join(out, CAMPAIGN_FILE)
    if os.path.exists(record) and not (resume or force):
        raise CampaignError(f"--out {out}: holds an earlier campaign ({record}); --resume continues it, "
                            f"--force starts over")
    if os.path.isdir(out) and not os.path.exists(record) and os.listdir(out) and not force:
        raise CampaignError(f"--out {out}: a folder that is not a campaign's and not empty; "
                            f"choose another (or --force to use it anyway)")
    if force and not resume:
        for name in _OWN:
            p = os.path.join(out, name)
            if os.path.isdir(p):
                shutil.rmtree(p)
            elif os.path.exists(p):
                os.remove(p)
    os.makedirs(out, exist_ok=True)
    # Made here, not only by the tasks: a task that fails before its code runs
    # on a worker (e.g. one that cannot import thrustsched) is recorded here.
    for name in ("scenarios", "tasks", "rows", "attempts"):
        os.makedirs(os.path.join(out, name), exist_ok=True)
    write_json_atomic(record, {"name": spec.name, "source": spec.source, "base": spec.base_source,
                               "kind": spec.kind, "parameters": spec.parameters,
                               "tasks": [{"task": t.index, "task_id": t.id, "params": t.params} for t in tasks]})


class _Progress:
    """One line per finished task on stderr: done/running/failed and an ETA
    from this run's mean task time per worker slot."""

    def __init__(self, total: int, skipped: int, slots: int, enabled: bool):
        self.total, self.done, self.failed, self.slots = total, skipped, 0, max(1, slots)
        self.ran = 0
        self.start = time.monotonic()
        self.enabled = enabled

    def finished(self, ok: bool, label: str) -> None:
        self.done += 1
        self.ran += 1
        self.failed += 0 if ok else 1
        if not self.enabled:
            return
        elapsed = time.monotonic() - self.start
        remaining = self.total - self.done
        eta = elapsed / self.ran * remaining if self.ran else float("nan")
        running = min(self.slots, remaining)
        print(f"sweep: {self.done}/{self.total} done, {running} running, {self.failed} failed, "
              f"elapsed {elapsed:.0f} s, ETA {eta:.0f} s ({label})", file=sys.stderr, flush=True)


# Ctrl-C seen by this process. Python raises KeyboardInterrupt wherever the
# main thread is when the signal lands; inside a finaliser or a logging lock
# release ("Exception ignored in ...") it is printed and dropped, and the
# campaign would run on. The flag stops it at the next task boundary anyway.
_SIGINT_SEEN = threading.Event()


def _on_sigint(signum: int, frame: Any) -> None:
    _SIGINT_SEEN.set()
    raise KeyboardInterrupt


def _record(outcome: CampaignOutcome, task: Task, row: Optional[Dict[str, Any]], error: str,
            progress: _Progress) -> None:
    if row is None:
        row = failed_row(task, error, attempts=read_attempts(task_paths(outcome.out, task.id)["attempts"]))
        outcome.failed.append(row)
        write_json_atomic(os.path.join(outcome.out, "rows", f"{task.id}.failed.json"), row)
        progress.finished(False, f"task {task.index} failed: {error.splitlines()[0][:120]}")
    else:
        progress.finished(True, f"task {task.index}: {row['status']}")
    outcome.rows.append(row)
    write_results_csv(os.path.join(outcome.out, "results.csv"), outcome.spec.parameters, outcome.rows)
    if _SIGINT_SEEN.is_set():
        raise KeyboardInterrupt


def _run_serial(outcome: CampaignOutcome, pending: List[Task], progress: _Progress, faults: Dict[str, str]) -> None:
    for t in pending:
        row, error = None, ""
        for _ in range(2):  # a crash is retried once
            try:
                row = run_task(dataclasses.asdict(t), outcome.out, fault=faults.get(t.id))
                break
            except TaskCrashed as e:
                error = str(e)
            except TaskInterrupted:
                raise KeyboardInterrupt from None
            except subprocess.SubprocessError:
                # A Ctrl-C that lands while the task's process forks raises
                # KeyboardInterrupt in the child's preexec_fn, which Popen
                # reports as this error: the interrupt, not a crash.
                if _SIGINT_SEEN.is_set():
                    raise KeyboardInterrupt from None
                raise
        _record(outcome, t, row, error, progress)


def _run_dask(outcome: CampaignOutcome, pending: List[Task], progress: _Progress, client: Any,
              faults: Dict[str, str]) -> None:
    from distributed import as_completed

    from ._campaign_workers import erred_workers

    out = os.path.abspath(outcome.out)
    futures = {}
    for t in pending:
        f = client.submit(run_task, dataclasses.asdict(t), out, sys.executable,
                          faults.get(t.id), key=f"thrustsched-task-{t.id}", pure=False,
                          retries=1)
        futures[f] = t
    try:
        for f in as_completed(list(futures)):
            t = futures[f]
            if f.status == "finished":
                _record(outcome, t, f.result(), "", progress)
            else:
                exc = f.exception()
                if isinstance(exc, TaskInterrupted):
                    raise KeyboardInterrupt
                # The worker's message and its address (Dask retried the task once).
                where = erred_workers(client, [f.key]).get(f.key, "")
                _record(outcome, t, None, f"{type(exc).__name__}: {exc}"
                        + (f" (on worker {where})" if where else ""), progress)
    finally:
        for f in futures:
            if not f.done():
                f.cancel()


def run_campaign(spec: CampaignSpec, out: str, *, client: Any = None, workers: Optional[int] = None,
                 resume: bool = False, force: bool = False, progress: bool = True,
                 _faults: Optional[Dict[str, str]] = None, _check_workers: bool = True) -> CampaignOutcome:
    """Runs what is missing of the campaign into out (see the module's text).

    client: a dask.distributed Client (an existing cluster); else workers
    (default: one per core) local worker processes, or 1 to run the tasks one
    after the other in this process's children without Dask.
    _faults: task id -> a fault to inject (tests only; run_task's fault).
    _check_workers: False skips the workers' handshake (tests only: to see
    how a task that fails on a worker is recorded).
    A client's workers are checked first (_campaign_workers.check_workers):
    CampaignError, nothing run, when one cannot run tasks.
    """
    from ._campaign_report import write_report

    start = time.monotonic()
    tasks = expand(spec)
    if client is not None and _check_workers:
        from ._campaign_workers import check_workers

        check_workers(client, out)
    prepare_out(out, spec, tasks, resume, force)
    outcome = CampaignOutcome(out=out, spec=spec, tasks=tasks)
    pending = []
    for t in tasks:
        row = finished_row(out, t.id) if resume else None
        if row is None:
            pending.append(t)
        else:
            outcome.rows.append(row)
    outcome.skipped = len(outcome.rows)
    write_results_csv(os.path.join(out, "results.csv"), spec.parameters, outcome.rows)
    faults = dict(_faults or {})
    slots = workers or os.cpu_count() or 1
    prog = _Progress(len(tasks), outcome.skipped, slots if client is None else 0, progress)
    if progress and outcome.skipped:
        print(f"sweep: {outcome.skipped} of {len(tasks)} tasks finished before, {len(pending)} to run",
              file=sys.stderr, flush=True)
    _SIGINT_SEEN.clear()
    main_thread = threading.current_thread() is threading.main_thread()
    previous_handler = signal.signal(signal.SIGINT, _on_sigint) if main_thread else None
    try:
        if not pending:
            pass
        elif client is not None:
            prog.slots = max(1, sum(w.get("nthreads", 1) for w in client.scheduler_info()["workers"].values()))
            _announce(client, progress)
            _run_dask(outcome, pending, prog, client, faults)
        elif slots == 1:
            _run_serial(outcome, pending, prog, faults)
        else:
            _run_local_cluster(outcome, pending, prog, slots, faults, progress)
    except KeyboardInterrupt:
        outcome.interrupted = True
        if progress:
            print(f"sweep: interrupted; {len(outcome.rows)} of {len(tasks)} tasks are on disk, "
                  f"--resume runs the rest", file=sys.stderr, flush=True)
    finally:
        if main_thread and previous_handler is not None:
            signal.signal(signal.SIGINT, previous_handler)
    outcome.wall_s = time.monotonic() - start
    write_report(outcome)
    return outcome


def _run_local_cluster(outcome: CampaignOutcome, pending: List[Task], progress: _Progress, workers: int,
                       faults: Dict[str, str], verbose: bool) -> None:
    import dask
    from distributed import Client, LocalCluster

    # A task whose worker dies is given to another worker once, then failed.
    with dask.config.set({"distributed.scheduler.allowed-failures": 1,
                          "distributed.worker.daemon": False,
                          "distributed.logging.distributed": "error"}):
        with tempfile.TemporaryDirectory(prefix="thrustsched-dask-") as scratch, \
                LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0",
                             silence_logs=40, local_directory=scratch) as cluster, Client(cluster) as client:
            _announce(client, verbose)
            _run_dask(outcome, pending, progress, client, faults)


def _announce(client: Any, verbose: bool) -> None:
    if not verbose:
        return
    link = getattr(client, "dashboard_link", None)
    n = len(client.scheduler_info().get("workers", {}))
    print(f"sweep: {n} Dask worker{'' if n == 1 else 's'}" + (f", dashboard {link}" if link else ""),
          file=sys.stderr, flush=True)
