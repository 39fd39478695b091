#!/usr/bin/env python3
"""Campaign engine scaling: a 12-task GEO-week campaign on 1 and 2 Dask
workers, the engine's per-task overhead, and on paper the wall time of the
thesis's chapter 5 study on 1, 16 and 128 cores.

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/campaign_scaling.py [--repeat 3] [--out docs/bench/campaigns.md]

The campaign: data/scenarios/geo_week_anzel4.json (118 deg E, from 1 Jan
2034) for 12 spacecraft masses, 4700 to 4975 kg: weeks of about the same
difficulty (7-9 s each), so the speed-up measures the engine, not one hard
week. (Other epochs and longitudes include weeks that take minutes within
the node budget: the hard weeks of the solver's own benchmark.) One CBC
thread per task and a node budget (the campaign default), so each task does
the same work in every run. Per repetition it
runs the campaign on a LocalCluster of 1 worker process, then of 2, into
fresh folders, and reports the wall times (medians over the repetitions),
the speed-up, and the per-task overhead: (campaign wall on 1 worker - the
sum of the tasks' own C++ time, summary.json total_seconds) / tasks, which
is everything the engine adds (the Dask round trip, the task's process and
its Python start, reading the row back).

The paper estimate takes the measured wall time of our year runs
(docs/year/*/year.json) as the cost of each year of the study and schedules
them longest first on P cores (a year is a chain of weekly cycles: one
core each).
"""
import argparse
import json
import os
import statistics
import sys
import tempfile
import time

import thrustsched as ts

MASSES_KG = [4700 + 25 * k for k in range(12)]
# The thesis's chapter 5 study (Gazzino 2018, Tables 5.3-5.8) as year runs,
# each costed by the closest of our measured years (docs/year/<name>/year.json).
STUDY = [
    ("nominal, four Anzel thrusters, fixed horizon (Table 5.3)", "year_anzel4_fixed"),
    ("zero final rates, K = 2 (sec. 5.3.2)", "year_anzel4_fixed_margin"),
    ("Table 5.6: thrust angle theta = 55 deg", "year_anzel4_fixed"),
    ("Table 5.6: theta = 60 deg", "year_anzel4_fixed"),
    ("Table 5.6: theta = 65 deg", "year_anzel4_fixed"),
    ("Table 5.6: theta = 70 deg", "year_anzel4_fixed"),
    ("Table 5.6: theta = 75 deg", "year_anzel4_fixed"),
    ("Table 5.6: theta = 80 deg", "year_anzel4_fixed"),
    ("Table 5.6: theta = 85 deg", "year_anzel4_fixed"),
    ("NE thruster failed (Table 5.7)", "year_anzel4_failed_ne"),
    ("SE thruster failed (Table 5.7)", "year_anzel4_failed_ne"),
    ("six ideal thrusters, fixed horizon (Table 5.8)", "year_ideal6_fixed"),
    ("four Anzel thrusters, receding horizon (Table 5.8)", "year_anzel4_receding"),
    ("six ideal thrusters, receding horizon (Table 5.8)", "year_ideal6_receding"),
]


def campaign_spec(base: str) -> dict:
    return {"name": "geo_week_longitudes", "base": os.path.abspath(base), "job": {"kind": "solve"},
            "grid": {"spacecraft.mass_kg": MASSES_KG}}


def run_once(spec: dict, workers: int, root: str) -> dict:
    from distributed import Client, LocalCluster

    out = os.path.join(root, f"w{workers}")
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0",
                      silence_logs=40, local_directory=os.path.join(root, f"dask{workers}")) as cluster, \
            Client(cluster) as client:
        start = time.perf_counter()
        outcome = ts.sweep.run(spec, out=out, client=client, progress=False)
        wall = time.perf_counter() - start
    if outcome.failed:
        sys.exit(f"campaign_scaling: {len(outcome.failed)} tasks failed: {outcome.failed[0]['error']}")
    own = 0.0
    for t in outcome.tasks:
        with open(os.path.join(out, "tasks", t.id, "summary.json")) as f:
            own += json.load(f)["total_seconds"]
    rows = sorted(outcome.rows, key=lambda r: r["task"])
    return {"wall_s": wall, "own_s": own, "consumption": [r["consumption_l1_m_s"] for r in rows],
            "status": [r["status"] for r in rows]}


def makespan(costs, cores: int) -> float:
    loads = [0.0] * cores
    for c in sorted(costs, reverse=True):
        loads[loads.index(min(loads))] += c
    return max(loads)


