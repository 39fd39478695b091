#!/usr/bin/env python3
"""Runs thrustsched-bench cases by two builds side by side, in the same run,
and prints each case's medians and their ratio.

    python3 scripts/compare_releases.py --baseline REV_OR_BENCH [--candidate BENCH]
        --cases GLOB [--rounds 3] [--out out/compare] [--time-limit S] [--threads N]
        [--data-dir DIR] [--disable-phases A,B] [--labels BASE,CANDIDATE]

--baseline is a git revision of this repository (built once, Release, in
build-releases/<commit>/, a detached worktree) or the path of a
thrustsched-bench executable; --candidate defaults to this checkout's
build/benchmarks/thrustsched-bench. Every case the candidate's --list matches
with GLOB and the baseline also has is run once per round by each build, one
after the other, the order alternating between rounds, so both see the same
machine load. Both read the candidate's data directory unless --data-dir says
otherwise. --time-limit, --threads and --disable-phases are handed to both
(the last to the candidate only: an older build may not have phases).

Writes OUT/rows.csv (every run's bench row, with columns build and round) and
OUT/comparison.md, and prints the table: per case the status and objective of
each build (a difference is flagged), the median of solve_s and of
time_to_1pct_s, and the ratio baseline / candidate (above 1: the candidate is
faster), with the geometric mean of the ratios. Progress and an ETA go to
stderr.
"""
import argparse
import csv
import fnmatch
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
MEASURES = ("solve_s", "time_to_1pct_s")


def fail(message):
    print("compare_releases: " + message, file=sys.stderr)
    sys.exit(2)


def build_revision(revision):
    """The bench of a git revision, built once in build-releases/<commit>/."""
    try:
        commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--verify", revision + "^{commit}"],
                                check=True, capture_output=True, text=True).stdout.strip()
    except subprocess.CalledProcessError:
        fail("--baseline: neither an executable nor a git revision: " + revision)
    tree = os.path.join(ROOT, "build-releases", commit[:12])
    bench = os.path.join(tree, "build", "benchmarks", "thrustsched-bench")
    if os.access(bench, os.X_OK):
        return bench, commit[:12]
    if not os.path.isdir(tree):
        subprocess.run(["git", "-C", ROOT, "worktree", "add", "--detach", tree, commit], check=True)
    launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []
    print("compare_releases: building the bench of %s in %s" % (commit[:12], tree), file=sys.stderr)
    subprocess.run(["cmake", "-S", tree, "-B", os.path.join(tree, "build"),
                    "-DCMAKE_BUILD_TYPE=Release"] + launcher, check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", os.path.join(tree, "build"), "-j", "2", "--target",
                    "thrustsched-bench"], check=True, stdout=subprocess.DEVNULL)
    return bench, commit[:12]


