"""ts.simulate: the year loop, against `thrustsched simulate` on the same scenario.

    pytest tests/python/test_simulate.py
"""
import pandas as pd
import pytest

import thrustsched as ts
from conftest import SCENARIOS, SOURCE_DIR, read_json, run_cli, run_python

YEAR_TEST = SCENARIOS / "year" / "year_test_4cycles.json"  # 1-day cycles (the test scenario of the CLI)
TIMING = ["solve_s", "first_solution_s", "wall_s", "cpu_s"]


def test_example_run_with_resume_equals_the_cli(tmp_path):
    # The example (examples/python/year.py) makes the Python run: one cycle,
    # then the rest resumed from the checkpoint; run from a temporary folder
    # (it finds its scenario with ts.data_path) with a relative out folder.
    r = run_python(SOURCE_DIR / "examples" / "python" / "year.py", "py", cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "total " in r.stdout and "over 2 days" in r.stdout
    assert "cycle 2 (2/2)" in r.stderr or "2/2" in r.stderr  # progress: plain lines or tqdm
    # The CLI on the same scenario, uninterrupted.
    scn = ts.Scenario.load(YEAR_TEST)
    scn["horizon"]["step_s"] = 600
    scn["long_horizon"]["duration_s"] = 2 * 86400
    scn.save(tmp_path / "year.json")
    cli = run_cli("simulate", tmp_path / "year.json", "--out", tmp_path / "cli", "--no-plots")
    assert cli.returncode == 0, cli.stderr
    py_cycles = pd.read_csv(tmp_path / "py" / "cycles.csv").drop(columns=TIMING)
    cli_cycles = pd.read_csv(tmp_path / "cli" / "cycles.csv").drop(columns=TIMING)
    assert len(py_cycles) == 2
    pd.testing.assert_frame_equal(py_cycles, cli_cycles)
    for f in ("cycle_001.csv", "cycle_002.csv"):
        assert (tmp_path / "py" / "cycles" / f).read_text() == (tmp_path / "cli" / "cycles" / f).read_text()
    year = read_json(tmp_path / "cli" / "year.json")
    run = ts.simulate(scn, out=tmp_path / "py", plots=False, progress=False)  # all done: nothing to solve
    assert run.year["consumption_l1_m_s"] == year["consumption_l1_m_s"] > 0
    assert not run.interrupted and run.exit_code == 0
    # A callable gets nothing when no cycle runs; a folder holding a run,
    # neither resumed nor forced, is refused as by the CLI.
    with pytest.raises(ValueError, match="--resume|--force|earlier run"):
        ts.simulate(scn, out=tmp_path / "py", resume=False, plots=False, progress=False)


def test_progress_callable_gets_one_dict_per_cycle(tmp_path):
    scn = ts.Scenario.load(YEAR_TEST)
    scn["horizon"]["step_s"] = 600
    scn["long_horizon"]["duration_s"] = 86400
    seen = []
    run = ts.simulate(scn, out=tmp_path / "one", plots=False, progress=seen.append)
    assert [(d["cycle"], d["done"], d["target"], d["status"]) for d in seen] == [(1, 1, 1, "optimal")]
    assert seen[0]["consumption_l1_m_s"] == pytest.approx(run.year["consumption_l1_m_s"], rel=1e-12)


def test_simulate_needs_a_long_horizon_section():
    with pytest.raises(ValueError, match=r"scenario\.long_horizon: missing"):
        ts.simulate(ts.Scenario.load(SCENARIOS / "geo_week_anzel4.json"), cycles=1, out="/nonexistent/x",
                    progress=False)