def paper_estimate(year_dir: str):
    costs = []
    for label, name in STUDY:
        with open(os.path.join(year_dir, name, "year.json")) as f:
            costs.append((label, name, json.load(f)["wall_seconds"]))
    return costs, {p: makespan([c for _, _, c in costs], p) for p in (1, 16, 128)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", default="data/scenarios/geo_week_anzel4.json")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--year-dir", default="docs/year")
    ap.add_argument("--out", default=None, help="also write the results as Markdown here")
    a = ap.parse_args()
    spec = campaign_spec(a.base)
    results = {1: [], 2: []}
    for k in range(a.repeat):
        with tempfile.TemporaryDirectory(prefix="campaign_scaling_") as root:
            for workers in (1, 2):
                r = run_once(spec, workers, root)
                results[workers].append(r)
                print(f"repeat {k + 1}, {workers} worker(s): {r['wall_s']:.1f} s for {len(MASSES_KG)} tasks "
                      f"(their own C++ time {r['own_s']:.1f} s)", flush=True)
    same = all(r["consumption"] == results[1][0]["consumption"] for w in (1, 2) for r in results[w])
    w1 = statistics.median(r["wall_s"] for r in results[1])
    w2 = statistics.median(r["wall_s"] for r in results[2])
    overhead = statistics.median((r["wall_s"] - r["own_s"]) / len(MASSES_KG) for r in results[1])
    own1 = statistics.median(r["own_s"] for r in results[1])
    own2 = statistics.median(r["own_s"] for r in results[2])
    costs, spans = paper_estimate(a.year_dir)
    lines = [
        "# Campaign engine scaling (thrustsched-sweep on Dask)", "",
        f"Measured {time.strftime('%Y-%m-%d')} by `benchmarks/campaign_scaling.py --repeat {a.repeat}` "
        f"(medians of {a.repeat} repetitions) on this {os.cpu_count()}-core machine: "
        f"{len(MASSES_KG)} GEO-week solves (`{a.base}` for masses {MASSES_KG[0]}-{MASSES_KG[-1]} kg), "
        "one CBC thread each, node budget 100 000 (the campaign default).", "",
        "| workers | wall (s) | speed-up | target |", "|---|---|---|---|",
        f"| 1 | {w1:.1f} | 1.00 | |",
        f"| 2 | {w2:.1f} | {w1 / w2:.2f} | >= 1.8 ({'met' if w1 / w2 >= 1.8 else f'missed by {1.8 - w1 / w2:.2f}'}) |",
        "",
        f"Per-task overhead of the engine (1 worker: campaign wall minus the tasks' own C++ time, "
        f"per task): {overhead:.2f} s (target < 1 s: {'met' if overhead < 1 else 'missed'}). "
        f"Identical results on 1 and 2 workers in every repetition: {'yes' if same else 'NO'}; "
        f"statuses: {', '.join(sorted(set(results[1][0]['status'])))}.", "",
        f"The tasks' own C++ time is {100 * (own2 / own1 - 1):.1f} % higher when two run at once "
        f"({own1:.1f} s on 1 worker, {own2:.1f} s on 2: the two cores share the machine's caches and "
        f"memory), so the best any engine could reach here is {own1:.1f} / ({own2:.1f} / 2) = "
        f"{2 * own1 / own2:.2f}; the rest of the gap is the engine's "
        f"({w2 - own2 / 2:.1f} s over the ideal split: the last tasks' uneven end and the Dask round trips).",
        "",
        "## On paper: the thesis's chapter 5 study", "",
        "Each year of the study costed by the wall time of our closest measured year "
        f"(`{a.year_dir}/*/year.json`), scheduled longest first, one core per year (its weeks are a chain):", "",
        "| year run | costed as | wall (h) |", "|---|---|---|",
    ]
    lines += [f"| {label} | {name} | {c / 3600:.2f} |" for label, name, c in costs]
    lines += ["", "| cores | wall (h) |", "|---|---|"]
    lines += [f"| {p} | {s / 3600:.2f} |" for p, s in spans.items()]
    lines += ["", f"From 16 cores on, the study takes as long as its longest year "
                  f"({max(c for _, _, c in costs) / 3600:.2f} h): more cores help only with more years "
                  "(longitudes, layouts, failures)."]
    text = "\n".join(lines) + "\n"
    print(text)
    if a.out:
        with open(a.out, "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    main()
