#!/usr/bin/env python3
"""Writes GEO station-keeping weeks drawn at random, as scenario files, so that
the solver's speed can be measured on weeks nobody chose (the bench's section
"Random weeks" runs 50 of them from a seed of its own).

    python3 scripts/random_weeks.py --seed 7 --count 20 --out /tmp/weeks

Each week draws, independently and uniformly:
  - the station longitude in [-180, 180) deg and the epoch in 2025-2045 (UTC,
    whole minutes), full perturbation model (J2, tesserals, Sun, Moon, SRP);
  - the thruster preset (`anzel4`, the thesis's four, or `ideal6`, one per
    face) and, with probability 1/3, one of its thrusters failed (`disabled`);
  - the window half-width in [0.03, 0.1] deg (latitude and longitude);
  - the rules: minimum burn 5-15 min, rest of a thruster between its burns
    10-40 min, gap before another thruster's burn 5-15 min (whole minutes,
    applied on the grid as the solver rounds them), one thruster at a time;
  - the grid step, 5 or 10 min;
  - the initial state inside the window, as relative equinoctial elements
    (Gazzino 2018, eqs. (1.17), (1.20)): |e| <= w/5, |i| <= 3w/10 (latitude
    <= 2|i| <= 0.6 w), |dl| <= 0.6 w - 2|e| (longitude <= |dl| + 2|e|), da in
    +-300 m (a drift of at most 0.0038 deg/day), w the half-width in rad;
  - the end-of-week station-keeping set (`terminal`), with probability 1/2.
The solver stops at a 1 % gap or after 60 s (2 threads). The same seed and
count write the same files; `weeks.csv` in the output folder lists the draws
(weeks an earlier run left in the folder are removed first).
Exit 2 on a bad option (naming it).
"""
import argparse
import csv
import datetime
import json
import math
import os
import random
import sys

PRESETS = {
    "anzel4": ["NE", "SE", "NW", "SW"],
    "ideal6": ["+R", "+T", "+N", "-R", "-T", "-N"],
}
# The thesis spacecraft and Anzel layout (Gazzino 2018, sec. 5.1).
SPACECRAFT = {"mass_kg": 4850, "isp_s": 2005, "thrust_n": 0.265}
ANZEL_ANGLES = {"theta_deg": 63.64, "alpha_deg": 7.03}
FIRST_EPOCH = datetime.datetime(2025, 1, 1, tzinfo=datetime.timezone.utc)
LAST_EPOCH = datetime.datetime(2045, 12, 31, tzinfo=datetime.timezone.utc)
WEEK_S = 7 * 86400


