#!/usr/bin/env python3
"""Write cycles of a finished year run as stand-alone `solve` scenarios.

Reads a `thrustsched simulate` output folder (checkpoint.json and year.json)
and, for each cycle K asked for, writes a scenario that `thrustsched solve`
(and thrustsched-bench) solve as the MILP the year loop built for that cycle:
the year scenario without its long_horizon section, the horizon moved to the
cycle's start, the true state the run handed the cycle (model variables, full
precision), each thruster's time off since its last burn (history), the
failures active in the cycle as forced-off windows, and the end-of-cycle
station-keeping sets of the run. The recorded cycle (consumption, gap,
fallback, solve time) is quoted in the description.

--verify replays each cycle's recorded schedule through `thrustsched check`
on the written scenario: the consumption must match the recorded one and the
operational rules (history and forced-off windows included) must hold.

Example (the six-thruster hard weeks of data/scenarios/hard/):
  scripts/extract_year_weeks.py --run docs/year/year_ideal6_fixed \\
      --scenario data/scenarios/year/year_ideal6_fixed.json \\
      --cycles 14,16,33,39,47,52 --out data/scenarios/hard --verify
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile


def fail(msg):
    sys.exit(f"extract_year_weeks: {msg}")


def read_json(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        fail(f"{what} {path}: {e.strerror}")
    except json.JSONDecodeError as e:
        fail(f"{what} {path}: not JSON ({e})")


def parse_cycles(text, count):
    cycles = []
    for part in text.split(","):
        try:
            k = int(part)
        except ValueError:
            fail(f"--cycles {text!r}: {part!r} is not an integer")
        if not 1 <= k <= count:
            fail(f"--cycles {text!r}: the run has cycles 1..{count}, got {k}")
        cycles.append(k)
    return cycles


def thruster_names(scenario, cli):
    """Thruster names in index order, as the CLI reads the scenario."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "s.json")
        s = {k: v for k, v in scenario.items() if k != "long_horizon"}
        with open(path, "w") as f:
            json.dump(s, f)
        out = subprocess.run([cli, "validate", path], capture_output=True, text=True)
    # "model  geo, 2016 intervals of 300 s from t = 0 s, 6 thrusters (+R, +T, ...)"
    for line in out.stdout.splitlines():
        if line.startswith("model") and "thrusters (" in line:
            inside = line.split("thrusters (", 1)[1].rsplit(")", 1)[0]
            return [w.strip() for w in inside.split(",")]
    fail("could not read the thruster names from `thrustsched validate`:\n" + out.stdout + out.stderr)


def week_scenario(scenario, year, checkpoint, k, names):
    rec = checkpoint["cycles"][k - 1]
    settings = year["settings"]
    start = rec["start_s"]
    end = rec["prediction_end_s"]
    s = {key: value for key, value in scenario.items() if key != "long_horizon"}
    s["name"] = f"{scenario['name']}_w{k:02d}"
    s["description"] = (
        f"Cycle {k} of the year run {year['scenario']} ({year['mode']} horizons), started from "
        f"the state and thruster history that run handed it. Recorded: L1 "
        f"{rec['consumption_l1_m_s']:.4f} m/s, objective {rec['objective']:.6g}, best bound "
        f"{rec['best_bound']:.6g}, gap {100 * rec['gap']:.1f} %, fallback {rec['fallback']}, "
        f"solve {rec['solve_seconds']:.0f} s. Written by scripts/extract_year_weeks.py.")
    s["horizon"] = {"start_s": start, "duration_s": end - start, "step_s": settings["step_s"]}
    s["initial_state"] = {"state": rec["initial_state"]}
    last = [None] * len(names)
    for earlier in checkpoint["cycles"][: k - 1]:
        for thruster, _t0, t1 in earlier["burns"]:
            last[thruster] = t1 if last[thruster] is None else max(last[thruster], t1)
    history = {names[i]: {"off_for_s": max(0.0, start - e)} for i, e in enumerate(last)
               if e is not None}
    if history:
        s["history"] = history
    forced = []
    for f in year.get("failures", []):
        until = f["until_s"] if f["until_s"] is not None else math.inf
        if until <= start or f["from_s"] >= end:
            continue
        for name in f["switched_off"]:
            forced.append({"thruster": name, "start_s": max(f["from_s"], start),
                           "end_s": min(until, end)})
    if forced:
        s["forced_off"] = forced
    t = settings["terminal"]
    if t.get("type") == "station_keeping":
        s["terminal"] = {"type": "station_keeping", "facets_out_of_plane": t["facets"],
                         "facets_cone_plus": t["facets"], "facets_cone_minus": t["facets"],
                         "lookahead_s": t["lookahead_s"], "margin": t["margin"]}
    s.setdefault("operations", {})["allow_burn_across_end"] = False
    return s


