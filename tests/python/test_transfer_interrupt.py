"""Ctrl-C during ts.transfer and `thrustsched transfer`: the first stops the
continuation and keeps its last converged step, the second raises (Python)
or exits at once (CLI).

    pytest tests/python/test_transfer_interrupt.py
"""
import json
import pathlib
import signal
import subprocess

from conftest import CLI, SCENARIOS, SOURCE_DIR, read_json, run_python

import pytest

HELPER = pathlib.Path(__file__).with_name("transfer_interrupt_helper.py")
CAILLAU_0P2N = SCENARIOS / "transfer" / "gto_geo_caillau_0p2n.json"
G0 = 9.80665


def _run(mode):
    r = run_python(HELPER, mode, timeout=400)
    assert r.returncode == 0, r.stdout + r.stderr
    return json.loads(r.stdout.strip().splitlines()[-1]), r.stderr


def _check_interrupted_continuation(s_thrust, duration_s, propellant_kg, steps):
    # The last converged step of the 60 N -> 0.2 N continuation: a thrust in
    # between, always on (propellant = T t_f / (g0 Isp)), and T t_f near the
    # 850-888 N h of Bombrun's Theorem 45.
    assert 0.2 < s_thrust < 60.0
    assert steps >= 1
    assert propellant_kg == pytest.approx(s_thrust * duration_s / (G0 * 1994.75), rel=1e-9)
    assert 800.0 < s_thrust * duration_s / 3600 < 900.0


def test_first_ctrl_c_returns_the_last_converged_continuation_step():
    out, err = _run("once")
    assert out["returned"] and out["interrupted"], out
    assert out["status"] == "interrupted" and not out["converged"]
    assert "interrupted: stopping the transfer" in err
    _check_interrupted_continuation(out["thrust_reached_n"], out["duration_s"], out["propellant_kg"],
                                    out["steps"])
    # Stopped long before the 17 steps of the whole continuation, and the
    # result is a converged extremal at that thrust whose replay reaches GEO.
    assert out["steps"] < 17 and out["steps_seen"] >= 1
    assert out["residual"] < 1e-6
    assert abs(out["replay_a_m"] - 42165e3) < 1e3 and out["replay_e"] < 1e-4
    assert out["rows"] > 100
    # Within one shooting evaluation of the signal: generous for a loaded machine.
    assert out["stop_s"] < 30.0, out


def test_second_ctrl_c_raises_keyboard_interrupt():
    out, _ = _run("twice")
    assert out == {"returned": False, "keyboard_interrupt": True}


def test_cli_first_sigint_writes_the_best_result_and_exits_4(tmp_path):
    if not pathlib.Path(CLI).exists():
        pytest.skip(f"the thrustsched CLI is not built ({CLI})")
    out = tmp_path / "run"
    p = subprocess.Popen([CLI, "transfer", str(CAILLAU_0P2N), "--out", str(out), "--no-plots"],
                         cwd=SOURCE_DIR, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        # The first converged continuation step, then SIGINT.
        for line in p.stderr:
            if "thrust" in line and ": converged" in line:
                break
        p.send_signal(signal.SIGINT)
        stdout, stderr = p.communicate(timeout=300)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert p.returncode == 4, stdout + stderr
    assert "status        interrupted" in stdout
    assert "SIGINT" in stderr
    s = read_json(out / "summary.json")
    assert s["status"] == "interrupted" and s["interrupted"] is True
    c = s["convergence"]
    _check_interrupted_continuation(c["continuation_thrust_reached_n"], s["duration_s"],
                                    s["propellant_kg"], c["continuation_steps"])
    assert c["continuation_steps"] < 17
    assert (out / "trajectory.csv").exists() and (out / "report.html").exists()
