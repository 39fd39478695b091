#!/usr/bin/env python3
"""How often do two co-located GEO satellites planned alone come within the keep-out cube?

Draws e/i separations (Soop, Handbook of Geostationary Orbits, ch. 7: parallel
e- and i-vector offsets +d/-d) for the pair of
data/scenarios/fleet/geo_colocation_pair_week.json, solves the fleet without
its keep-out (the members alone) with `thrustsched solve`, and prints the
closest approach of each draw (linear and nonlinear replay) and how many come
closer than the cube's half-size.

    python3 scripts/colocation_alone.py --seed 2026 --draws 20 [--cli build/app/thrustsched]
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
    args = ap.parse_args()
    if args.draws < 1:
        sys.exit("--draws: must be >= 1, got %d" % args.draws)
    rng = random.Random(args.seed)
    base = json.load(open(args.fleet))
    half_size = base["fleet"].pop("keep_out")["half_size_m"]
    base["fleet"]["solver"] = {"relative_gap": 0.01, "threads": 1}
    close = 0
    print("draw,de,di,direction_deg,status,objective,min_distance_m,min_box_distance_m,"
          "nonlinear_min_distance_m")
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
            if run.returncode != 0:
                sys.exit("draw %d: thrustsched exited %d: %s" % (i, run.returncode, run.stderr))
            s = json.load(open(os.path.join(out, "summary.json")))
            p = s["pairs"][0]
            close += p["min_box_distance_m"] < half_size
            print("%d,%.4g,%.4g,%.1f,%s,%.6f,%.1f,%.1f,%s" % (
                i, de, di, math.degrees(phi), s["status"], s["objective"], p["min_distance_m"],
                p["min_box_distance_m"], p.get("nonlinear_min_distance_m")), flush=True)
            print("draw %d of %d" % (i + 1, args.draws), file=sys.stderr, flush=True)
    print("# %d of %d draws closer than the %g m cube" % (close, args.draws, half_size))


if __name__ == "__main__":
    main()
