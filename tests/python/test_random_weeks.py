"""scripts/random_weeks.py: the draws stay in the documented ranges, start
inside the window, are the same for the same seed, and every week is a
scenario the CLI accepts (validate builds its model); bad options exit 2."""
import datetime
import json
import math
import os

from conftest import SOURCE_DIR, run_cli, run_python

SCRIPT = SOURCE_DIR / "scripts" / "random_weeks.py"
PRESETS = {"anzel4": {"NE", "SE", "NW", "SW"}, "ideal6": {"+R", "+T", "+N", "-R", "-T", "-N"}}


def weeks(folder):
    return {f: open(os.path.join(folder, f)).read() for f in sorted(os.listdir(folder))}


def test_same_seed_same_weeks_other_seed_other_weeks(tmp_path):
    for name, seed in (("a", 3), ("b", 3), ("c", 4)):
        r = run_python(SCRIPT, "--seed", seed, "--count", 6, "--out", tmp_path / name)
        assert r.returncode == 0, r.stderr
    a, b, c = (weeks(tmp_path / n) for n in "abc")
    assert a == b
    assert len(a) == 7 and "weeks.csv" in a  # six weeks and the list of draws
    assert set(a).isdisjoint(set(c) - {"weeks.csv"})


def test_draws_in_range_inside_the_window_and_valid(tmp_path):
    r = run_python(SCRIPT, "--seed", 11, "--count", 40, "--out", tmp_path)
    assert r.returncode == 0, r.stderr
    files = sorted(f for f in os.listdir(tmp_path) if f.endswith(".json"))
    assert len(files) == 40
    seen_presets, failed, end_sets, steps = set(), 0, 0, set()
    for k, f in enumerate(files):
        s = json.load(open(tmp_path / f))
        assert s["name"] == f[:-5] and f.startswith("rw_11_%03d_" % k)
        preset = s["spacecraft"]["thrusters"]["preset"]
        seen_presets.add(preset)
        assert s["spacecraft"]["disabled"] in ([],) + tuple([t] for t in PRESETS[preset])
        failed += bool(s["spacecraft"]["disabled"])
        assert ("_failed" in f) == bool(s["spacecraft"]["disabled"])
        assert -180 <= s["model"]["station_longitude_deg"] < 180
        epoch = datetime.datetime.strptime(s["model"]["epoch"], "%Y-%m-%dT%H:%M:%SZ")
        assert 2025 <= epoch.year <= 2045
        w_deg = s["window"]["half_width_deg"]
        assert 0.03 <= w_deg <= 0.1
        ops = s["operations"]
        assert 300 <= ops["min_burn_s"] <= 900 and 600 <= ops["min_off_same_s"] <= 2400
        assert 300 <= ops["min_gap_other_s"] <= 900 and ops["max_simultaneous"] == 1
        steps.add(s["horizon"]["step_s"])
        assert s["horizon"]["duration_s"] == 7 * 86400
        end_sets += "terminal" in s
        # Inside the window at t = 0 (Gazzino 2018, (B.82)): latitude <= 2 |i|,
        # longitude <= |dl| + 2 |e| (first order), each at most 0.6 w.
        da, ex, ey, ix, iy, dl = s["initial_state"]["relative_equinoctial"]
        w = math.radians(w_deg)
        assert 2 * math.hypot(ix, iy) <= 0.6 * w * (1 + 1e-6)
        assert abs(dl) + 2 * math.hypot(ex, ey) <= 0.6 * w * (1 + 1e-6)
        assert abs(da) <= 300
    assert seen_presets == set(PRESETS) and steps == {300, 600}
    assert 0 < failed < 40 and 0 < end_sets < 40
    for f in files[:4]:
        r = run_cli("validate", tmp_path / f)
        assert r.returncode == 0, (f, r.stderr)


def test_an_earlier_draw_in_the_folder_is_replaced(tmp_path):
    assert run_python(SCRIPT, "--seed", 1, "--count", 5, "--out", tmp_path).returncode == 0
    assert run_python(SCRIPT, "--seed", 2, "--count", 3, "--out", tmp_path).returncode == 0
    files = [f for f in os.listdir(tmp_path) if f.endswith(".json")]
    assert len(files) == 3 and all(f.startswith("rw_2_") for f in files)


def test_bad_options_exit_2_naming_them(tmp_path):
    r = run_python(SCRIPT, "--seed", 1, "--count", 0, "--out", tmp_path / "x")
    assert r.returncode == 2 and "--count" in r.stderr
    (tmp_path / "file").write_text("")
    r = run_python(SCRIPT, "--seed", 1, "--count", 2, "--out", tmp_path / "file")
    assert r.returncode == 2 and "--out" in r.stderr
    r = run_python(SCRIPT, "--count", 2, "--out", tmp_path / "y")
    assert r.returncode == 2 and "--seed" in r.stderr
