"""ts.transfer: orbit transfers from Python, against the published 60 N
minimum time (Caillau, Gergaud & Noailles 2003: 14.8004 h) and the CLI's
summary.json on the same scenario.

    pytest tests/python/test_transfer.py
"""
import copy
import json

import pandas as pd
import pytest

import thrustsched as ts
from conftest import SCENARIOS, read_json, run_cli

CAILLAU_60N = SCENARIOS / "transfer" / "gto_geo_caillau_60n.json"
G0 = 9.80665


def test_60n_minimum_time_from_a_path_and_from_a_dict():
    res = ts.transfer(CAILLAU_60N)
    s = res.summary
    assert isinstance(s, dict)
    assert res.converged and s["status"] == "converged" and s["method"] == "minimum_time"
    assert s["duration_h"] == pytest.approx(14.8004, rel=1e-3)
    # Always on: the propellant is T t_f / (g0 Isp).
    assert s["propellant_kg"] == pytest.approx(60.0 * s["duration_s"] / (G0 * 1994.75), rel=1e-9)
    assert abs(s["errors"]["a_m"]) < 1.0 and abs(s["errors"]["e"]) < 1e-8
    assert s["final_state"]["keplerian"]["semi_major_axis_km"] == pytest.approx(42165.0, abs=1e-3)
    t = res.trajectory
    assert isinstance(t, pd.DataFrame)
    assert list(t.columns) == ["t_s", "p_m", "ex", "ey", "hx", "hy", "l_rad", "a_m", "e", "i_deg",
                               "mass_kg", "u_q", "u_s", "u_w"]
    assert len(t) > 100
    assert t["t_s"].iloc[-1] == pytest.approx(s["duration_s"], rel=1e-12)
    assert t["mass_kg"].iloc[-1] == pytest.approx(s["final_mass_kg"], rel=1e-9)
    assert t["a_m"].iloc[-1] == pytest.approx(42165e3, abs=1.0)
    o = res.orbit
    assert list(o.columns) == ["t_s", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s", "mass_kg"]
    # The same transfer from the file's content as a dict, with an epoch: the
    # arrival is dated.
    d = read_json(CAILLAU_60N)
    d["transfer"]["epoch"] = "2034-01-01T00:00:00Z"
    s2 = ts.transfer(d).summary
    assert s2["duration_s"] == s["duration_s"]
    assert s2["end_epoch"].startswith("2034-01-01T14:48:01")
    assert s2["final_state"]["keplerian"]["epoch"] == s2["end_epoch"]


def test_equals_the_cli_summary(tmp_path):
    cli = run_cli("transfer", CAILLAU_60N, "--out", tmp_path / "cli", "--quiet", "--no-plots",
                  "--no-report")
    assert cli.returncode == 0, cli.stderr
    want = read_json(tmp_path / "cli" / "summary.json")
    got = ts.transfer(CAILLAU_60N).summary
    for key in ["duration_s", "propellant_kg", "final_elements", "convergence", "replay", "final_state",
                "second_order", "interrupted", "force_model"]:
        assert got[key] == want[key], key
    traj = pd.read_csv(tmp_path / "cli" / "trajectory.csv")
    pd.testing.assert_frame_equal(ts.transfer(CAILLAU_60N).trajectory, traj)


def test_method_override_and_bad_fields_raise_scenario_error_naming_them():
    d = read_json(CAILLAU_60N)
    bad = copy.deepcopy(d)
    bad["transfer"]["thrust_n"] = -60
    with pytest.raises(ts.ScenarioError, match=r"scenario\.transfer\.thrust_n.*-60"):
        ts.transfer(bad)
    bad = copy.deepcopy(d)
    bad["transfer"]["isp_sec"] = bad["transfer"].pop("isp_s")
    with pytest.raises(ts.ScenarioError, match=r"scenario\.transfer\.isp_sec"):
        ts.transfer(bad)
    bad = copy.deepcopy(d)
    bad["transfer"]["epoch"] = "2034-13-01"
    with pytest.raises(ts.ScenarioError, match=r"scenario\.transfer\.epoch"):
        ts.transfer(bad)
    bad = copy.deepcopy(d)
    bad["transfer"]["mass_kg"] = float("nan")
    with pytest.raises(ts.ScenarioError, match=r"scenario\.transfer\.mass_kg"):
        ts.transfer(bad)
    assert issubclass(ts.ScenarioError, ValueError)
    with pytest.raises(ts.ScenarioError, match=r"method.*warp"):
        ts.transfer(d, method="warp")
    # two_impulse needs circular orbits: refused naming the method field.
    with pytest.raises(ts.ScenarioError, match=r"scenario\.transfer\.method"):
        ts.transfer(d, method="two_impulse")
    with pytest.raises(TypeError):
        ts.transfer(42)


def test_two_impulse_is_hohmann():
    res = ts.transfer(SCENARIOS / "transfer" / "map434_hohmann.json")
    assert res.summary["two_impulse"]["total_dv_m_s"] == pytest.approx(3907.1, abs=0.05)
    # The coast, with the states before the first impulse and after the second.
    assert res.summary["orbit_source"] == "coast"
    assert len(res.orbit) == len(res.trajectory) + 2
    dv = res.orbit[["vx_m_s", "vy_m_s", "vz_m_s"]].to_numpy()
    assert ((dv[1] - dv[0]) ** 2).sum() ** 0.5 == pytest.approx(res.summary["two_impulse"]["dv0_m_s"], rel=1e-9)
    assert ((dv[-1] - dv[-2]) ** 2).sum() ** 0.5 == pytest.approx(res.summary["two_impulse"]["dvf_m_s"], rel=1e-6)


def test_j2_feedback_minimum_time_and_two_impulse_refusing_j2():
    # The feedback at 10 N to V <= 1e-5 from Caillau's GTO, with and without
    # J2: both reach GEO (the final a within 0.16 %); the J2 run's longitude
    # differs (the node and perigee drift). Minimum time at 60 N with J2:
    # 14.800065 h (two-body 14.800364 h), its replay (with J2) at GEO.
    d = read_json(CAILLAU_60N)
    d["transfer"].update(thrust_n=10.0, method="feedback",
                         feedback={"optimal_end": False, "stop_at_saturation": False, "v_stop": 1e-5})
    two_body = ts.transfer(d).summary
    d["transfer"]["force_model"] = "j2"
    j2 = ts.transfer(d).summary
    assert two_body["force_model"] == "two_body" and j2["force_model"] == "j2"
    for s in (two_body, j2):
        assert s["status"] == "converged" and s["feedback"]["stop_reason"] == "target"
        assert s["final_elements"]["a_m"] == pytest.approx(42165e3, rel=0.0016)
    assert abs(j2["final_elements"]["l_rad"] - two_body["final_elements"]["l_rad"]) > 1e-3
    mt = read_json(CAILLAU_60N)
    mt["transfer"]["force_model"] = "j2"
    s = ts.transfer(mt).summary
    assert s["status"] == "converged" and s["duration_h"] == pytest.approx(14.800065, abs=1e-5)
    assert abs(s["replay"]["a_m"] - 42165e3) < 50 and s["replay"]["e"] < 2e-6
    assert s["second_order"]["conjugate_point_test"] == "no_conjugate_point"
    with pytest.raises(ts.ScenarioError, match=r"scenario\.transfer\.force_model: two_impulse"):
        ts.transfer(d, method="two_impulse")
