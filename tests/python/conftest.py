"""Shared helpers of the Python package's tests (run by ctest: tests/CMakeLists.txt).

    THRUSTSCHED_SOURCE_DIR   the source tree (default: two levels up)
    THRUSTSCHED_CLI          the thrustsched executable (the independent reference)
    PYTHONPATH               build/python (the built package)

Every test runs in the source tree (its paths are data/scenarios/...); the
examples run in a temporary folder (they find the data with ts.data_path).
"""
import json
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("THRUSTSCHED_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
SCENARIOS = SOURCE_DIR / "data" / "scenarios"
TEST_DATA = SOURCE_DIR / "tests" / "app" / "data"
CLI = os.environ.get("THRUSTSCHED_CLI", str(SOURCE_DIR / "build" / "app" / "thrustsched"))

# Thesis Table 4.1 (Gazzino 2018): one 5-minute slot of one ideal thruster,
# F / m * 300 s, per day of the 1-day case; five slots for the 2-day case.
SLOT_M_S = 0.265 / 4850 * 300
TABLE41_2D_M_S = 0.0819588


@pytest.fixture(autouse=True)
def _in_source_tree(monkeypatch):
    monkeypatch.chdir(SOURCE_DIR)


def run_cli(*args, timeout=300):
    """Runs the thrustsched CLI; returns the CompletedProcess (text)."""
    if not os.path.exists(CLI):
        pytest.skip(f"the thrustsched CLI is not built ({CLI})")
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout,
                          cwd=SOURCE_DIR)


def run_python(script, *args, timeout=300, env=None, cwd=SOURCE_DIR):
    """Runs a Python script with this interpreter and PYTHONPATH (in the source tree unless cwd)."""
    e = dict(os.environ)
    e.update(env or {})
    return subprocess.run([sys.executable, str(script), *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd, env=e)


def read_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)
