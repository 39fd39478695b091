"""ts.solve on scenarios, against the thesis tables and the CLI (the C++ result).

    pytest tests/python/test_solve.py
"""
import math

import numpy as np
import pandas as pd
import pytest

import thrustsched as ts
from conftest import SCENARIOS, SLOT_M_S, TABLE41_2D_M_S, TEST_DATA, read_json, run_cli


def test_table41_one_day_is_one_five_minute_slot():
    res = ts.solve(ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json"))
    assert res.status == "optimal"
    assert res.objective == pytest.approx(SLOT_M_S, rel=1e-9)  # 0.265 N / 4850 kg x 300 s
    assert res.gap == pytest.approx(0.0, abs=1e-6)
    assert len(res.schedule) == 1
    assert res.schedule["duration_s"].iloc[0] == 300
    assert res.check.operational_ok and res.check.passed
    assert res.consumption_l1_m_s == pytest.approx(SLOT_M_S, rel=1e-9)


def test_table41_two_days_equals_the_cli(tmp_path):
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_2d.json")
    res = ts.solve(scn, threads=1)
    cli = run_cli("solve", SCENARIOS / "hcw_table41_2d.json", "--out", tmp_path / "cli", "--no-plots",
                  "--threads", "1")
    assert cli.returncode == 0, cli.stderr
    summary = read_json(tmp_path / "cli" / "summary.json")

    assert res.status == summary["status"] == "optimal"
    assert res.objective == pytest.approx(TABLE41_2D_M_S, abs=5e-8)  # thesis Table 4.1, 2 days
    assert res.objective == summary["objective"]                      # bit for bit: same C++ path
    assert res.best_bound == summary["best_bound"]
    for key in ("n_burns", "consumption_l1_m_s", "delta_v_m_s", "propellant_kg", "n_binaries", "n_rows",
                "n_nonzeros", "burns", "effective_rules", "final_drift_term_m"):
        assert res.summary[key] == summary[key], key
    assert res.summary["check"]["passed"] == summary["check"]["passed"] is True

    # The DataFrames are the CLI's files.
    cli_schedule = pd.read_csv(tmp_path / "cli" / "schedule.csv")
    pd.testing.assert_frame_equal(res.schedule, cli_schedule)
    cli_traj = pd.read_csv(tmp_path / "cli" / "trajectory.csv")
    assert list(res.trajectory.columns) == list(cli_traj.columns)
    pd.testing.assert_frame_equal(res.trajectory, cli_traj)
    # Discrete states at the nodes: the final drift term 2x + vy/n of the summary.
    n = 7.2921159e-5
    xf = res.states[-1]
    assert res.states.shape == (577, 6)
    assert 2 * xf[0] + xf[4] / n == pytest.approx(summary["final_drift_term_m"], rel=1e-12)
    assert res.pattern.shape == (6, 576) and res.pattern.sum() == 5  # five 5-min slots


def test_dict_access_edits_the_problem():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_2d.json")
    scn["horizon"]["duration_s"] = 86400          # the 2-day file made a 1-day one
    res = ts.solve(scn)
    assert res.objective == pytest.approx(SLOT_M_S, rel=1e-9)
    d = scn.to_dict()
    d["name"] = "from_dict"
    assert ts.solve(ts.Scenario.from_dict(d)).objective == pytest.approx(SLOT_M_S, rel=1e-9)


def test_geo_schedule_has_utc_times_and_the_nonlinear_replay():
    res = ts.solve(ts.Scenario.load(TEST_DATA / "geo_day_small.json"))
    assert res.status in ("optimal", "feasible") and res.has_schedule
    s = res.schedule
    assert list(s.columns) == ["thruster", "start_s", "end_s", "duration_s", "start_utc", "end_utc",
                               "dir_r", "dir_t", "dir_n", "delta_v_m_s"]
    epoch = pd.Timestamp("2034-01-01T00:00:00Z")
    assert ((s["start_utc"] - epoch).dt.total_seconds() == s["start_s"]).all()
    assert res.check.nonlinear_checked
    t = res.trajectory
    assert {"utc", "lin_lat_deg", "lin_dlon_deg", "lat_deg", "dlon_deg"} <= set(t.columns)
    assert t["lat_deg"].abs().max() == pytest.approx(res.check.max_abs_lat_deg, rel=1e-9)


def test_infeasible_is_a_status_not_an_exception():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    scn["window"]["half_width_m"] = 2000            # the 1 km start drifts 3 km a day...
    scn["operations"]["max_burns_per_thruster"] = 0  # ...and no thruster may fire
    res = ts.solve(scn, search=False, threads=1)
    assert res.status == "infeasible"
    assert not res.has_schedule and res.check is None
    assert math.isnan(res.objective)
    assert len(res.schedule) == 0


def test_no_solution_is_a_status_not_an_exception():
    # As the CLI's test (tests/app/stop_and_output_test.cc): a time limit far
    # below what the infeasibility proof takes (tens of seconds).
    res = ts.solve(TEST_DATA / "hcw_10km_infeasible_1d.json", time_limit_s=0.05, diagnosis_time_limit_s=0)
    assert res.status == "no_solution"
    assert not res.has_schedule and res.check is None


def test_progress_callback_receives_dicts_in_this_thread():
    seen = []
    res = ts.solve(SCENARIOS / "hcw_table41_1d.json", progress=seen.append, progress_interval_s=0.05)
    assert res.status == "optimal"
    assert seen, "no progress event"
    assert all(isinstance(d, dict) and "phase" in d for d in seen)
    inc = [d for d in seen if d.get("new_incumbent")]
    assert inc and inc[-1]["objective"] == pytest.approx(res.objective, rel=1e-9)


def test_solve_keywords_are_validated():
    scn = SCENARIOS / "hcw_table41_1d.json"
    with pytest.raises(ValueError, match="threads: must be in"):
        ts.solve(scn, threads=0)
    with pytest.raises(ValueError, match="time_limit_s: must be > 0"):
        ts.solve(scn, time_limit_s=-1)
    with pytest.raises(ValueError, match="scheme"):
        ts.solve(scn, scheme="rk5")


def test_plot_returns_the_three_figures():
    import matplotlib
    import matplotlib.pyplot as plt

    res = ts.solve(SCENARIOS / "hcw_table41_1d.json")
    figs = res.plot()
    assert set(figs) == {"window", "timeline", "outputs"}
    assert all(isinstance(f, matplotlib.figure.Figure) for f in figs.values())
    # The timeline holds the one burn, from its start (h).
    bars = [c for c in figs["timeline"].axes[0].collections]
    assert len(bars) == 1
    assert np.allclose(bars[0].get_paths()[0].vertices[:, 0].min(), res.schedule["start_s"].iloc[0] / 3600)
    for f in figs.values():
        plt.close(f)


def test_min_time_objective_matches_the_closed_form_and_the_cli(tmp_path):
    # Rest to rest over 1 m with |u| = 4 m/s^2: T* = 2 sqrt(1 / 4) = 1 s, fuel U T* = 4 m/s.
    path = SCENARIOS / "min_time_double_integrator.json"
    res = ts.solve(ts.Scenario.load(path))
    assert res.status == "optimal"
    m = res.min_time
    assert m is not None
    assert m["arrival_time_s"] == pytest.approx(1.0, abs=1e-9)
    assert m["arrival_bound_s"] == pytest.approx(1.0, abs=1e-9)
    assert m["verified"] is True
    assert res.objective == pytest.approx(4.0, abs=1e-6)
    cli = run_cli("solve", path, "--out", tmp_path / "cli", "--no-plots", "--no-report")
    assert cli.returncode == 0, cli.stderr
    summary = read_json(tmp_path / "cli" / "summary.json")
    assert summary["min_time"]["arrival_time_s"] == m["arrival_time_s"]
    assert summary["objective"] == res.objective
    assert ts.solve(ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")).min_time is None


def test_fleet_swap_matches_the_derived_optimum_and_the_cli(tmp_path):
    # Swap with a keep-out: 2 m/s for the swap + 1 m/s for b's step aside (tests/app/fleet_cli_test.cc).
    path = SCENARIOS / "fleet" / "di_swap.json"
    res = ts.fleet(path)
    assert res.status == "optimal"
    assert res.objective == pytest.approx(3.0, abs=1e-9)
    assert list(res.pairs.columns) == ["member_a", "member_b", "min_distance_m", "min_box_distance_m", "time_s",
                                       "planned_min_distance_m", "planned_min_box_distance_m",
                                       "keep_out_half_size_m"]
    assert res.pairs["planned_min_box_distance_m"].iloc[0] >= 0.5 - 1e-9
    assert set(res.schedules) == {"a", "b"}
    assert list(res.schedules["b"].columns)[:4] == ["thruster", "start_s", "end_s", "duration_s"]
    cli = run_cli("solve", path, "--out", tmp_path / "cli")
    assert cli.returncode == 0, cli.stderr
    summary = read_json(tmp_path / "cli" / "summary.json")
    assert summary["objective"] == res.summary["objective"]
    assert summary["members"] == res.summary["members"]
    # A dict with a member by path needs its folder; bad fields name the field.
    spread = read_json(SCENARIOS / "fleet" / "di_spread.json")
    assert ts.fleet(spread, base_dir=SCENARIOS / "fleet").objective == pytest.approx(1.002, abs=1e-9)
    spread["fleet"]["balance"] = "fair"
    with pytest.raises(ts.ScenarioError, match="fleet.balance"):
        ts.fleet(spread, base_dir=SCENARIOS / "fleet")
