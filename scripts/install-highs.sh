#!/usr/bin/env bash
# Installs HiGHS' WebAssembly build (npm package `highs`, pinned below) into
# .deps/highs for thrustsched-bench's external cross-check; nothing to do when
# that version is already there. Never fails the set-up: without node/npm or
# the registry, it says so and the bench reports "HiGHS skipped: <reason>".
#   scripts/install-highs.sh [DIR (default .deps/highs)]
set -uo pipefail
case "${1:-}" in -h|--help) sed -n "2,6p" "$0" | sed "s/^# \{0,1\}//"; exit 0 ;; esac
cd "$(dirname "$0")/.."
# The version the committed bench figures were measured with (it wraps HiGHS 1.15.1).
HIGHS_NPM_VERSION=1.15.3
dir=${1:-.deps/highs}
have=$(node -p "require('./$dir/node_modules/highs/package.json').version" 2>/dev/null || true)
if [ "$have" = "$HIGHS_NPM_VERSION" ]; then
  echo "install-highs: npm highs@$have present in $dir, nothing to install."
  exit 0
fi
if ! command -v node > /dev/null 2>&1 || ! command -v npm > /dev/null 2>&1; then
  echo "install-highs: node or npm not found: HiGHS is left out of the bench's cross-check."
  exit 0
fi
echo "install-highs: installing npm highs@$HIGHS_NPM_VERSION into $dir"
mkdir -p "$dir"
if ! timeout 300 npm install --prefix "$dir" --no-audit --no-fund --no-save --loglevel=error \
       "highs@$HIGHS_NPM_VERSION"; then
  echo "install-highs: npm install failed (registry unreachable?): HiGHS is left out of the" \
       "bench's cross-check."
fi
exit 0
