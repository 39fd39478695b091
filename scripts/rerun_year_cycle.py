#!/usr/bin/env python3
"""Re-solve one cycle of a finished year run from the state it started from.

Cuts a year checkpoint (thrustsched simulate's checkpoint.json) back to the end
of cycle K-1, optionally changes fields of the scenario, and runs
`thrustsched simulate --resume --cycles K` on it: cycle K is solved again from
exactly the true state and thruster history it had in the recorded run (with
unchanged settings this reproduces the recorded cycle bit for bit). Prints the
recorded and the new cycle side by side, with every attempt of the new one.

Example (docs/year_results.md, six thrusters, week 39 with the retry option):
  scripts/rerun_year_cycle.py --checkpoint docs/year/year_ideal6_fixed/checkpoint.json \\
      --scenario data/scenarios/year/year_ideal6_fixed.json --cycle 39 \\
      --set long_horizon.cycle_retry_without_preprocessing=true --out /tmp/w39
"""
import argparse
import json
import os
import re
import subprocess
import sys


def fail(msg):
    sys.exit(f"rerun_year_cycle: {msg}")


def read_json(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        fail(f"{what} {path}: {e.strerror}")
    except json.JSONDecodeError as e:
        fail(f"{what} {path}: not JSON ({e})")


def set_field(scenario, assignment):
    if "=" not in assignment:
        fail(f"--set {assignment!r}: expected path.to.field=JSON_VALUE")
    path, value = assignment.split("=", 1)
    try:
        value = json.loads(value)
    except json.JSONDecodeError as e:
        fail(f"--set {assignment!r}: the value is not JSON ({e})")
    keys = path.split(".")
    node = scenario
    for key in keys[:-1]:
        if not isinstance(node.get(key), dict):
            fail(f"--set {assignment!r}: scenario has no object {key!r}")
        node = node[key]
    node[keys[-1]] = value


def cut(checkpoint, cycle, fingerprint):
    """The checkpoint as it was after cycle `cycle - 1` (1-based cycle)."""
    done = checkpoint["cycles"][: cycle - 1]
    if not done:
        fail("--cycle must be >= 2 (cycle 1 starts from the scenario itself: run it directly)")
    last = [None] * len(checkpoint["last_burn_end_s"])
    for rec in done:
        for thruster, _start, end in rec["burns"]:
            last[thruster] = end if last[thruster] is None else max(last[thruster], end)
    out = dict(checkpoint)
    out.update(cycles=done, next_cycle=cycle - 1, eci=done[-1]["eci_end"],
               time_s=done[-1]["applied_end_s"], last_burn_end_s=last, fingerprint=fingerprint)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--checkpoint", required=True, help="checkpoint.json of the recorded run")
    ap.add_argument("--scenario", required=True, help="the scenario of the recorded run")
    ap.add_argument("--cycle", type=int, required=True, help="cycle to re-solve (1-based)")
    ap.add_argument("--set", action="append", default=[], metavar="PATH=JSON",
                    help="change a scenario field, e.g. long_horizon.cycle_max_nodes=500")
    ap.add_argument("--out", required=True, help="output directory (replaced)")
    ap.add_argument("--cli", default=os.path.join(os.path.dirname(__file__), "..", "build", "app",
                                                  "thrustsched"))
    a = ap.parse_args()

    checkpoint = read_json(a.checkpoint, "--checkpoint")
    if not isinstance(checkpoint, dict) or checkpoint.get("format") != "thrustsched-year-checkpoint-1":
        fail(f"{a.checkpoint}: not a thrustsched year checkpoint")
    if not 1 <= a.cycle <= len(checkpoint["cycles"]):
        fail(f"--cycle {a.cycle}: the checkpoint has cycles 1..{len(checkpoint['cycles'])}")
    recorded = checkpoint["cycles"][a.cycle - 1]
    scenario = read_json(a.scenario, "--scenario")
    if not isinstance(scenario, dict):
        fail(f"--scenario {a.scenario}: not a JSON object")
    for s in a.set:
        set_field(scenario, s)
    if not os.access(a.cli, os.X_OK):
        fail(f"--cli {a.cli}: not an executable (build first: make demo, or pass --cli)")

    os.makedirs(a.out, exist_ok=True)
    for name in ("checkpoint.json", "in_progress.json"):
        if os.path.exists(os.path.join(a.out, name)):
            os.remove(os.path.join(a.out, name))
    scenario_path = os.path.join(a.out, "scenario.json")
    with open(scenario_path, "w") as f:
        json.dump(scenario, f, indent=1)
    ckpt_path = os.path.join(a.out, "checkpoint.json")
    cmd = [a.cli, "simulate", scenario_path, "--out", a.out, "--resume", "--cycles",
           str(a.cycle), "--no-plots"]

    # The checkpoint must carry the scenario's fingerprint; the CLI names it
    # when it refuses a checkpoint written with another one.
    with open(ckpt_path, "w") as f:
        json.dump(cut(checkpoint, a.cycle, "0" * 16), f)
    probe = subprocess.run(cmd, capture_output=True, text=True)
    m = re.search(r"this scenario ([0-9a-f]+)", probe.stderr)
    if not m:
        fail("could not learn the scenario's fingerprint; the CLI said:\n" + probe.stderr)
    with open(ckpt_path, "w") as f:
        json.dump(cut(checkpoint, a.cycle, m.group(1)), f)

    print(" ".join(cmd), file=sys.stderr)
    run = subprocess.run(cmd, stdout=subprocess.DEVNULL)
    if run.returncode != 0:
        fail(f"thrustsched simulate exited {run.returncode}")
    with open(ckpt_path) as f:
        new = json.load(f)["cycles"][a.cycle - 1]

    def line(label, c):
        return (f"{label:9} L1 {c['consumption_l1_m_s']:.4f} m/s, objective {c['objective']:.6g}, "
                f"gap {100 * c['gap']:.2f} %, fallback {c['fallback']}, "
                f"outside the box {c['time_outside_window_s']:.0f} s, rules ok {c['rules_ok']}, "
                f"solve {c['solve_seconds']:.0f} s")
    print(f"cycle {a.cycle}")
    print(line("recorded", recorded))
    print(line("re-solved", new))
    for att in new["attempts"]:
        print(f"  attempt {att['level']:>13} {att['status']:>17} {att['solve_seconds']:7.1f} s  "
              f"{att['detail']}")


if __name__ == "__main__":
    main()
