#!/usr/bin/env bash
# Installs the Debian packages thrustsched needs, only when some are missing.
# Uses apt-get when run as root, sudo otherwise (asking for the password when
# there is a terminal to ask on); fails clearly if it can do neither.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n "2,4p" "$0" | sed "s/^# \{0,1\}//"; exit 0 ;; esac

PACKAGES=(
  build-essential cmake pkgconf
  libeigen3-dev libboost-dev
  # orbit raising (transfer/): MINPACK for the shooting
  libcminpack-dev
  coinor-libcbc-dev coinor-libclp-dev coinor-libcgl-dev coinor-libosi-dev coinor-libcoinutils-dev
  nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  coinor-cbc glpk-utils python3-scipy gnuplot-nox
  # the Python package (python/) and its tests
  pybind11-dev python3-dev python3-numpy python3-pandas python3-matplotlib python3-pytest
  # `pip install .` into a virtual environment, offline (pyproject.toml, setup.py)
  python3-setuptools python3-wheel python3-pip python3-venv
  # campaigns (thrustsched-sweep) on Dask
  python3-distributed
  # the test that opens report.html in a real browser (headless)
  chromium
  # the format check of CI (scripts/check_format.sh)
  clang-format
  # the compiler cache of every build (scripts/setup.sh, .ci/run)
  ccache
)

# THRUSTSCHED_DEPS_PACKAGES (space-separated) replaces the list: used by the
# test of this script (tests/install/install_deps_test.sh).
if [ -n "${THRUSTSCHED_DEPS_PACKAGES:-}" ]; then
  read -r -a PACKAGES <<< "$THRUSTSCHED_DEPS_PACKAGES"
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} Debian packages present, nothing to install."
  exit 0
fi

echo "install-deps: installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  SUDO=(sudo)
elif command -v sudo >/dev/null 2>&1 && [ -t 0 ]; then
  echo "install-deps: sudo will ask for your password to run apt-get"
  SUDO=(sudo)
else
  echo "install-deps: error: not root, and sudo is unavailable (not installed, or it needs a" \
       "password and there is no terminal to ask on)." >&2
  echo "install-deps: install these packages by hand: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
if ! "${SUDO[@]}" apt-get install -y --no-install-recommends "${missing[@]}"; then
  "${SUDO[@]}" apt-get update
  "${SUDO[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi
