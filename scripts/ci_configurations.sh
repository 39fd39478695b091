#!/usr/bin/env bash
# Every documented CMake configuration (README.md, "Build options") is
# configured, and the ones that compile code the default build does not are
# built (and their tests run), so that no documented option rots.
#
#   bash scripts/ci_configurations.sh [BUILD_ROOT] [JOBS]     (default: build-configs 2)
#
# The default configuration (everything on) is `make test`'s build; the
# sanitizer build (with -Werror) is .ci/run's last stage. Here:
#   no-cbc     -DTHRUSTSCHED_WITH_CBC=OFF: the core libraries and the tests
#              that solve nothing (no CLI, Python package or bench tool),
#              built in BUILD_ROOT-no-cbc and its tests run. The compiler
#              flags are the default build's and the folder is as deep as
#              build/, so through ccache its libraries are the default
#              build's objects: what it checks is that they link and pass
#              without the CBC backend.
#   no-app     -DTHRUSTSCHED_BUILD_APP=OFF: configured (its code is a subset
#              of the default build's).
#   no-bench   -DTHRUSTSCHED_BUILD_BENCHMARKS=OFF: configured.
#   no-python  -DTHRUSTSCHED_BUILD_PYTHON=OFF: configured.
set -euo pipefail
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then
  sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
cd "$(dirname "$0")/.."
root=${1:-build-configs}
jobs=${2:-2}
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
configure() {  # configure NAME DIR [CMAKE ARGS...]
  local name=$1 dir=$2; shift 2
  echo "configurations: $name ($*)"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" > "$root/$name.configure.log" 2>&1 ||
    { cat "$root/$name.configure.log"; echo "configurations: $name does not configure"; exit 1; }
}
mkdir -p "$root"
configure no-app "$root/no-app" -DTHRUSTSCHED_BUILD_APP=OFF
configure no-bench "$root/no-bench" -DTHRUSTSCHED_BUILD_BENCHMARKS=OFF
configure no-python "$root/no-python" -DTHRUSTSCHED_BUILD_PYTHON=OFF
configure no-cbc "$root-no-cbc" -DTHRUSTSCHED_WITH_CBC=OFF
cmake --build "$root-no-cbc" -j "$jobs"
ctest --test-dir "$root-no-cbc" --output-on-failure -j "$jobs" -LE "nosan|slow"
echo "configurations: all configured; no-cbc built and tested"
