"""One campaign task, run on whatever worker holds it: the CLI in a process of
its own (``python3 -m thrustsched solve|simulate ...``) into out/tasks/ID,
then its result row written to out/rows/ID.json before it is returned (the
row file is the mark of a finished task; thrustsched.sweep).

    row = run_task(task_dict, "out/campaign")      # what a Dask worker calls

A task's process dies with the worker that started it (PR_SET_PDEATHSIG), so
a killed worker leaves no orphan writing into the folder its retry uses. A
process that crashes (a signal, exit 1) raises TaskCrashed: the campaign
retries the task once, then records it as failed with the error's last lines.
"""
from __future__ import annotations

import ctypes
import json
import os
import signal
import socket
import subprocess
import sys
import time
from typing import Any, Dict, List, Optional

from ._campaign_results import result_row, write_json_atomic

# Exit codes of the CLI that are results (app/cli.h): 0 solved, 3 infeasible,
# 4 no solution within a limit, 5 the checked schedule fails. 2 (bad input)
# cannot happen after the campaign's own check, 1 and signals are crashes.
RESULT_EXIT_CODES = (0, 3, 4, 5)
_PR_SET_PDEATHSIG = 1


class TaskCrashed(RuntimeError):
    """The task's process crashed (the message holds its last stderr lines)."""


class TaskInterrupted(RuntimeError):
    """The task's process was interrupted (Ctrl-C, SIGTERM): not a result, the
    task stays unfinished (a resumed campaign runs it again; a year task then
    continues from its checkpoint)."""


try:  # looked up here: the child between fork and exec only calls it
    _PRCTL = ctypes.CDLL(None, use_errno=True).prctl
except (OSError, AttributeError):
    _PRCTL = None  # not Linux: an orphan may outlive a killed worker


def _die_with_parent() -> None:
    if _PRCTL is not None:
        _PRCTL(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


def task_paths(out: str, task_id: str) -> Dict[str, str]:
    return {"scenario": os.path.join(out, "scenarios", f"{task_id}.json"),
            "dir": os.path.join(out, "tasks", task_id),
            "row": os.path.join(out, "rows", f"{task_id}.json"),
            "attempts": os.path.join(out, "attempts", task_id)}


def finished_row(out: str, task_id: str) -> Optional[Dict[str, Any]]:
    """The task's row when it has finished (its row file), else None."""
    path = task_paths(out, task_id)["row"]
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def run_task(task: Dict[str, Any], out: str, python: str = sys.executable,
             fault: Optional[str] = None) -> Dict[str, Any]:
    """Runs one task (a dict of Task's fields) unless its row is already on
    disk; returns the row. fault (tests only): "crash" makes the task's
    process abort; "kill_worker_once" kills the process running this
    function (a Dask worker) in the task's first attempt."""
    from ._campaign_tasks import Task

    t = Task(**task)
    done = finished_row(out, t.id)
    if done is not None:
        return done
    paths = task_paths(out, t.id)
    for key in ("scenario", "row", "attempts"):
        os.makedirs(os.path.dirname(paths[key]), exist_ok=True)
    collected = _collect_finished_run(t, paths)
    if collected is not None:
        return collected
    write_json_atomic(paths["scenario"], t.scenario)
    attempts = _count_attempt(paths["attempts"])
    resume = t.kind == "simulate" and os.path.exists(os.path.join(paths["dir"], "checkpoint.json"))
    cmd: List[str] = [python, "-m", "thrustsched"] + t.command(paths["scenario"], paths["dir"],
                                                                 resume=resume)[1:]
    if fault == "crash":
        cmd = [python, "-c", "import os; os.abort()"]
    start = time.monotonic()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=_die_with_parent)
    if fault == "kill_worker_once" and attempts == 1:
        os.kill(os.getpid(), signal.SIGKILL)  # mid-task: the task's process dies with this one
    try:
        _, stderr = proc.communicate()
    except KeyboardInterrupt:  # Ctrl-C in a serial campaign: the CLI keeps what it found, then stops
        proc.send_signal(signal.SIGINT)
        try:
            proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
        raise
    wall = time.monotonic() - start
    if _interrupted(t, paths["dir"], proc.returncode):
        raise TaskInterrupted(f"task {t.index} ({t.id}): interrupted")
    if proc.returncode not in RESULT_EXIT_CODES:
        how = (f"killed by signal {-proc.returncode}" if proc.returncode < 0
               else f"exit {proc.returncode}")
        tail = "\n".join((stderr or "").strip().splitlines()[-5:])
        raise TaskCrashed(f"task {t.index} ({t.id}): `{' '.join(cmd[2:])}` {how}"
                          + (f": {tail}" if tail else ""))
    row = result_row(t, paths["dir"], proc.returncode, wall_s=wall, worker=_worker_name())
    row["attempts"] = attempts
    write_json_atomic(paths["row"], row)
    return row


# A finished run's status -> the CLI's exit code (app/cli.h).
_STATUS_EXIT = {"optimal": 0, "feasible": 0, "infeasible": 3, "no_solution": 4}


def _collect_finished_run(t: Any, paths: Dict[str, str]) -> Optional[Dict[str, Any]]:
    """A task run by its emitted command (--emit-tasks, e.g. on Slurm) has its
    files but no row: the row is made from them instead of running again."""
    if not os.path.exists(paths["scenario"]):
        return None
    if t.kind == "solve":
        path = os.path.join(paths["dir"], "summary.json")
        if not os.path.exists(path):
            return None
        with open(path, encoding="utf-8") as f:
            s = json.load(f)
        if s.get("interrupted") or s.get("status") not in _STATUS_EXIT:
            return None
        check = s.get("check") or {}
        code = 5 if check.get("passed") is False else _STATUS_EXIT[s["status"]]
    else:
        path = os.path.join(paths["dir"], "year.json")
        if not os.path.exists(path):
            return None
        with open(path, encoding="utf-8") as f:
            year = json.load(f)
        if not (year.get("complete") or (t.cycles is not None and year.get("cycles", 0) >= t.cycles)):
            return None
        code = 0
    row = result_row(t, paths["dir"], code, wall_s=float("nan"), worker="collected")
    row["attempts"] = 1
    write_json_atomic(paths["row"], row)
    return row


def _interrupted(t: Any, task_dir: str, exit_code: int) -> bool:
    if t.kind == "simulate":
        return exit_code == 4  # `simulate` interrupted (app/cli.h)
    path = os.path.join(task_dir, "summary.json")
    if exit_code not in RESULT_EXIT_CODES or not os.path.exists(path):
        return False
    with open(path, encoding="utf-8") as f:
        return bool(json.load(f).get("interrupted"))


def read_attempts(path: str) -> int:
    """Attempts recorded in an attempts file (0 when there is none)."""
    try:
        with open(path, encoding="utf-8") as f:
            return int(f.read().strip() or 0)
    except (FileNotFoundError, ValueError):
        return 0


def _count_attempt(path: str) -> int:
    """Attempts so far at this task, this one included (a retry after a crash
    or a killed worker counts)."""
    n = read_attempts(path) + 1
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"{n}\n")
    return n


def _worker_name() -> str:
    try:
        from distributed import get_worker

        return str(get_worker().name)
    except (ImportError, ValueError):
        return f"{socket.gethostname()}:{os.getpid()}"
