#!/usr/bin/env bash
# The hard-weeks suite (data/scenarios/hard/) is what scripts/extract_year_weeks.py
# writes from the shipped six-thruster year checkpoint, byte for byte, and each
# recorded schedule passes `thrustsched check` on its week with the recorded
# consumption (state, history and failures carried over faithfully).
#   tests/install/hard_weeks_test.sh SOURCE_DIR CLI
set -euo pipefail
src=${1:?usage: hard_weeks_test.sh SOURCE_DIR CLI}
cli=${2:?usage: hard_weeks_test.sh SOURCE_DIR CLI}
cd "$src"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
weeks=$(ls data/scenarios/hard/year_ideal6_fixed_w*.json | sed 's/.*_w0*\([0-9]*\)\.json/\1/' | paste -sd,)
python3 scripts/extract_year_weeks.py --run docs/year/year_ideal6_fixed \
  --scenario data/scenarios/year/year_ideal6_fixed.json --cycles "$weeks" --out "$out" \
  --verify --cli "$cli"
status=0
for f in data/scenarios/hard/year_ideal6_fixed_w*.json; do
  if ! cmp -s "$f" "$out/$(basename "$f")"; then
    echo "FAIL $f differs from the script's output (regenerate it, see data/scenarios/README.md)"
    status=1
  fi
done
exit $status
