#!/usr/bin/env bash
# Coverage-guided fuzzing of the input parsers (libFuzzer harnesses of tests/fuzz/).
#   scripts/fuzz.sh SECONDS [HARNESS...]   (default: every harness, one after the other)
# Configures and builds build-fuzz (clang, -DTHRUSTSCHED_FUZZ=ON) if needed, runs each
# harness SECONDS with -timeout=1 -rss_limit_mb=2048 on the work corpus out/fuzz/corpus/NAME
# (seeded from data/ and tests/fuzz/corpus/NAME), appends one line per run to
# out/fuzz/totals.csv and prints the totals per harness. Crash inputs go to out/fuzz/crashes/NAME/.
# FUZZ_TIMEOUT_S (default 1) replaces the 1-s wall-clock budget per input on a loaded machine;
# replay a timeout input on a quiet one (build-fuzz/tests/fuzz/fuzz_NAME FILE) to judge it.
set -euo pipefail
usage() { sed -n "2,9p" "$0" | sed "s/^# \{0,1\}//"; }
case "${1:-}" in -h|--help) usage; exit 0 ;; "") usage >&2; exit 2 ;; esac
cd "$(dirname "$0")/.."
seconds=$1
shift
timeout_s=${FUZZ_TIMEOUT_S:-1}
if ! [[ "$timeout_s" =~ ^[0-9]+$ ]] || [ "$timeout_s" -lt 1 ]; then
  echo "fuzz.sh: FUZZ_TIMEOUT_S must be a positive integer, got '$timeout_s'" >&2
  exit 2
fi
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "fuzz.sh: SECONDS must be a positive integer, got '$seconds'" >&2
  exit 2
fi
all=(scenario_text scenario_values opm oem mps mps_roundtrip solution schedule_csv impulses_csv
     checkpoint)
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=("${all[@]}")
for h in "${harnesses[@]}"; do
  [ -f "tests/fuzz/${h}_fuzz.cc" ] || { echo "fuzz.sh: unknown harness '$h' (${all[*]})" >&2; exit 2; }
done

build=build-fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
  launcher=()
  if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DTHRUSTSCHED_FUZZ=ON -DBUILD_TESTING=OFF -DTHRUSTSCHED_BUILD_BENCHMARKS=OFF \
    -DTHRUSTSCHED_BUILD_PYTHON=OFF "${launcher[@]}"
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
nice -n 10 cmake --build "$build" -j 2 --target "${targets[@]}"

# The shipped files each harness starts from (besides tests/fuzz/corpus/NAME).
seeds() {
  case "$1" in
    scenario_text) find data/scenarios -name '*.json' -size -16k ;;
    opm) find data -name '*.opm' ;;
    mps|mps_roundtrip) find data/golden -name '*.mps' ;;
    *) ;;
  esac
}

# Third-party leaks only (the file says which and why); UB reports with their stack.
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan_suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"
out=out/fuzz
mkdir -p "$out"
totals=$out/totals.csv
[ -f "$totals" ] || echo "harness,seconds,executions,cov,ft,crashes,date_utc" > "$totals"
for h in "${harnesses[@]}"; do
  corpus=$out/corpus/$h
  crashes=$out/crashes/$h
  mkdir -p "$corpus" "$crashes"
  cp -n tests/fuzz/corpus/"$h"/* "$corpus"/ 2> /dev/null || true
  while read -r f; do
    [ -n "$f" ] && cp -n "$f" "$corpus/seed_$(basename "$f")"
  done < <(seeds "$h")
  log=$out/$h.log
  echo "== $h: $seconds s (log $log)"
  # One process; a finding ends the run (its input is in $crashes).
  started=$SECONDS
  set +e
  nice -n 10 "$build/tests/fuzz/fuzz_$h" "$corpus" -max_total_time="$seconds" -timeout="$timeout_s" \
    -rss_limit_mb=2048 -malloc_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$crashes/" > "$log" 2>&1
  status=$?
  set -e
  ran=$((SECONDS - started))
  # libFuzzer's last status line: "#N  DONE|pulse|...  cov: C ft: F corp: ..."
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  execs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || true)
  [ -n "$execs" ] || execs=$(sed -E 's/^#([0-9]+).*/\1/' <<< "$last")
  cov=$(grep -oE 'cov: [0-9]+' <<< "$last" | grep -oE '[0-9]+' || echo 0)
  ft=$(grep -oE 'ft: [0-9]+' <<< "$last" | grep -oE '[0-9]+' || echo 0)
  found=0
  if [ "$status" -ne 0 ]; then
    found=1
    echo "   FINDING (exit $status): $(grep -E 'ERROR|SUMMARY|terminate|what\(\)' "$log" | head -3)"
    echo "   input: $(grep -oE "$crashes/[^ ]+" "$log" | tail -1)"
  fi
  echo "$h,$ran,${execs:-0},$cov,$ft,$found,$(date -u +%FT%TZ)" >> "$totals"
done

echo "totals per harness (all sessions, $totals):"
printf "%-16s %9s %12s %7s %7s %8s\n" harness seconds executions cov ft crashes
awk -F, 'NR > 1 { s[$1] += $2; e[$1] += $3; c[$1] += $6; if ($4 > cov[$1]) cov[$1] = $4;
                  if ($5 > ft[$1]) ft[$1] = $5 }
         END { for (h in s) printf "%-16s %9d %12d %7d %7d %8d\n", h, s[h], e[h], cov[h], ft[h],
                                   c[h] }' "$totals" | sort
