#!/usr/bin/env bash
# The C++ sources follow .clang-format (Google style, 100 columns): lists the
# files that do not and exits 1, or formats them in place with --fix.
#
#   bash scripts/check_format.sh          # CI: check only
#   bash scripts/check_format.sh --fix    # format the tree
#
# Needs clang-format (Debian package clang-format; checked with version 14).
set -euo pipefail
if [[ "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
  exit 0
fi
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check_format: clang-format not found"; exit 1; }
# Tracked files and new ones not yet added (what the next commit would hold).
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.cc' '*.h' |
                     grep -v '^tests/install/consumer/')
if [[ "${1:-}" == "--fix" ]]; then
  clang-format -i "${files[@]}"
  echo "check_format: formatted ${#files[@]} files"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done
if ((${#bad[@]})); then
  printf 'check_format: not formatted (bash scripts/check_format.sh --fix):\n'
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
