"""The milp layer, and schedule MILPs extended with the user's rows.

    pytest tests/python/test_milp.py
"""
import itertools

import numpy as np
import pytest

import thrustsched as ts
from conftest import SCENARIOS, SLOT_M_S
from thrustsched import milp


def test_knapsack_equals_brute_force(tmp_path):
    w, v, cap = [2, 3, 4, 5, 9], [3, 4, 5, 8, 10], 10
    m = milp.Model("knapsack")
    take = m.add_variables(len(w), 0, 1, "binary", "take")
    m.add_constraint(milp.dot(w, take) <= cap, "weight")
    m.maximize(milp.dot(v, take))
    r = milp.solve(m)
    best = max(sum(vi for vi, t in zip(v, ts_) if t) for ts_ in itertools.product([0, 1], repeat=len(w))
               if sum(wi for wi, t in zip(w, ts_) if t) <= cap)
    assert r.status == "optimal" and r.objective == pytest.approx(best)
    assert r.value(milp.dot(w, take)) <= cap + 1e-9
    milp.write(m, tmp_path / "k.lp")
    assert "weight:" in (tmp_path / "k.lp").read_text()
    assert "take(0)" in milp.to_mps_string(m)


def test_expressions_and_bulk_rows():
    m = milp.Model()
    x = m.add_variable(0, 10, "continuous", "x")
    y = m.add_variable(0, 10, "integer", "y")
    e = 2 * x - y / 2 + 3
    idx, coef = e.terms
    assert list(idx) == [0, 1] and list(coef) == [2.0, -0.5] and e.constant == 3.0
    c = 1 <= x + y
    assert c.lower == 1 and np.isinf(c.upper)
    s = sum([x, y, x])  # Python's sum works (radd)
    assert list(s.terms[1]) == [2.0, 1.0]
    assert list(milp.quicksum([x, y, 4.0]).terms[1]) == [1.0, 1.0]
    start, count = m.add_rows(np.array([[1.0, 1.0], [1.0, -1.0]]), [x, y], [-np.inf, 0.5], [7.5, np.inf])
    assert (start, count) == (0, 2)
    m.maximize(x + 2 * y)
    r = milp.solve(m)
    # x + y <= 7.5, x - y >= 0.5, y integer: y = 3, x = 4.5 -> 10.5
    assert r.status == "optimal" and r.objective == pytest.approx(10.5)
    assert r.x[1] == pytest.approx(3.0)
    lp = m.to_lp()
    assert lp.num_rows == 2 and lp.matrix.shape == (2, 2) and lp.integer == [False, True]


def test_forbidding_the_optimal_slot_moves_the_burn(tmp_path):
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    b = ts.build(scn)
    first = b.solve()
    assert first.objective == pytest.approx(SLOT_M_S, rel=1e-9)
    thr = first.schedule["thruster"].iloc[0]
    j = b.interval_at(float(first.schedule["start_s"].iloc[0]))
    # Forbid that thruster for an hour around its slot (twelve rows, one refreeze).
    b.add_constraints([b.on(thr, k) == 0 for k in range(j - 6, j + 6)], "forbidden")
    assert b.modified and b.num_rows == ts.build(scn).num_rows + 12
    second = b.solve()
    assert second.status == "optimal" and second.check.passed
    assert second.objective == pytest.approx(SLOT_M_S, rel=1e-9)  # any one slot will do...
    s = second.schedule.iloc[0]
    assert not (s["thruster"] == thr and (j - 6) * 300 <= s["start_s"] < (j + 6) * 300)  # ...elsewhere
    b.write(tmp_path / "forbidden.lp")
    assert "forbidden(0)" in (tmp_path / "forbidden.lp").read_text()


def test_a_keep_out_row_on_an_output_is_respected():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    b = ts.build(scn)
    base = b.solve()
    node = 200
    y_free = base.outputs[node, 1]  # along-track y at node 200 without the row
    limit = y_free + 2000.0 if y_free < 0 else y_free - 2000.0
    row = b.output_expr(node, 1) >= limit if y_free < 0 else b.output_expr(node, 1) <= limit
    b.add_constraint(row, "keep_out_y")
    r = b.solve()
    assert r.status == "optimal" and r.check.operational_ok
    y = r.outputs[node, 1]
    assert (y >= limit - 1e-6) if y_free < 0 else (y <= limit + 1e-6)
    assert r.objective >= base.objective - 1e-12
    # state_expr is the same quantity from the states.
    assert b.state_expr(node, 1).evaluate(r.x) == pytest.approx(y, rel=1e-9, abs=1e-6)
