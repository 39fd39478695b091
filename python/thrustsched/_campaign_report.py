"""report.md of a campaign: what ran, the results against each swept
parameter (a table and an SVG plot each), and the failures with their errors
(thrustsched.sweep).

    write_report(outcome)     # out/report.md, out/plots/<parameter>.svg
"""
from __future__ import annotations

import math
import os
from typing import Any, Dict, List

from ._campaign_results import columns

_SHOWN = ["status", "consumption_l1_m_s", "gap", "thrust_days", "max_window_violation", "check_passed",
          "solve_s"]


def _fmt(v: Any) -> str:
    if isinstance(v, float):
        return "" if math.isnan(v) else f"{v:.6g}"
    if isinstance(v, bool):
        return "yes" if v else "no"
    return str(v)


def _scalar(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _plots(outcome: Any, rows: List[Dict[str, Any]]) -> List[str]:
    """One plot per swept parameter with numeric values: consumption against
    it, one line per combination of the other swept values."""
    params = outcome.spec.parameters
    numeric = [p for p in params if rows and all(_scalar(r.get(p)) for r in rows)]
    if not numeric:
        return []
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return []
    os.makedirs(os.path.join(outcome.out, "plots"), exist_ok=True)
    made = []
    for p in numeric:
        others = [q for q in params if q != p]
        groups: Dict[str, List[Dict[str, Any]]] = {}
        for r in rows:
            label = ", ".join(f"{q} = {_fmt(r.get(q))}" for q in others) or outcome.spec.name
            groups.setdefault(label, []).append(r)
        fig, ax = plt.subplots(figsize=(7, 4))
        for label, rs in sorted(groups.items()):
            rs = sorted(rs, key=lambda r: r[p])
            ax.plot([r[p] for r in rs], [r["consumption_l1_m_s"] for r in rs], marker="o", label=label)
        ax.set_xlabel(p)
        ax.set_ylabel("consumption (L1, m/s)")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        if len(groups) > 1:
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        fig.tight_layout()
        name = "".join(c if c.isalnum() or c in "._-" else "_" for c in p) + ".svg"
        fig.savefig(os.path.join(outcome.out, "plots", name), metadata={"Date": None})
        plt.close(fig)
        made.append(f"plots/{name}")
    return made


def write_report(outcome: Any) -> None:
    spec = outcome.spec
    done = sorted((r for r in outcome.rows if r.get("status") != "failed"), key=lambda r: r["task"])
    lines = [f"# Campaign {spec.name}", "",
             f"- campaign file: `{spec.source}`; base scenario: `{spec.base_source}`; job: {spec.kind}"
             + (f", {spec.cycles} cycles" if spec.cycles else ""),
             f"- tasks: {len(outcome.tasks)}; finished: {len(done)}; failed: {len(outcome.failed)}; "
             f"finished by an earlier run: {outcome.skipped}"
             + ("; interrupted (`--resume` runs the rest)" if outcome.interrupted else ""),
             f"- this run's wall time: {outcome.wall_s:.1f} s; results: `results.csv` "
             f"(columns: {', '.join(columns(spec.parameters))})", ""]
    plots = _plots(outcome, done)
    if plots:
        lines += ["## Consumption against each swept parameter", ""]
        lines += [f"![{p}]({p})" for p in plots] + [""]
    lines += ["## Results", "", "| task | " + " | ".join(spec.parameters + _SHOWN) + " |",
              "|" + "---|" * (1 + len(spec.parameters) + len(_SHOWN))]
    for r in done:
        lines.append(f"| {r['task']} | " + " | ".join(_fmt(r.get(c)) for c in spec.parameters + _SHOWN) + " |")
    if outcome.failed:
        lines += ["", "## Failed tasks", ""]
        for r in sorted(outcome.failed, key=lambda r: r["task"]):
            lines.append(f"- task {r['task']} (`{r['task_id']}`, {r['attempts']} attempts): {r['error']}")
    with open(os.path.join(outcome.out, "report.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
