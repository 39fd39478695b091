#!/usr/bin/env python3
"""Solves scenarios with two builds of the CLI and compares what the search
did, step by step: the check that a change of the search's code keeps its
behaviour.

    python3 scripts/compare_search_steps.py --baseline OLD_CLI [--candidate NEW_CLI]
        [--max-nodes 300] [--relative-gap G] [--out out/steps] SCENARIO...

Each scenario is solved by each build with one thread (CBC's parallel mode
is not deterministic), no time limit and a node limit on every MILP
(solver.max_nodes, default 300, which also caps each restricted MILP of the
search), so that both builds take the same path on any machine load;
--relative-gap overrides the scenario's gap. The two builds run side by side
(one process each). The summaries are compared with the timings, the
command line and the phase names at the head of each step left out: the
same steps, incumbents, bounds, status and objective print SAME; otherwise
the first differing step of each. Exit 0 when every scenario is SAME, 1
otherwise, 2 on bad arguments. --candidate defaults to this checkout's
build/app/thrustsched. Progress on stderr.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
TIMED_KEY = re.compile(r"seconds|_s$|command_line|wall|scenario_file")


def normalised_text(text):
    """A step log ("search: PHASE: step; PHASE: step; ...") without phase
    names and times. Any one-word head of a step goes, on both sides alike."""
    text = re.sub(r"(^|; )[a-z_]+: ", r"\1", re.sub(r"^search: ", "", text))
    return re.sub(r"[0-9.]+(e[-+]?[0-9]+)? ?s\b", "T s", text)


def normalised(value):
    if isinstance(value, dict):
        return {k: normalised(v) for k, v in value.items() if not TIMED_KEY.search(k)}
    if isinstance(value, list):
        return [normalised(v) for v in value]
    if isinstance(value, str):
        return normalised_text(value)
    return value


def absolute_files(value, folder):
    """Every relative "file" path in the scenario made absolute (an OPM file
    is relative to its scenario, which is written elsewhere)."""
    if isinstance(value, dict):
        for k, v in value.items():
            if k == "file" and isinstance(v, str) and not os.path.isabs(v):
                value[k] = os.path.join(folder, v)
            else:
                absolute_files(v, folder)
    elif isinstance(value, list):
        for v in value:
            absolute_files(v, folder)


def patched(scenario, out_dir, max_nodes, relative_gap):
    with open(scenario) as f:
        doc = json.load(f)
    absolute_files(doc, os.path.dirname(os.path.abspath(scenario)))
    solver = doc.setdefault("solver", {})
    solver["max_nodes"] = max_nodes
    solver["threads"] = 1
    solver.pop("time_limit_s", None)
    if relative_gap is not None:
        solver["relative_gap"] = relative_gap
    path = os.path.join(out_dir, os.path.basename(scenario))
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
    return path


def start(cli, scenario, out):
    cmd = [cli, "solve", scenario, "--out", out, "--threads", "1", "--no-diagnose", "--no-plots",
           "--no-report", "--quiet", "--force"]
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def first_difference(a, b):
    steps_a, steps_b = a.get("solver_detail", "").split("; "), b.get("solver_detail", "").split("; ")
    for k, (x, y) in enumerate(zip(steps_a, steps_b)):
        if x != y:
            return "step %d:\n    baseline:  %s\n    candidate: %s" % (k, x[:300], y[:300])
    if len(steps_a) != len(steps_b):
        return "%d steps against %d" % (len(steps_a), len(steps_b))
    keys = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
    return "fields " + ", ".join(keys)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--baseline", required=True)
    p.add_argument("--candidate", default=os.path.join(ROOT, "build/app/thrustsched"))
    p.add_argument("--max-nodes", type=int, default=300)
    p.add_argument("--relative-gap", type=float)
    p.add_argument("--out", default="out/steps")
    p.add_argument("scenarios", nargs="+")
    a = p.parse_args()
    for name, cli in (("--baseline", a.baseline), ("--candidate", a.candidate)):
        if not os.access(cli, os.X_OK):
            print("compare_search_steps: %s: no executable at %s" % (name, cli), file=sys.stderr)
            return 2
    if a.max_nodes < 0:
        print("compare_search_steps: --max-nodes must be >= 0, got %d" % a.max_nodes, file=sys.stderr)
        return 2
    os.makedirs(os.path.join(a.out, "scenarios"), exist_ok=True)
    t0, differing = time.time(), 0
    for k, scenario in enumerate(a.scenarios):
        name = os.path.splitext(os.path.basename(scenario))[0]
        path = patched(scenario, os.path.join(a.out, "scenarios"), a.max_nodes, a.relative_gap)
        runs = {b: start(cli, path, os.path.join(a.out, b, name))
                for b, cli in (("baseline", a.baseline), ("candidate", a.candidate))}
        codes = {b: (r.wait(), r.stderr.read()) for b, r in runs.items()}
        summaries = {}
        for b in runs:
            try:
                with open(os.path.join(a.out, b, name, "summary.json")) as f:
                    summaries[b] = normalised(json.load(f))
            except OSError:
                summaries[b] = {"error": "exit %d: %s" % (codes[b][0], codes[b][1].strip()[-300:])}
        same = summaries["baseline"] == summaries["candidate"] and "error" not in summaries["baseline"]
        differing += 0 if same else 1
        s = summaries["candidate"]
        failed = [b for b in runs if "error" in summaries[b]]
        print("%-48s %s  %d steps, %s, objective %s" %
              (name, "SAME" if same else ("FAILED" if failed else "DIFFERENT"),
               len(s.get("solver_detail", "").split("; ")), s.get("status"), s.get("objective")))
        for b in failed:
            print("  %s: %s" % (b, summaries[b]["error"]))
        if not same and not failed:
            print("  " + first_difference(summaries["baseline"], summaries["candidate"]))
        sys.stdout.flush()
        elapsed = time.time() - t0
        print("compare_search_steps: %d/%d scenarios, %.0f s, ETA %.0f s" %
              (k + 1, len(a.scenarios), elapsed, elapsed / (k + 1) * (len(a.scenarios) - k - 1)),
              file=sys.stderr)
    print("%d of %d scenarios the same" % (len(a.scenarios) - differing, len(a.scenarios)))
    return 0 if differing == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
