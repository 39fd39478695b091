#!/usr/bin/env bash
# Every script in scripts/ answers --help (exit 0, some text) and changes
# nothing when given it: no file under data/ or scripts/ is written (none is
# newer than a marker made before) and their contents are the same.
#   tests/install/scripts_help_test.sh SOURCE_DIR
set -euo pipefail
src=${1:?usage: scripts_help_test.sh SOURCE_DIR}
cd "$src"
sum() { find data scripts -type f -print0 | sort -z | xargs -0 sha256sum | sha256sum; }
before=$(sum)
marker=$(mktemp)
trap 'rm -f "$marker"' EXIT
sleep 1  # file times have a resolution; anything written from now on is newer
status=0
for s in scripts/*; do
  case "$s" in
    *.py) out=$(python3 "$s" --help 2>&1) || { echo "FAIL $s --help exited $?"; status=1; continue; } ;;
    *.sh) out=$(bash "$s" --help 2>&1) || { echo "FAIL $s --help exited $?"; status=1; continue; } ;;
    *) continue ;;
  esac
  if [ -z "$out" ]; then echo "FAIL $s --help printed nothing"; status=1; fi
  echo "ok   $s --help ($(printf '%s\n' "$out" | wc -l) lines)"
done
after=$(sum)
if [ "$before" != "$after" ]; then echo "FAIL a --help changed files under data/ or scripts/"; status=1; fi
written=$(find data scripts -type f -newer "$marker")
if [ -n "$written" ]; then echo "FAIL a --help wrote: $written"; status=1; fi
exit $status
