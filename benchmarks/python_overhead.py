#!/usr/bin/env python3
"""Overhead of the Python layer over the C++ call on the GEO week (build + solve + check).

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_overhead.py [SCENARIO] [--threads N] [--repeat R]

For each run: the wall time of ts.solve() as the caller sees it, the C++
work inside it (discretise + build + solve + check, timed in C++ from the
start of the build to the summary: SolveOutcome.total_seconds), and the
difference, which is everything the Python layer adds (parsing the
scenario dict, the worker thread, GIL hand-overs, progress polling, result
objects). The DataFrames (schedule, trajectory) are made on first access
and timed separately: the CLI spends the same work writing schedule.csv and
trajectory.csv. Prints one line per run and the median overhead in percent.
"""
import argparse
import statistics
import time

import thrustsched as ts


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenario", nargs="?", default="data/scenarios/geo_week_anzel4.json")
    ap.add_argument("--threads", type=int, default=None, help="CBC threads (default: the scenario's)")
    ap.add_argument("--repeat", type=int, default=1)
    a = ap.parse_args()
    scn = ts.Scenario.load(a.scenario)
    rows = []
    for k in range(a.repeat):
        t0 = time.perf_counter()
        res = ts.solve(scn, threads=a.threads)
        wall = time.perf_counter() - t0
        cpp = res.total_seconds
        t1 = time.perf_counter()
        n_sched = len(res.schedule)
        t2 = time.perf_counter()
        n_traj = len(res.trajectory)
        t3 = time.perf_counter()
        s = res.summary
        rows.append((wall - cpp) / cpp)
        print(f"run {k + 1}: {res.status}, {res.objective:.6g} m/s, gap {res.gap:.3g}; ts.solve {wall:.3f} s, "
              f"C++ {cpp:.3f} s (discretise {s['discretise_seconds']:.3f}, build {s['build_seconds']:.3f}, "
              f"solve {s['solve_seconds']:.3f}, check {s['check_seconds']:.3f}); Python layer "
              f"{wall - cpp:.3f} s = {100 * (wall - cpp) / cpp:.2f} %; DataFrames: schedule {t2 - t1:.3f} s "
              f"({n_sched} rows), trajectory {t3 - t2:.3f} s ({n_traj} rows)", flush=True)
    print(f"median Python-layer overhead: {100 * statistics.median(rows):.2f} % of the C++ call")


if __name__ == "__main__":
    main()
