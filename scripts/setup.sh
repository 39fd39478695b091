#!/usr/bin/env bash
# The set-up shared by `make demo` and `make test`: install the missing Debian
# packages (scripts/install-deps.sh) and HiGHS for the bench's cross-check
# (scripts/install-highs.sh, never fatal), configure a Release build and build it
# (through ccache when it is installed: a rebuild compiles only what changed).
#   scripts/setup.sh [BUILD_DIR (default build)] [JOBS (default 2)]
set -euo pipefail
case "${1:-}" in -h|--help) sed -n "2,6p" "$0" | sed "s/^# \{0,1\}//"; exit 0 ;; esac
cd "$(dirname "$0")/.."
build=${1:-build}
jobs=${2:-2}
bash scripts/install-deps.sh
bash scripts/install-highs.sh
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
cmake --build "$build" -j "$jobs"
