"""Bad input: ValueError with the CLI's message; C++ exceptions never crash the interpreter.

    pytest tests/python/test_errors.py
"""
import json

import numpy as np
import pandas as pd
import pytest

import thrustsched as ts
from conftest import SCENARIOS, run_cli


def _cli_message(path):
    r = run_cli("solve", path, "--out", str(path) + ".out", "--no-plots")
    assert r.returncode == 2, r.stderr
    line = r.stderr.strip().splitlines()[-1]
    assert line.startswith("error: ")
    return line[len("error: "):]


@pytest.mark.parametrize("section,key,value,expected", [
    ("horizon", "step_s", 7, "scenario.horizon.step_s: 7 s does not divide the horizon duration 86400 s"),
    ("window", "half_width_m", -3, "scenario.window.half_width_m: must be > 0, got -3"),
    ("horizon", "stpe_s", 300, "scenario.horizon.stpe_s: unknown field"),
    ("operations", "min_burn_s", "five", "scenario.operations.min_burn_s"),
])
def test_bad_field_raises_value_error_with_the_cli_message(tmp_path, section, key, value, expected):
    d = json.loads((SCENARIOS / "hcw_table41_1d.json").read_text())
    d[section][key] = value
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(d, indent=2))
    cli = _cli_message(path)
    assert cli.startswith(expected)
    # Scenario.load, from_dict + solve, and a dict edit + solve all say the same.
    with pytest.raises(ValueError) as e:
        ts.Scenario.load(path)
    assert str(e.value) == cli
    with pytest.raises(ts.ScenarioError) as e:
        ts.solve(ts.Scenario.from_dict(d, validate=False))
    assert str(e.value) == cli
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    scn[section][key] = value
    with pytest.raises(ValueError) as e:
        ts.solve(scn)
    assert str(e.value) == cli


def test_malformed_json_and_duplicate_keys_name_the_file(tmp_path):
    text = (SCENARIOS / "hcw_table41_1d.json").read_text()
    path = tmp_path / "dup.json"
    path.write_text(text.replace('"name": "hcw_table41_1d",', '"name": "a", "name": "b",'))
    cli = _cli_message(path)
    with pytest.raises(ValueError) as e:
        ts.Scenario.load(path)
    assert str(e.value) == cli and "name" in cli


def test_non_finite_number_names_the_field():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    scn["spacecraft"]["mass_kg"] = float("nan")
    with pytest.raises(ValueError, match=r"^scenario\.spacecraft\.mass_kg: must be a finite number"):
        ts.solve(scn)


def test_check_on_a_broken_schedule_fails():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    good = ts.solve(scn).schedule
    assert ts.check(scn, good).passed
    broken = pd.DataFrame({"thruster": ["-T", "-T"], "start_s": [9000.0, 9600.0], "end_s": [9100.0, 9900.0]})
    c = ts.check(scn, broken)
    assert not c.passed and not c.operational_ok
    rules = {d["rule"] for d in c.report["rule_violation_details"]}
    assert rules == {"min_burn", "min_off_same"}  # 100 s < 300 s; 500 s off < 1200 s
    # No burn at all: the 1 km start drifts out of a 2 km window.
    scn["window"]["half_width_m"] = 2000
    c = ts.check(scn, pd.DataFrame({"thruster": [], "start_s": [], "end_s": []}))
    assert c.operational_ok and not c.passed
    assert c.max_window_violation_nodes > 0 and "window violated" in c.findings[0]


def test_unknown_thruster_or_column_is_a_value_error():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    with pytest.raises(ValueError, match=r'thruster "\+X" is not a thruster'):
        ts.check(scn, [{"thruster": "+X", "start_s": 0.0, "end_s": 300.0}])
    with pytest.raises(ValueError, match="missing column 'end_s'"):
        ts.check(scn, pd.DataFrame({"thruster": ["+T"], "start_s": [0.0]}))
    with pytest.raises(ValueError, match="end_s 0 is before start_s 300"):
        ts.check(scn, [{"thruster": "+T", "start_s": 300.0, "end_s": 0.0}])


def test_cpp_exceptions_become_python_exceptions():
    hcw = ts.dynamics.Hcw(7.2921159e-5)
    with pytest.raises(ValueError, match="mean_motion"):
        ts.dynamics.Hcw(-1.0)
    with pytest.raises(ValueError, match="scheme"):
        hcw.discretise([0.0, 300.0], scheme="nope")
    with pytest.raises(ValueError, match="grid"):
        hcw.discretise([0.0, 0.0])
    thr = ts.ThrusterSet.preset("ideal6", 0.265, 4850, 2005)
    with pytest.raises(ValueError, match=r"gamma .*expected an array of shape \(2, 6, 6\), got shape \(2, 6, 3\)"):
        ts.ScheduleProblem(np.zeros((2, 6, 6)), np.zeros((2, 6, 3)), grid_s=[0, 1, 2], initial_state=np.zeros(6),
                           output_matrix=np.eye(6)[:3], thrusters=thr)
    from thrustsched import milp
    a, b = milp.Model("a"), milp.Model("b")
    x = a.add_variable(0, 1)
    with pytest.raises(ValueError):
        b.add_constraint(x <= 1)
    with pytest.raises(ValueError):
        a.add_variable(2, 1)  # lower > upper
    with pytest.raises(IndexError):
        a.add_variables(2, 0, 1)[5]
    with pytest.raises(ValueError, match="truth value"):
        bool(x <= 1)
    # A GEO model with a bad option.
    with pytest.raises(ValueError, match="gravity_degree"):
        ts.dynamics.Geo(gravity_degree=9)
