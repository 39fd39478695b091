#!/usr/bin/env bash
# The hard-weeks suite (data/scenarios/hard/<run>_wNN.json) is what
# scripts/extract_year_weeks.py writes from the year run they were taken
# from, data/scenarios/hard/source/<run>/ (its checkpoint.json and year.json;
# docs/year/<run>/ holds the latest run, which may be another), byte for byte, and each recorded schedule
# passes `thrustsched check` on its week with the recorded consumption (state,
# history and failures carried over faithfully).
#   tests/install/hard_weeks_test.sh SOURCE_DIR CLI
set -euo pipefail
src=${1:?usage: hard_weeks_test.sh SOURCE_DIR CLI}
cli=${2:?usage: hard_weeks_test.sh SOURCE_DIR CLI}
cd "$src"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
runs=$(ls data/scenarios/hard/*_w[0-9][0-9].json | sed 's|.*/\(.*\)_w[0-9][0-9]\.json|\1|' | sort -u)
for run in $runs; do
  weeks=$(ls data/scenarios/hard/"$run"_w[0-9][0-9].json | sed 's/.*_w0*\([0-9]*\)\.json/\1/' | paste -sd,)
  python3 scripts/extract_year_weeks.py --run "data/scenarios/hard/source/$run" \
    --scenario "data/scenarios/year/$run.json" --cycles "$weeks" --out "$out" --verify --cli "$cli"
  for f in data/scenarios/hard/"$run"_w[0-9][0-9].json; do
    if ! cmp -s "$f" "$out/$(basename "$f")"; then
      echo "FAIL $f differs from the script's output (see data/scenarios/README.md, hard weeks)"
      status=1
    fi
  done
done
exit $status
