"""ts.check and ts.export against `thrustsched check` and `thrustsched export`.

    pytest tests/python/test_check_export.py
"""
import pytest

import thrustsched as ts
from conftest import SCENARIOS, read_json, run_cli


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli") / "run"
    r = run_cli("solve", SCENARIOS / "hcw_table41_1d.json", "--out", out, "--no-plots")
    assert r.returncode == 0, r.stderr
    return out


def test_check_reads_the_cli_schedule_and_agrees_with_cli_check(cli_run, tmp_path):
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    c = ts.check(scn, cli_run / "schedule.csv")
    assert c.passed and c.operational_ok
    r = run_cli("check", SCENARIOS / "hcw_table41_1d.json", cli_run / "schedule.csv", "--out", tmp_path / "c",
                "--no-plots")
    assert r.returncode == 0, r.stdout + r.stderr
    cli = read_json(tmp_path / "c" / "check.json")
    for key in ("passed", "operational_ok", "max_window_violation", "max_window_violation_nodes", "terminal_ok",
                "final_state", "samples"):
        assert c.report[key] == cli[key], key
    # A broken copy: the CLI exits 5 and both report the same findings.
    text = (cli_run / "schedule.csv").read_text().splitlines()
    thruster, start, end, _ = text[1].split(",")
    broken = tmp_path / "broken.csv"
    broken.write_text(text[0] + "\n" + f"{thruster},{start},{float(start) + 60:g},60\n")
    r = run_cli("check", SCENARIOS / "hcw_table41_1d.json", broken, "--out", tmp_path / "b", "--no-plots")
    assert r.returncode == 5
    cli = read_json(tmp_path / "b" / "check.json")
    c = ts.check(scn, broken)
    assert not c.passed
    assert c.findings == cli["findings"]
    assert len(c.trajectory) == cli["samples"]


def test_export_writes_the_cli_files(tmp_path):
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_1d.json")
    for ext in ("mps", "lp"):
        info = ts.export(scn, tmp_path / f"py.{ext}")
        r = run_cli("export", SCENARIOS / "hcw_table41_1d.json", tmp_path / f"cli.{ext}")
        assert r.returncode == 0, r.stderr
        assert (tmp_path / f"py.{ext}").read_bytes() == (tmp_path / f"cli.{ext}").read_bytes()
        assert info["n_binaries"] == 6 * 288
    with pytest.raises(ValueError, match="must end in .mps or .lp"):
        ts.export(scn, tmp_path / "x.txt")
