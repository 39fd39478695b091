"""matplotlib figures of a checked schedule (the CLI's three SVG plots).

    figs = plot_all(trajectory_df, schedule_df, ["+R", "+T"], ["y_m", "z_m"], [36800, 36800], "m", "name")
"""
from __future__ import annotations

from typing import Any, Dict, List


def plot_all(trajectory, schedule, thrusters: List[str], window_columns: List[str],
             half_widths: List[float], unit: str, title: str) -> Dict[str, Any]:
    import matplotlib.pyplot as plt

    figs: Dict[str, Any] = {}
    have_traj = trajectory is not None and len(trajectory) > 0
    cols = [c for c in window_columns if have_traj and c in trajectory.columns]

    # The trajectory in the window.
    fig, ax = plt.subplots(figsize=(6, 5), layout="constrained")
    if len(cols) == 2:
        ax.plot(trajectory[cols[0]], trajectory[cols[1]], lw=0.8, label="linear re-propagation")
        if "dlon_deg" in trajectory.columns and "lat_deg" in trajectory.columns:
            ax.plot(trajectory["dlon_deg"], trajectory["lat_deg"], lw=0.8, ls="--", label="nonlinear replay")
        if len(half_widths) == 2:
            w0, w1 = half_widths
            ax.plot([-w0, w0, w0, -w0, -w0], [-w1, -w1, w1, w1, -w1], color="k", lw=1, label="window")
        ax.set_xlabel(f"{cols[0]}")
        ax.set_ylabel(f"{cols[1]}")
        ax.legend(loc="best", fontsize="small")
    else:
        ax.text(0.5, 0.5, "no trajectory (or no two-output window)", ha="center", va="center")
    ax.set_title(f"{title}: trajectory in the window")
    figs["window"] = fig

    # Firing timeline.
    fig, ax = plt.subplots(figsize=(8, 1.0 + 0.45 * max(1, len(thrusters))), layout="constrained")
    for k, name in enumerate(thrusters):
        if schedule is not None and len(schedule) and "start_s" in schedule.columns:
            rows = schedule[schedule["thruster"] == name]
            bars = [(s / 3600.0, (e - s) / 3600.0) for s, e in zip(rows["start_s"], rows["end_s"])]
            if bars:
                ax.broken_barh(bars, (k - 0.35, 0.7))
        elif schedule is not None and len(schedule) and "time_s" in schedule.columns:
            rows = schedule[schedule["thruster"] == name]
            ax.vlines(rows["time_s"] / 3600.0, k - 0.35, k + 0.35)
    ax.set_yticks(range(len(thrusters)))
    ax.set_yticklabels(thrusters)
    ax.invert_yaxis()
    ax.set_xlabel("time (h)")
    if have_traj:
        ax.set_xlim(trajectory["t_s"].iloc[0] / 3600.0, trajectory["t_s"].iloc[-1] / 3600.0)
    ax.set_title(f"{title}: firings")
    figs["timeline"] = fig

    # Outputs against time.
    fig, axes = plt.subplots(max(1, len(cols)), 1, figsize=(8, 2.5 * max(1, len(cols))), sharex=True,
                             squeeze=False, layout="constrained")
    for k, c in enumerate(cols):
        a = axes[k][0]
        a.plot(trajectory["t_s"] / 3600.0, trajectory[c], lw=0.8)
        if k < len(half_widths):
            a.axhline(half_widths[k], color="k", lw=0.8)
            a.axhline(-half_widths[k], color="k", lw=0.8)
        a.set_ylabel(f"{c}")
    axes[-1][0].set_xlabel("time (h)")
    axes[0][0].set_title(f"{title}: outputs ({unit})" if unit else f"{title}: outputs")
    figs["outputs"] = fig
    return figs
