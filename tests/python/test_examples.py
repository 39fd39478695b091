"""Every example of examples/python runs and prints what it promises, from
a temporary folder (neither the source tree nor the examples' folder): the
examples find the shipped scenarios through ts.data_path, not the working
directory.

    pytest tests/python/test_examples.py
"""
import re

import pytest

from conftest import SLOT_M_S, SOURCE_DIR, TABLE41_2D_M_S, run_python

EXAMPLES = SOURCE_DIR / "examples" / "python"


def _run(cwd, name, *args):
    r = run_python(EXAMPLES / name, *args, cwd=cwd)
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_every_example_has_a_test():
    tested = {"quickstart.py", "results_and_plots.py", "errors.py", "own_dynamics.py", "add_constraints.py",
              "threads.py", "year.py"}
    assert {p.name for p in EXAMPLES.glob("*.py")} == tested


def test_quickstart(tmp_path):
    out = _run(tmp_path, "quickstart.py")
    # The line README.md quotes ("It prints ..."), with the Table 4.1 value.
    assert out.splitlines()[0] == f"optimal: {TABLE41_2D_M_S:g} m/s, gap 0, 1 burns; checker ok"
    assert (tmp_path / "two_days.mps").read_text().startswith("*")  # default: in the working directory


def test_results_and_plots(tmp_path):
    out = _run(tmp_path, "results_and_plots.py", "plots")
    tmp_path = tmp_path / "plots"
    assert "status='optimal'" in out and "objective=0.016391753" in out
    assert "FAILED" in out and "min_burn" in out
    for name in ("window.png", "timeline.png", "outputs.png", "one_day.lp"):
        assert (tmp_path / name).stat().st_size > 0, name


def test_errors(tmp_path):
    out = _run(tmp_path, "errors.py")
    assert "bad input: scenario.horizon.step_s: 7 s does not divide" in out
    assert "status: infeasible | schedule rows: 0 | check: None" in out


def test_own_dynamics(tmp_path):
    out = _run(tmp_path, "own_dynamics.py")
    m = re.search(r"arrays: optimal ([0-9.]+) m/s; scenario: optimal ([0-9.]+) m/s", out)
    assert m and m.group(1) == m.group(2)
    assert float(m.group(1)) == pytest.approx(SLOT_M_S, rel=1e-8)


def test_add_constraints(tmp_path):
    out = _run(tmp_path, "add_constraints.py")
    lines = out.splitlines()
    thr, start, end, duration = lines[0].split()[2:]
    assert float(end) - float(start) == float(duration) == 300  # Table 4.1: one slot
    thr, start, end, _ = lines[1].split()[3:]
    assert not (7200 <= float(start) < 14400 or 7200 < float(end) <= 14400)  # outside the pass
    m = re.search(r"optimal, ([0-9.]+) m/s, y\(12 h\) = (-?[0-9.]+) m, checker ok", out)
    assert m and float(m.group(2)) >= -10000.0 - 1e-6
    assert float(m.group(1)) > SLOT_M_S  # the keep-out row costs propellant
    assert "knapsack: optimal 7.0 [1.0, 1.0, 0.0]" in out


def test_threads(tmp_path):
    out = _run(tmp_path, "threads.py")
    assert f"half width 36800 m: optimal, {TABLE41_2D_M_S:g} m/s" in out
    assert "half width 25000 m: optimal" in out
