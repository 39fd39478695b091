#!/usr/bin/env python3
"""How often do two co-located GEO satellites planned alone come within the keep-out cube?

Draws e/i separations (Soop, Handbook of Geostationary Orbits, ch. 7: parallel
e- and i-vector offsets +d/-d) for the pair of
data/scenarios/fleet/geo_colocation_pair_week.json, solves the fleet without
its keep-out (the members alone) with `thrustsched solve`, and prints the
closest approach of each draw (linear and nonlinear replay) and how many come
closer than the cube's half-size. With --keep-out, the fleet with its cube
instead: the fleet plan of each draw, its gap to the members-alone bound, the
time to the first plan (the start) and the closest approach.

    python3 scripts/colocation_alone.py --seed 2026 --draws 20 [--cli build/app/thrustsched]
    python3 scripts/colocation_alone.py --keep-out --time-limit 150 --seed 2027 --draws 8
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=2026)
    ap.add_argument("--draws", type=int, default=20)
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "app", "thrustsched"))
    ap.add_argument("--fleet", default=os.path.join(ROOT, "data", "scenarios", "fleet",
                                                    "geo_colocation_pair_week.json"))
    ap.add_argument("--keep-out", action="store_true",
                    help="solve the fleet with its keep-out cube (default: the members alone)")
    ap.add_argument("--time-limit", type=float, default=600.0,
                    help="the fleet solve's time limit (s), with --keep-out")
    args = ap.parse_args()
    if args.draws < 1:
        sys.exit("--draws: must be >= 1, got %d" % args.draws)
    if not args.time_limit > 0:
        sys.exit("--time-limit: must be > 0, got %g" % args.time_limit)
    rng = random.Random(args.seed)
    base = json.load(open(args.fleet))
    half_size = base["fleet"]["keep_out"]["half_size_m"]
    if args.keep_out:
        base["fleet"]["solver"]["time_limit_s"] = args.time_limit
    else:
        base["fleet"].pop("keep_out")
        base["fleet"]["solver"] = {"relative_gap": 0.01, "threads": 1}
    close = 0
    planned = []
    print("draw,de,di,direction_deg,status,objective,min_distance_m,min_box_distance_m,"
          "nonlinear_min_distance_m" +
          (",nonlinear_min_box_distance_m,bound,gap,start_s,in_turn,total_s" if args.keep_out else ""))
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(args.draws):
            de, di = rng.uniform(1.0e-4, 3.0e-4), rng.uniform(0.5e-4, 1.5e-4)
            phi = rng.uniform(0.0, 2.0 * math.pi)
            d = json.loads(json.dumps(base))
            for k, sign in ((0, 1.0), (1, -1.0)):
                d["fleet"]["members"][k]["scenario"]["initial_state"] = {"relative_equinoctial": [
                    0.0, sign * de / 2 * math.cos(phi), sign * de / 2 * math.sin(phi),
                    sign * di / 2 * math.cos(phi), sign * di / 2 * math.sin(phi), 0.0]}
            path, out = os.path.join(tmp, "draw%d.json" % i), os.path.join(tmp, "draw%d" % i)
            json.dump(d, open(path, "w"))
            run = subprocess.run([args.cli, "solve", path, "--out", out, "--no-plots"],
                                 capture_output=True, text=True)
            no_plan = args.keep_out and run.returncode == 4  # a result: no schedule found
            if no_plan:
                print("draw %d: no fleet plan: %s" % (i, json.load(open(os.path.join(
                    out, "summary.json")))["start"]["note"]), file=sys.stderr, flush=True)
            if run.returncode != 0 and not no_plan:
                sys.exit("draw %d: thrustsched exited %d: %s" % (i, run.returncode, run.stderr))
            s = json.load(open(os.path.join(out, "summary.json")))
            p = s["pairs"][0] if s["pairs"] else {}
            close += p.get("min_box_distance_m", float("inf")) < half_size
            line = "%d,%.4g,%.4g,%.1f,%s,%s,%s,%s,%s" % (
                i, de, di, math.degrees(phi), s["status"], s["objective"], p.get("min_distance_m"),
                p.get("min_box_distance_m"), p.get("nonlinear_min_distance_m"))
            if args.keep_out:
                start = s["start"] or {}
                in_turn = start.get("in_turn") or {}
                line += ",%s,%s,%s,%.1f,%s,%.1f" % (
                    p.get("nonlinear_min_box_distance_m"), s.get("best_bound"), s.get("gap"),
                    start.get("seconds", float("nan")), in_turn.get("found"),
                    s.get("total_seconds", float("nan")))
                if s["objective"] is not None:
                    planned.append(s)
            print(line, flush=True)
            print("draw %d of %d" % (i + 1, args.draws), file=sys.stderr, flush=True)
    if not args.keep_out:
        print("# %d of %d draws closer than the %g m cube" % (close, args.draws, half_size))
    else:
        print("# %d of %d draws with a fleet plan" % (len(planned), args.draws))


if __name__ == "__main__":
    main()
