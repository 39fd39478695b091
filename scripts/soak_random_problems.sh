#!/usr/bin/env bash
# Long-run soak of the schedule search: N small random problems (HCW and
# double-integrator models, 1-3 thrusters of random geometry, random rules,
# windows, horizons of 6-40 slots, random initial states, some infeasible),
# each solved by the search and compared with its exact optimum (exhaustive
# enumeration of the on-off patterns where they are few, plain CBC on the
# whole MILP otherwise); the checker passes every returned schedule. The
# generator is the one of tests/transcription/random_problems_test
# (tests/transcription/random_problems.h), whose few hundred seeds run in
# every `ctest`. Prints each disagreement (seed and case) and a summary;
# exit 0 when none, 1 otherwise.
#
#   scripts/soak_random_problems.sh --soak 100000                # seeds 1..100000, at nice 19
#   scripts/soak_random_problems.sh --soak 5000 --first-seed 100001
#
# Options: --soak N (cases, required), --first-seed S (default 1),
#          --max-slots M (longest horizon, 6-40, default 40), --verbose (each
#          case and its answer), --build DIR (default build; the random_soak
#          target is built there).
set -euo pipefail
case "${1:-}" in -h|--help|"") sed -n "2,19p" "$0" | sed "s/^# \{0,1\}//"; exit 0 ;; esac
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --soak|--first-seed|--max-slots) args+=("$1" "${2:?$1 needs a value}"); shift 2 ;;
    --verbose) args+=("$1"); shift ;;
    --build) build="${2:?--build needs a directory}"; shift 2 ;;
    *) echo "soak_random_problems.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
cmake --build "$build" --target random_soak -j 1 > /dev/null
exec nice -n 19 "$build/tests/transcription/random_soak" "${args[@]}"
