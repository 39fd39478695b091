#!/usr/bin/env bash
# Runs the thesis chapter 5 validation set of `thrustsched simulate` (one year
# of weekly cycles each) and prints our figures against the published ones
# (data/reference/thesis_chapter5.json). Results are written to OUT/<name>/
# (cycles.csv, year.json, plots); an interrupted run continues with --resume.
#
#   scripts/run_year_validation.sh                    # all six years, 2 at a time
#   scripts/run_year_validation.sh -j 1 year_anzel4_fixed
#   scripts/run_year_validation.sh --summary-only      # table from existing results
#
# Options: -j N (years run in parallel, default 2: each uses one core),
#          --cli PATH (default build/app/thrustsched), --out DIR (default out/year),
#          --fresh (start over: earlier results in OUT/<name> are replaced), --summary-only.
# Each year takes 0.5-2 hours on the 2-core development machine (see
# docs/year_results.md); the receding-horizon years solve twice as many cycles.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
cli="$root/build/app/thrustsched"
out="$root/out/year"
jobs=2
resume="--resume"
summary_only=0
names=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -j) jobs="$2"; shift 2 ;;
    --cli) cli="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --fresh) resume="--force"; shift ;;
    --summary-only) summary_only=1; shift ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
if [[ ${#names[@]} -eq 0 ]]; then
  names=(year_anzel4_fixed year_anzel4_fixed_margin year_ideal6_fixed year_anzel4_failed_ne
         year_anzel4_receding year_ideal6_receding)
fi

if [[ $summary_only -eq 0 ]]; then
  if [[ ! -x "$cli" ]]; then
    echo "no thrustsched binary at $cli (build it, or pass --cli PATH)" >&2
    exit 2
  fi
  mkdir -p "$out"
  running=0
  for name in "${names[@]}"; do
    scenario="$root/data/scenarios/year/$name.json"
    [[ -f "$scenario" ]] || { echo "no scenario $scenario" >&2; exit 2; }
    echo "[$(date +%T)] start $name -> $out/$name (log $out/$name.log)"
    # A run killed by a signal other than Ctrl-C/TERM (a solver crash) is
    # resumed: `simulate --resume` re-solves the cycle that died with CBC's
    # preprocessing off (its crash guard), at most 3 times per name.
    # shellcheck disable=SC2086
    ( "$cli" simulate "$scenario" --out "$out/$name" $resume > "$out/$name.log" 2>&1
      rc=$?
      for _ in 1 2 3; do
        if [[ $rc -le 128 || $rc -eq 130 || $rc -eq 143 ]]; then break; fi
        echo "[$(date +%T)] $name died (exit $rc, signal $((rc - 128))); resuming"
        "$cli" simulate "$scenario" --out "$out/$name" --resume >> "$out/$name.log" 2>&1
        rc=$?
      done
      echo "[$(date +%T)] $name finished, exit $rc" ) &
    running=$((running + 1))
    if [[ $running -ge $jobs ]]; then
      wait -n || true
      running=$((running - 1))
    fi
  done
  wait || true
fi

python3 - "$root" "$out" "${names[@]}" <<'PY'
import json, os, sys
root, out, names = sys.argv[1], sys.argv[2], sys.argv[3:]
ref = json.load(open(os.path.join(root, "data/reference/thesis_chapter5.json")))
published = {
    "year_anzel4_fixed": ref["results"]["nominal_anzel_fixed"]["l1_m_s"],
    "year_ideal6_fixed": ref["results"]["ideal6_fixed"]["l1_m_s"],
    "year_anzel4_receding": ref["results"]["anzel_receding"]["l1_m_s"],
    "year_ideal6_receding": ref["results"]["ideal6_receding"]["l1_m_s"],
    "year_anzel4_failed_ne": ref["results"]["failed_ne"]["l1_m_s"],
}
normal_ref = ref["normal_delta_v"]["value_m_s_per_year"]
hdr = ("scenario", "cycles", "L1 m/s", "thesis", "ratio", "normal dv", "thrust d",
       "outside s", "max|lat|", "max|lon|", "fallbacks", "solve med/p90/max s", "gap med/max %",
       "wall h", "cpu h")
print(" | ".join(hdr))
for name in names:
    path = os.path.join(out, name, "year.json")
    if not os.path.exists(path):
        print(f"{name} | (no year.json)")
        continue
    y = json.load(open(path))
    pub = published.get(name)
    # A ratio only for a whole year: a partial run's consumption is not comparable.
    ratio = y["consumption_l1_m_s"] / pub if pub and y.get("complete") else None
    s, g = y["solve_seconds"], y["gap"]
    fmt = lambda v, f="{:.3g}": "n/a" if v is None else f.format(v)
    print(" | ".join([
        name, f'{y["cycles"]}/{y["cycles_total"]}' + ("" if y.get("complete") else " (incomplete)"), f'{y["consumption_l1_m_s"]:.2f}',
        fmt(pub, "{:.1f}"), fmt(ratio, "{:.3f}"), f'{y["normal_delta_v_m_s"]:.2f}',
        f'{y["thrust_days"]["total"]:.2f}', f'{y["time_outside_window_s"]:.0f}',
        f'{y["max_abs_lat_deg"]:.4f}', f'{y["max_abs_lon_deg"]:.4f}', str(y["fallbacks"]["total"]),
        f'{fmt(s["median"])}/{fmt(s["p90"])}/{fmt(s["max"])}',
        f'{fmt(g["median"] and 100 * g["median"])}/{fmt(g["max"] and 100 * g["max"])}',
        f'{y["wall_seconds"] / 3600:.2f}', f'{y.get("cpu_seconds", 0) / 3600:.2f}']))
print(f"normal delta-v reference: {normal_ref} m/s per year (+-10 %), derived from Gazzino 2018 "
      "sec. 5.3.1 and Table 5.6 (data/reference/thesis_chapter5.json)")
PY