def label_of(bench):
    """The short commit of the checkout a bench executable was built in, else its path."""
    tree = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(bench))))
    r = subprocess.run(["git", "-C", tree, "rev-parse", "--short=12", "HEAD"],
                       capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 else bench


def case_ids(bench, pattern):
    r = subprocess.run([bench, "--list"], capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s --list failed: %s" % (bench, r.stderr.strip()))
    ids = [line.split()[0] for line in r.stdout.splitlines() if line.strip()]
    return [i for i in ids if fnmatch.fnmatchcase(i, pattern)]


def run_case(bench, case, out, common_args):
    if os.path.isdir(out):
        shutil.rmtree(out)
    cmd = [bench, "--cases", case, "--repeats", "1", "--out", out] + common_args
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    rows_file = os.path.join(out, "results.csv")
    if r.returncode != 0 or not os.path.exists(rows_file):
        return [{"case_id": case, "status": "bench_failed", "note": r.stderr.strip()[-300:]}]
    return [row for row in csv.DictReader(open(rows_file)) if row.get("case_id") == case]


def median(values):
    numbers = [float(v) for v in values if v not in ("", None)]
    return statistics.median(numbers) if numbers else None


def summarise(rows, builds, cases):
    """One table line per case: statuses, objectives, medians and ratios."""
    lines = ["| case | %s status, objective | %s status, objective | same | %s |" %
             (builds[0], builds[1], " | ".join("%s median (s) %s / %s, ratio" %
                                               (m, builds[0], builds[1]) for m in MEASURES)),
             "|---|---|---|---|" + "---|" * len(MEASURES)]
    ratios = {m: [] for m in MEASURES}
    for case in cases:
        by = {b: [r for r in rows if r["build"] == b and r["case_id"] == case] for b in builds}
        outcome = {b: sorted({(r.get("status", ""), r.get("objective", "")) for r in by[b]})
                   for b in builds}
        cells = []
        for m in MEASURES:
            a, c = median(r.get(m) for r in by[builds[0]]), median(r.get(m) for r in by[builds[1]])
            if a is not None and c is not None and a > 0 and c > 0:
                ratios[m].append(a / c)
                cells.append("%.2f / %.2f, %.2fx" % (a, c, a / c))
            else:
                cells.append("%s / %s" % (a, c))
        same = "yes" if outcome[builds[0]] == outcome[builds[1]] else "**no**"
        text = {b: "; ".join("%s %s" % o for o in outcome[b]) for b in builds}
        lines.append("| %s | %s | %s | %s | %s |" % (case, text[builds[0]], text[builds[1]], same,
                                                     " | ".join(cells)))
    geo = ["%s %.3fx over %d cases" % (m, math.exp(statistics.mean(math.log(x) for x in v)), len(v))
           for m, v in ratios.items() if v]
    lines.append("")
    lines.append("Geometric mean of the ratios %s / %s: %s." % (builds[0], builds[1],
                                                               "; ".join(geo) or "none"))
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--baseline", required=True)
    p.add_argument("--candidate", default=os.path.join(ROOT, "build/benchmarks/thrustsched-bench"))
    p.add_argument("--cases", required=True)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--out", default="out/compare")
    p.add_argument("--time-limit")
    p.add_argument("--threads")
    p.add_argument("--data-dir", default=os.path.join(ROOT, "data"))
    p.add_argument("--disable-phases")
    p.add_argument("--labels", help="BASE,CANDIDATE: the builds' names in the table "
                   "(default: their checkouts' short commits)")
    a = p.parse_args()
    if a.rounds < 1:
        fail("--rounds must be >= 1, got %d" % a.rounds)
    if not os.access(a.candidate, os.X_OK):
        fail("--candidate: no executable at " + a.candidate + " (build it: make, or cmake --build build)")
    if os.path.isfile(a.baseline) and os.access(a.baseline, os.X_OK):
        baseline, base_label = a.baseline, label_of(a.baseline)
    else:
        baseline, base_label = build_revision(a.baseline)
    cand_label = label_of(a.candidate)
    if a.labels:
        if len(a.labels.split(",")) != 2 or "" in a.labels.split(","):
            fail("--labels must be BASE,CANDIDATE, got " + a.labels)
        base_label, cand_label = a.labels.split(",")
    if cand_label == base_label:
        cand_label += "-candidate"
    builds = [base_label, cand_label]
    benches = {base_label: baseline, cand_label: a.candidate}
    cases = [c for c in case_ids(a.candidate, a.cases) if c in set(case_ids(baseline, a.cases))]
    if not cases:
        fail("--cases: no case of both builds matches " + a.cases)
    common = ["--data-dir", a.data_dir]
    for flag, value in (("--time-limit", a.time_limit), ("--threads", a.threads)):
        if value is not None:
            common += [flag, value]
    extra = {base_label: [], cand_label: ["--disable-phases", a.disable_phases] if a.disable_phases else []}
    os.makedirs(a.out, exist_ok=True)
    rows, total, done, start = [], a.rounds * len(cases) * 2, 0, time.time()
    for round_index in range(a.rounds):
        order = builds if round_index % 2 == 0 else builds[::-1]
        for case in cases:
            for build in order:
                out = os.path.join(a.out, "runs", "r%d" % round_index, build.replace("/", "_"), case)
                for row in run_case(benches[build], case, out, common + extra[build]):
                    row.update(build=build, round=round_index)
                    rows.append(row)
                done += 1
                elapsed = time.time() - start
                print("compare_releases: %d/%d runs, %.0f s, ETA %.0f s (%s by %s)" %
                      (done, total, elapsed, elapsed / done * (total - done), case, build),
                      file=sys.stderr)
    columns = ["build", "round"] + sorted({k for r in rows for k in r} - {"build", "round"})
    with open(os.path.join(a.out, "rows.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    table = summarise(rows, builds, cases)
    header = ("Cases `%s`, %d round(s), each build once per round, order alternating; "
              "baseline %s, candidate %s.\n\n" % (a.cases, a.rounds, base_label, cand_label))
    with open(os.path.join(a.out, "comparison.md"), "w") as f:
        f.write(header + table)
    print(header + table)


if __name__ == "__main__":
    main()
