"""Bring your own dynamics: ScheduleProblem from numpy arrays, ts.dynamics.

    pytest tests/python/test_problem.py
"""
import numpy as np
import pandas as pd
import pytest

import thrustsched as ts
from conftest import SCENARIOS, SLOT_M_S

N_GEO = 7.2921159e-5  # rad/s, the scenarios' HCW mean motion


def _hcw_arrays_problem(days=1, **kw):
    hcw = ts.dynamics.Hcw(N_GEO)
    thr = ts.ThrusterSet.preset("ideal6", 0.265, 4850, 2005)
    grid = ts.dynamics.uniform_grid(0, days * 86400, days * 288)
    d = hcw.discretise(grid, thr, scheme="exact_zoh")
    args = dict(initial_state=[1000, 0, 0, 0, 0, 0], output_matrix=hcw.output_matrix(0), thrusters=thr,
                window={"outputs": ["y_m", "z_m"], "half_widths": [36800, 36800], "enforce_from_s": 0},
                rules={"max_simultaneous": 1, "min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300},
                state_scale=hcw.state_scale, state_names=hcw.state_names, output_names=hcw.output_names)
    args.update(kw)
    return ts.ScheduleProblem.from_discretisation(d, **args), d


def test_discretisation_arrays_are_the_closed_form():
    hcw = ts.dynamics.Hcw(N_GEO)
    d = hcw.discretise([0.0, 300.0, 600.0])
    assert d["phi"].shape == (2, 6, 6) and d["gamma"].shape == (2, 6, 3) and d["drift"].shape == (2, 6)
    np.testing.assert_allclose(d["phi"][1], hcw.transition_matrix(300.0), rtol=0, atol=1e-12)
    # Gamma with unit inputs: the response to 1 m/s^2 along T held 300 s (HCW,
    # small n tau): dy ~ tau^2 / 2, dvy ~ tau.
    assert d["gamma"][0][4, 1] == pytest.approx(300.0, rel=1e-3)
    assert d["gamma"][0][1, 1] == pytest.approx(300.0 ** 2 / 2, rel=1e-3)
    a, b, dr = hcw.evaluate(0.0)
    assert a[3, 0] == pytest.approx(3 * N_GEO ** 2) and b.shape == (6, 3) and np.all(dr == 0)
    assert "hermite_simpson" in ts.dynamics.schemes()


def test_array_problem_equals_the_shipped_hcw_problem():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    p, _ = _hcw_arrays_problem()
    np.testing.assert_array_equal(scn.info.state_scale, ts.dynamics.Hcw(N_GEO).state_scale)
    # The same MILP, coefficient for coefficient.
    a, b = ts.build(p).lp, ts.build(scn).lp
    assert (a.num_rows, a.num_cols, a.num_nonzeros, a.num_integer_cols) == \
           (b.num_rows, b.num_cols, b.num_nonzeros, b.num_integer_cols)
    for field in ("col_cost", "col_lower", "col_upper", "row_lower", "row_upper"):
        np.testing.assert_array_equal(getattr(a, field), getattr(b, field), err_msg=field)
    assert abs(a.matrix - b.matrix).max() == 0.0
    # And the same optimum: the thesis Table 4.1 slot.
    ra, rb = ts.solve(p), ts.solve(scn)
    assert ra.status == rb.status == "optimal"
    assert ra.objective == rb.objective == pytest.approx(SLOT_M_S, rel=1e-9)
    pd.testing.assert_frame_equal(ra.schedule, rb.schedule)
    np.testing.assert_allclose(ra.states, rb.states, rtol=0, atol=1e-9)
    assert ra.check.passed and ra.check.kind == "discrete"
    t = ra.trajectory
    assert list(t.columns[:7]) == ["t_s"] + ts.dynamics.Hcw(N_GEO).state_names
    assert "out_y_m" in t.columns and len(t) == 289


def test_array_problem_check_judges_rules_and_window():
    p, _ = _hcw_arrays_problem(window={"outputs": [1, 2], "half_widths": [2000, 2000], "enforce_from_s": 0})
    c = ts.check(p, pd.DataFrame({"thruster": [], "start_s": [], "end_s": []}))
    assert c.operational_ok and not c.passed          # drifts out of a 2 km window without thrust
    assert c.max_window_violation_nodes > 0
    c = p.check([{"thruster": "-T", "start_s": 0.0, "end_s": 100.0}])
    assert not c.operational_ok and "min_burn" in c.findings[0]


def test_array_problem_from_names_and_a_drift():
    # A hand-made 1-D double integrator, x' = v, v' = a, with thrusters +X and -X.
    h, steps = 10.0, 30
    phi = np.tile(np.array([[1.0, h], [0.0, 1.0]]), (steps, 1, 1))
    acc = 0.01  # m/s^2 = thrust / mass
    g = np.array([[h * h / 2, -h * h / 2], [h, -h]]) * acc
    gamma = np.tile(g, (steps, 1, 1))
    drift = np.zeros((steps, 2))
    p = ts.ScheduleProblem(phi, gamma, drift=drift, grid_s=np.arange(steps + 1) * h, initial_state=[0.0, 0.2],
                           output_matrix=[[1.0, 0.0]], thrusters=["+X", "-X"], thrust_n=1.0, mass_kg=100.0,
                           isp_s=300.0, window={"outputs": [0], "half_widths": [20.0]},
                           rules={"min_burn_s": 10.0}, state_names=["x_m", "v_m_s"], output_names=["x_m"])
    r = ts.solve(p)
    assert r.status == "optimal" and r.check.passed
    # Without thrust x reaches 0.2 x 300 = 60 m; with it the window holds.
    assert np.abs(r.outputs[:, 0]).max() <= 20.0 + 1e-9
    # Cost (default directions +R): F/m per second on = delta-v.
    assert r.objective == pytest.approx(acc * r.schedule["duration_s"].sum(), rel=1e-12)
    with pytest.raises(ValueError, match=r"rules\.min_brn_s: unknown field"):
        ts.ScheduleProblem(phi, gamma, grid_s=np.arange(steps + 1) * h, initial_state=[0.0, 0.2],
                           output_matrix=[[1.0, 0.0]], thrusters=["+X", "-X"], thrust_n=1.0, mass_kg=100.0,
                           isp_s=300.0, rules={"min_brn_s": 10.0})
