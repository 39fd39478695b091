#!/usr/bin/env bash
# Test of scripts/install-deps.sh (the set-up step of `make demo` / `make test`):
#  1. everything present: exits 0 at once and says so, installs nothing;
#  2. a package missing, not root and no usable sudo (no terminal to ask a
#     password on): exits 1 with a clear message naming the package.
# Part 2 needs root (to become an unprivileged user with setpriv); skipped otherwise.
set -uo pipefail
script="$1/scripts/install-deps.sh"
fail=0

out=$(bash "$script" 2>&1); rc=$?
echo "$out"
if [ $rc -ne 0 ] || ! grep -q "nothing to install" <<< "$out"; then
  echo "FAIL: with every package present, expected exit 0 and 'nothing to install' (rc $rc)"
  fail=1
fi

if [ "$(id -u)" -eq 0 ] && command -v setpriv > /dev/null; then
  # The unprivileged user may not be able to read the checkout (a clone in a
  # mode-700 directory such as `mktemp -d`): it runs a readable copy.
  copy_dir=$(mktemp -d)
  trap 'rm -rf "$copy_dir"' EXIT
  chmod 755 "$copy_dir"
  install -m 644 "$script" "$copy_dir/install-deps.sh"
  out=$(THRUSTSCHED_DEPS_PACKAGES="thrustsched-no-such-package" \
        setpriv --reuid=65534 --regid=65534 --clear-groups bash "$copy_dir/install-deps.sh" \
        < /dev/null 2>&1); rc=$?
  echo "$out"
  if [ $rc -ne 1 ] || ! grep -q "install these packages by hand: thrustsched-no-such-package" <<< "$out" \
     || ! grep -q "error: not root" <<< "$out"; then
    echo "FAIL: as an unprivileged user without sudo, expected exit 1 naming the package (rc $rc)"
    fail=1
  fi
else
  echo "part 2 skipped (needs root and setpriv)"
fi
[ $fail -eq 0 ] && echo "install-deps test: PASSED"
exit $fail
