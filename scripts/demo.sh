#!/usr/bin/env bash
# Runs the default scenario with the CLI once it is built; until then the quick-start example.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n "2,2p" "$0" | sed "s/^# \{0,1\}//"; exit 0 ;; esac
build=${1:-build}; scenario=${2:-data/scenarios/geo_week_anzel4.json}; out=${3:-out/demo}
if [ -x "$build/app/thrustsched" ] && [ -f "$scenario" ]; then
  exec "$build/app/thrustsched" solve "$scenario" --out "$out" --force
fi
exec "$build/tests/quickstart_example"