def draw_week(rng, seed, k):
    """One week's scenario and its row of weeks.csv."""
    longitude = round(rng.uniform(-180.0, 180.0), 2)
    minutes = rng.randrange(int((LAST_EPOCH - FIRST_EPOCH).total_seconds() // 60))
    epoch = FIRST_EPOCH + datetime.timedelta(minutes=minutes)
    preset = rng.choice(sorted(PRESETS))
    failed = rng.choice(PRESETS[preset]) if rng.random() < 1.0 / 3.0 else None
    half_width_deg = round(rng.uniform(0.03, 0.1), 4)
    min_burn_min = rng.randint(5, 15)
    rest_min = rng.randint(10, 40)
    gap_other_min = rng.randint(5, 15)
    step_s = rng.choice([300, 600])
    w = math.radians(half_width_deg)
    e, e_angle = rng.uniform(0.0, 0.2 * w), rng.uniform(0.0, 2.0 * math.pi)
    i, i_angle = rng.uniform(0.0, 0.3 * w), rng.uniform(0.0, 2.0 * math.pi)
    dl = rng.uniform(-1.0, 1.0) * (0.6 * w - 2.0 * e)
    da_m = rng.uniform(-300.0, 300.0)
    state = [round(da_m, 3), e * math.cos(e_angle), e * math.sin(e_angle),
             i * math.cos(i_angle), i * math.sin(i_angle), dl]
    state[1:] = [float("%.6e" % v) for v in state[1:]]
    end_set = rng.random() < 0.5

    name = "rw_%d_%03d_%s%s" % (seed, k, preset, "_failed" if failed else "")
    thrusters = {"preset": preset}
    if preset == "anzel4":
        thrusters.update(ANZEL_ANGLES)
    scenario = {
        "name": name,
        "description": (
            "A GEO week drawn at random by scripts/random_weeks.py (seed %d, week %d): "
            "%.2f deg E from %s, %s thrusters%s, +-%g deg window, rules %d/%d/%d min, "
            "%d-min grid, %s." % (
                seed, k, longitude, epoch.strftime("%Y-%m-%dT%H:%MZ"), preset,
                " (%s failed)" % failed if failed else "", half_width_deg, min_burn_min,
                rest_min, gap_other_min, step_s // 60,
                "end-of-week station-keeping set" if end_set else "no end-of-week set")),
        "model": {
            "type": "geo",
            "station_longitude_deg": longitude,
            "epoch": epoch.strftime("%Y-%m-%dT%H:%M:%SZ"),
            "perturbations": ["j2", "tesseral", "sun", "moon", "srp"],
            "area_to_mass_m2_kg": 0.0227,
        },
        "spacecraft": dict(SPACECRAFT, thrusters=thrusters, disabled=[failed] if failed else []),
        "initial_state": {"relative_equinoctial": state},
        "horizon": {"duration_s": WEEK_S, "step_s": step_s},
        "window": {"half_width_deg": half_width_deg, "enforce_from_s": 0},
        "operations": {"max_simultaneous": 1, "min_burn_s": 60 * min_burn_min,
                       "min_off_same_s": 60 * rest_min, "min_gap_other_s": 60 * gap_other_min},
        "objective": "l1",
        "discretisation": {"scheme": "exact_zoh"},
        "solver": {"time_limit_s": 60, "relative_gap": 0.01, "threads": 2},
    }
    if end_set:
        scenario["terminal"] = {"type": "station_keeping"}
    row = {"name": name, "longitude_deg": longitude, "epoch": scenario["model"]["epoch"],
           "preset": preset, "failed": failed or "", "half_width_deg": half_width_deg,
           "min_burn_min": min_burn_min, "rest_min": rest_min, "gap_other_min": gap_other_min,
           "step_min": step_s // 60, "end_set": int(end_set),
           "da_m": state[0], "ex": state[1], "ey": state[2], "ix": state[3], "iy": state[4],
           "dl_rad": state[5]}
    return scenario, row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, required=True, help="seed of the draws")
    parser.add_argument("--count", type=int, required=True, help="number of weeks (>= 1)")
    parser.add_argument("--out", required=True, help="output folder (created)")
    try:
        args = parser.parse_args()
    except SystemExit as e:
        sys.exit(2 if e.code else 0)
    if args.count < 1:
        print("random_weeks.py: --count: must be >= 1, got %d" % args.count, file=sys.stderr)
        sys.exit(2)
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        print("random_weeks.py: --out: %s exists and is not a folder" % args.out, file=sys.stderr)
        sys.exit(2)
    os.makedirs(args.out, exist_ok=True)
    # The folder holds one draw: weeks an earlier run wrote there go first.
    for old in os.listdir(args.out):
        if old.startswith("rw_") and old.endswith(".json"):
            os.remove(os.path.join(args.out, old))
    rng = random.Random(args.seed)
    rows = []
    for k in range(args.count):
        scenario, row = draw_week(rng, args.seed, k)
        with open(os.path.join(args.out, scenario["name"] + ".json"), "w") as f:
            f.write(json.dumps(scenario, indent=2) + "\n")
        rows.append(row)
    with open(os.path.join(args.out, "weeks.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote %d weeks (seed %d) to %s" % (args.count, args.seed, args.out))


if __name__ == "__main__":
    main()