def verify(path, rec, names, cli):
    """The recorded schedule through `thrustsched check` on the written scenario."""
    with tempfile.TemporaryDirectory() as tmp:
        sched = os.path.join(tmp, "schedule.csv")
        with open(sched, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["thruster", "start_s", "end_s", "duration_s"])
            for thruster, t0, t1 in rec["burns"]:
                w.writerow([names[thruster], repr(t0), repr(t1), repr(t1 - t0)])
        out = subprocess.run([cli, "check", path, sched, "--out", os.path.join(tmp, "o"),
                              "--no-plots"], capture_output=True, text=True)
        report_path = os.path.join(tmp, "o", "check.json")
        if not os.path.exists(report_path):
            fail(f"{path}: thrustsched check wrote no check.json:\n{out.stderr}")
        report = read_json(report_path, "check.json")
    l1 = report.get("consumption_l1_m_s")
    if l1 is None or abs(l1 - rec["consumption_l1_m_s"]) > 1e-9 * max(1.0, l1):
        fail(f"{path}: the recorded schedule costs {l1} here, {rec['consumption_l1_m_s']} in the run")
    if not report.get("operational_ok", False):
        fail(f"{path}: the recorded schedule breaks the rules here: {report.get('findings')}")
    return l1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--run", required=True, help="thrustsched simulate output folder "
                    "(checkpoint.json and year.json)")
    ap.add_argument("--scenario", help="the run's scenario (default: year.json's scenario_file)")
    ap.add_argument("--cycles", required=True, help="comma-separated cycles (1-based), e.g. 14,16")
    ap.add_argument("--out", required=True, help="folder for the scenario files (created)")
    ap.add_argument("--verify", action="store_true",
                    help="check each recorded schedule on its written scenario")
    ap.add_argument("--cli", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                                  "build", "app", "thrustsched"))
    a = ap.parse_args()

    checkpoint = read_json(os.path.join(a.run, "checkpoint.json"), "--run")
    if checkpoint.get("format") != "thrustsched-year-checkpoint-1":
        fail(f"{a.run}/checkpoint.json: not a thrustsched year checkpoint")
    year = read_json(os.path.join(a.run, "year.json"), "--run")
    scenario = read_json(a.scenario or year["scenario_file"], "--scenario")
    if not os.access(a.cli, os.X_OK):
        fail(f"--cli {a.cli}: not an executable (build first: make demo, or pass --cli)")
    names = thruster_names(scenario, a.cli)
    os.makedirs(a.out, exist_ok=True)
    for k in parse_cycles(a.cycles, len(checkpoint["cycles"])):
        s = week_scenario(scenario, year, checkpoint, k, names)
        path = os.path.join(a.out, s["name"] + ".json")
        with open(path, "w") as f:
            json.dump(s, f, indent=1)
            f.write("\n")
        line = f"{path}: cycle {k}"
        if a.verify:
            l1 = verify(path, checkpoint["cycles"][k - 1], names, a.cli)
            line += f", recorded schedule re-checked: L1 {l1:.6f} m/s, rules ok"
        print(line)


if __name__ == "__main__":
    main()
