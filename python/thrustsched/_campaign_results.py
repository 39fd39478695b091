"""A campaign's results: one row per task (from the task's own summary.json
or year.json), results.csv, and the failures (thrustsched.sweep).

    row = result_row(task, "out/c/tasks/ID", exit_code=0, wall_s=1.4, worker="1")
    write_results_csv("out/c/results.csv", spec.parameters, rows)

Columns: task, task_id, the swept field paths, status, exit_code, objective,
best_bound, gap, consumption_l1_m_s, delta_v_m_s, propellant_kg,
thrust_days, max_window_violation, check_passed, then the ones that vary from
run to run (solve_s, wall_s, worker, attempts) and error. Every column before
solve_s is a function of the task id (the same on any worker, at any load).
"""
from __future__ import annotations

import csv
import io
import json
import math
import os
from typing import Any, Dict, List

RESULT_COLUMNS = ["status", "exit_code", "objective", "best_bound", "gap", "consumption_l1_m_s",
                  "delta_v_m_s", "propellant_kg", "thrust_days", "max_window_violation", "check_passed"]
VARYING_COLUMNS = ["solve_s", "wall_s", "worker", "attempts", "error"]


def write_json_atomic(path: str, data: Any) -> None:
    """Writes through a temporary file and a rename: a reader (or a crash)
    sees the old file or the new one, never half of one."""
    _write_atomic(path, json.dumps(data, indent=1, sort_keys=True, allow_nan=True) + "\n")


def _write_atomic(path: str, text: str) -> None:
    tmp = f"{path}.tmp{os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    finally:  # an interrupt (Ctrl-C) before the rename leaves no half file behind
        if os.path.exists(tmp):
            os.remove(tmp)


def _read(path: str) -> Dict[str, Any]:
    if not os.path.exists(path):
        return {}
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _number(v: Any) -> float:
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else math.nan


def result_row(task: Any, task_dir: str, exit_code: int, wall_s: float, worker: str) -> Dict[str, Any]:
    row: Dict[str, Any] = {"task": task.index, "task_id": task.id, **task.params, "exit_code": exit_code}
    if task.kind == "solve":
        s = _read(os.path.join(task_dir, "summary.json"))
        check = s.get("check") or {}
        on_time = s.get("on_time_s") or {}
        row.update(status=s.get("status", "unknown"), objective=_number(s.get("objective")),
                   best_bound=_number(s.get("best_bound")), gap=_number(s.get("gap")),
                   consumption_l1_m_s=_number(s.get("consumption_l1_m_s")),
                   delta_v_m_s=_number(s.get("delta_v_m_s")), propellant_kg=_number(s.get("propellant_kg")),
                   thrust_days=sum(_number(v) for v in on_time.values()) / 86400.0 if on_time else math.nan,
                   max_window_violation=_number(check.get("max_window_violation")),
                   check_passed=check.get("passed"), solve_s=_number(s.get("solve_seconds")))
    else:
        y = _read(os.path.join(task_dir, "year.json"))
        gap = y.get("gap") or {}
        thrust = y.get("thrust_days") or {}
        complete = y.get("complete") or (task.cycles is not None and y.get("cycles", 0) >= task.cycles)
        row.update(status="complete" if complete else "incomplete",
                   objective=_number(y.get("consumption_l1_m_s")), best_bound=math.nan,
                   gap=_number(gap.get("max")), consumption_l1_m_s=_number(y.get("consumption_l1_m_s")),
                   delta_v_m_s=_number(y.get("delta_v_m_s")), propellant_kg=_number(y.get("propellant_kg")),
                   thrust_days=_number(thrust.get("total")),
                   max_window_violation=_number(y.get("max_window_violation_deg")),
                   check_passed=bool(y.get("box_held")) and bool(y.get("rules_ok")),
                   solve_s=_number((y.get("solve_seconds") or {}).get("mean", math.nan)) *
                   _number((y.get("solve_seconds") or {}).get("count", math.nan)))
    row.update(wall_s=wall_s, worker=str(worker), attempts=1, error="")
    return row


def failed_row(task: Any, error: str, attempts: int) -> Dict[str, Any]:
    row: Dict[str, Any] = {"task": task.index, "task_id": task.id, **task.params}
    row.update({c: math.nan for c in RESULT_COLUMNS})
    row.update(status="failed", exit_code=math.nan, check_passed="", solve_s=math.nan, wall_s=math.nan,
               worker="", attempts=attempts, error=error.replace("\n", " | "))
    return row


def columns(parameters: List[str]) -> List[str]:
    return ["task", "task_id", *parameters, *RESULT_COLUMNS, *VARYING_COLUMNS]


def _cell(v: Any) -> str:
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return "" if math.isnan(v) else repr(v)
    if isinstance(v, (list, dict)):
        return json.dumps(v, separators=(",", ":"))
    return str(v)


def results_csv_text(parameters: List[str], rows: List[Dict[str, Any]]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    cols = columns(parameters)
    w.writerow(cols)
    for row in sorted(rows, key=lambda r: r["task"]):
        w.writerow([_cell(row.get(c)) for c in cols])
    return buf.getvalue()


def write_results_csv(path: str, parameters: List[str], rows: List[Dict[str, Any]]) -> None:
    _write_atomic(path, results_csv_text(parameters, rows))
