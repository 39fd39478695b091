#!/usr/bin/env python3
"""Solves scenario files with the thrustsched CLI and prints one table row per
file (status, objective, gap, published figure, times, check verdict).

    python3 scripts/run_scenarios.py [--cli build/app/thrustsched] [--time-limit S]
                                     [--wall-timeout S] [--out out/scenarios] [FILES...]

Without FILES, every data/scenarios/*.json is run. --time-limit overrides the
scenarios' solver limits; --wall-timeout kills a run that overruns (CBC does
not always honour its limit while solving the root LP). Published figures come
from data/reference/*.json via each file's name. The check column adds the
conjunction verification (risk and Monte Carlo) of scenarios that have one.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def published():
    ref = {}
    t = json.load(open(os.path.join(ROOT, "data/reference/thesis_tables.json")))
    for row in t["table_4_1"]["rows"]:
        ref["hcw_table41_%dd" % row["horizon_days"]] = row["consumption_m_s"]
    for row in t["table_4_2"]["rows"]:
        ref["hcw_table42_t1_%dd" % row["t1_days"]] = row["consumption_m_s"]
    ref["hcw_periodic_no_thrust"] = 0.0
    ref["hcw_10km_infeasible"] = "infeasible"
    s = json.load(open(os.path.join(ROOT, "data/reference/serra_rendezvous.json")))
    for case in s["cases"]:
        name = os.path.splitext(os.path.basename(case["scenario_file"]))[0]
        ref[name] = case.get("optimum_m_s", case.get("grid_optimum_derived", case.get("optimum")))
    c = json.load(open(os.path.join(ROOT, "data/reference/serra_avoidance.json")))
    for case in c["cases"]:  # Serra 2015 Tables 4.2 and 4.5, mm/s
        name = os.path.splitext(os.path.basename(case["scenario_file"]))[0]
        ref[name] = case["risk_selection"]["cost_mm_s"] * 1e-3
    return ref


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=os.path.join(ROOT, "build/app/thrustsched"))
    ap.add_argument("--time-limit", type=float)
    ap.add_argument("--wall-timeout", type=float, default=900)
    ap.add_argument("--out", default=os.path.join(ROOT, "out/scenarios"))
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    files = a.files or sorted(glob.glob(os.path.join(ROOT, "data/scenarios/*.json")))
    ref = published()
    print("| scenario | exit | status | objective | published | gap | burns | build s | solve s | total s | check |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for f in files:
        name = os.path.splitext(os.path.basename(f))[0]
        out = os.path.join(a.out, name)
        cmd = [a.cli, "solve", f, "--out", out, "--quiet"]
        if a.time_limit:
            cmd += ["--time-limit", str(a.time_limit)]
        t0 = time.time()
        try:
            rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                timeout=a.wall_timeout).returncode
        except subprocess.TimeoutExpired:
            print("| %s | killed | (wall timeout %.0f s) | | %s | | | | | %.0f | |"
                  % (name, a.wall_timeout, ref.get(name, ""), time.time() - t0))
            sys.stdout.flush()
            continue
        try:
            s = json.load(open(os.path.join(out, "summary.json")))
        except (OSError, ValueError):
            print("| %s | %d | (no summary) | | | | | | | %.0f | |" % (name, rc, time.time() - t0))
            continue

        def num(v, fmt="%.6g"):
            return fmt % v if isinstance(v, (int, float)) and v is not None else "-"
        chk = s.get("check") or {}
        verdict = ("pass" if chk.get("passed") else "FAIL") if chk else "-"
        if chk and s.get("model") == "geo" and chk.get("max_window_violation_nonlinear_deg") is not None:
            verdict += " (nl %.2g deg)" % chk["max_window_violation_nonlinear_deg"]
        conj = (s.get("conjunction") or {}).get("verification")
        if conj:  # computed risk and Monte Carlo of the "conjunction" section
            verdict += "; conjunction " + ("pass" if conj.get("passed") else "FAIL")
        n = s.get("n_impulses", s.get("n_burns"))
        print("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, rc, s["status"], num(s.get("objective")), ref.get(name, ""),
            num(s.get("gap"), "%.3g"), n, num(s.get("build_seconds"), "%.1f"),
            num(s.get("solve_seconds"), "%.1f"), num(s.get("total_seconds"), "%.1f"), verdict))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
