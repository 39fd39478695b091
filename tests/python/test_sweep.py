"""thrustsched.sweep and thrustsched-sweep: campaigns on a real Dask
LocalCluster against the same tasks run one after the other, resume, failure
isolation, bad campaign files, the emitted task list.

    pytest tests/python/test_sweep.py

The campaign is data/campaigns/hcw_quick.json: six one-day HCW solves whose
optima are whole numbers of 5-minute slots of one thruster (thesis Table 4.1
set-up): 5, 18 and 14 slots for radial offsets of 1.5, 3 and 2.5 km, checked
against the CLI run on the same scenario file.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import types

import pytest

import thrustsched as ts
from conftest import SLOT_M_S, SOURCE_DIR, run_cli

CAMPAIGN = SOURCE_DIR / "data" / "campaigns" / "hcw_quick.json"
LAUNCHER = os.path.join(os.path.dirname(os.environ.get("THRUSTSCHED_CLI", "")), "thrustsched-sweep")
VARYING = {"solve_s", "wall_s", "worker", "attempts", "error"}
SLOTS = {"[1500,0,0]": 5, "[3000,0,0]": 18, "[2500,0,0]": 14}

pytest.importorskip("distributed")


def rows(folder):
    with open(os.path.join(folder, "results.csv"), newline="") as f:
        return list(csv.DictReader(f))


def fixed(rs):
    """The columns a task id decides (everything but times, worker, attempts)."""
    return [{k: v for k, v in r.items() if k not in VARYING} for r in rs]


def sweep(*args, timeout=600):
    cmd = [sys.executable, "-m", "thrustsched.sweep", *map(str, args)]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=SOURCE_DIR)


@pytest.fixture(scope="module")
def serial_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("serial") / "c"
    outcome = ts.sweep.run(CAMPAIGN, out=out, workers=1, progress=False)
    assert outcome.exit_code == 0 and not outcome.failed
    return out


def test_local_cluster_gives_the_serial_rows_and_the_slot_optima(serial_run, tmp_path):
    r = sweep(CAMPAIGN, "--out", tmp_path / "c", "--workers", "2")
    assert r.returncode == 0, r.stderr
    assert "2 Dask workers" in r.stderr and "6/6 done" in r.stderr
    cluster, serial = rows(tmp_path / "c"), rows(serial_run)
    assert fixed(cluster) == fixed(serial)
    assert [r["task"] for r in cluster] == [str(k) for k in range(6)]
    assert {r["worker"] for r in cluster} == {"0", "1"}  # both workers ran tasks
    for row in cluster:
        assert row["status"] == "optimal" and row["check_passed"] == "true"
        slots = SLOTS[row["initial_state.hcw_position_m"]]
        assert float(row["consumption_l1_m_s"]) == pytest.approx(slots * SLOT_M_S, rel=1e-9)
        assert float(row["thrust_days"]) == pytest.approx(slots * 300 / 86400, rel=1e-12)
    # One task against the CLI on its own resolved scenario (the same file).
    task = ts.sweep.tasks(CAMPAIGN)[4]
    scenario = tmp_path / "c" / "scenarios" / f"{task.id}.json"
    cli = run_cli("solve", scenario, "--out", tmp_path / "cli", "--quiet", "--no-plots", "--no-report")
    assert cli.returncode == 0, cli.stderr
    with open(tmp_path / "cli" / "summary.json") as f:
        summary = json.load(f)
    assert float(cluster[4]["objective"]) == summary["objective"]
    assert task.params == {"operations.min_burn_s": 600, "initial_state.hcw_position_m": [3000, 0, 0]}
    report = (tmp_path / "c" / "report.md").read_text()
    assert "tasks: 6; finished: 6; failed: 0" in report
    assert (tmp_path / "c" / "plots" / "operations.min_burn_s.svg").exists()


def test_resume_runs_only_what_is_missing_and_refuses_to_start_over(serial_run, tmp_path):
    out = tmp_path / "c"
    shutil.copytree(serial_run, out)
    task = ts.sweep.tasks(CAMPAIGN)[2]
    os.remove(out / "rows" / f"{task.id}.json")
    shutil.rmtree(out / "tasks" / task.id)
    again = sweep(CAMPAIGN, "--out", out)
    assert again.returncode == 2 and "holds an earlier campaign" in again.stderr and "--resume" in again.stderr
    r = sweep(CAMPAIGN, "--out", out, "--resume", "--workers", "1")
    assert r.returncode == 0, r.stderr
    assert "5 of 6 tasks finished before, 1 to run" in r.stderr
    assert fixed(rows(out)) == fixed(rows(serial_run))
    assert (out / "attempts" / task.id).read_text().strip() == "2"  # run once more, the others not
    other = ts.sweep.tasks(CAMPAIGN)[3]
    assert (out / "attempts" / other.id).read_text().strip() == "1"


def test_a_crashing_task_is_retried_once_then_failed_and_the_rest_finish(tmp_path):
    spec = ts.sweep.load(CAMPAIGN)
    bad = ts.sweep.tasks(spec)[1]
    outcome = ts._campaign_run.run_campaign(spec, str(tmp_path / "c"), workers=2, progress=False,
                                            _faults={bad.id: "crash"})
    assert outcome.exit_code == 1
    assert [r["task"] for r in outcome.failed] == [1]
    assert "killed by signal 6" in outcome.failed[0]["error"]
    assert outcome.failed[0]["attempts"] == 2
    table = rows(tmp_path / "c")
    assert [r["status"] for r in table] == ["optimal", "failed", "optimal", "optimal", "optimal", "optimal"]
    assert "## Failed tasks" in (tmp_path / "c" / "report.md").read_text()


def test_a_worker_killed_mid_task_loses_nothing(serial_run, tmp_path):
    spec = ts.sweep.load(CAMPAIGN)
    victim = ts.sweep.tasks(spec)[0]
    outcome = ts._campaign_run.run_campaign(spec, str(tmp_path / "c"), workers=2, progress=False,
                                            _faults={victim.id: "kill_worker_once"})
    assert outcome.exit_code == 0, outcome.failed
    table = rows(tmp_path / "c")
    assert [r["task"] for r in table] == [str(k) for k in range(6)]  # each task once
    assert fixed(table) == fixed(rows(serial_run))
    assert table[0]["attempts"] == "2"


def test_bad_campaigns_exit_two_naming_the_path_and_value(tmp_path):
    base = json.loads(CAMPAIGN.read_text())
    base["base"] = str(SOURCE_DIR / "data" / "scenarios" / "hcw_table41_1d.json")
    cases = [
        ({"grid": {"operations.min_burn_s": []}}, "grid.operations.min_burn_s: an empty list"),
        ({"grid": {"operations.min_burn_s": ["long"]}}, "operations.min_burn_s"),
        ({"grid": {"operations.min_burn_s": [-300]}}, "-300"),
        ({"grid": {"operations.min_bur_s": [300]}}, "min_bur_s"),
        ({"grid": {"no_such_section.x": [1]}}, "no_such_section: no such section"),
        ({"zip": {"initial_state.hcw_position_m": [[1, 0, 0]], "operations.min_burn_s": [300, 600]}},
         "zipped lists differ in length"),
        ({"job": {"kind": "fly"}}, "job.kind: \"fly\" is not one of solve, simulate"),
        ({"monte_carlo": {"samples": 2, "seed": 1, "fields": {"operations.min_burn_s": {"gauss": [1, 2]}}}},
         "unknown distribution \"gauss\""),
        ({"colour": "blue"}, "colour: unknown campaign field"),
    ]
    for k, (change, message) in enumerate(cases):
        spec = {**base, **change}
        path = tmp_path / f"bad{k}.json"
        path.write_text(json.dumps(spec))
        r = sweep(path, "--out", tmp_path / f"out{k}")
        assert r.returncode == 2, (change, r.stderr)
        assert message in r.stderr, (change, r.stderr)
        assert not (tmp_path / f"out{k}").exists()  # nothing ran


def test_monte_carlo_samples_are_reproducible_and_independent_of_the_count():
    spec = json.loads(CAMPAIGN.read_text())
    spec["base"] = str(SOURCE_DIR / "data" / "scenarios" / "hcw_table41_1d.json")
    del spec["grid"], spec["zip"]
    spec["monte_carlo"] = {"samples": 3, "seed": 42, "fields": {
        "initial_state.hcw_position_m[0]": {"normal": [2000, 100]},
        "operations.min_burn_s": {"choice": [300, 600]}}}
    three = ts.sweep.tasks(spec)
    again = ts.sweep.tasks(spec)
    spec["monte_carlo"]["samples"] = 5
    five = ts.sweep.tasks(spec)
    assert [t.params for t in three] == [t.params for t in again] == [t.params for t in five[:3]]
    assert [t.id for t in three] == [t.id for t in five[:3]]
    xs = [t.params["initial_state.hcw_position_m[0]"] for t in five]
    assert len(set(xs)) == 5 and all(1500 < x < 2500 for x in xs)
    assert three[0].scenario["initial_state"]["hcw_position_m"][0] == xs[0]
    assert three[0].scenario["solver"]["threads"] == 1 and "time_limit_s" not in three[0].scenario["solver"]


def test_emitted_commands_run_anywhere_and_resume_collects_them(serial_run, tmp_path):
    out = tmp_path / "c"
    r = sweep(CAMPAIGN, "--out", out, "--emit-tasks", tmp_path / "tasks.txt")
    assert r.returncode == 0, r.stderr
    lines = (tmp_path / "tasks.txt").read_text().splitlines()
    assert len(lines) == 6 and all(line.startswith("thrustsched solve ") for line in lines)
    # Run the first line with the CLI (as a Slurm array element would).
    first = lines[0].split()
    cli = run_cli(*first[1:])
    assert cli.returncode == 0, cli.stderr
    r = sweep(CAMPAIGN, "--out", out, "--resume", "--workers", "1")
    assert r.returncode == 0, r.stderr
    table = rows(out)
    assert table[0]["worker"] == "collected"
    assert fixed(table) == fixed(rows(serial_run))


def test_dry_run_lists_the_tasks_and_runs_nothing(tmp_path):
    r = sweep(CAMPAIGN, "--out", tmp_path / "c", "--dry-run")
    assert r.returncode == 0, r.stderr
    assert "6 solve tasks over operations.min_burn_s, initial_state.hcw_position_m" in r.stdout
    assert r.stdout.count("to run") == 6
    assert not (tmp_path / "c").exists()


@pytest.mark.skipif(not os.path.exists(LAUNCHER), reason="the thrustsched-sweep launcher is not built")
def test_the_launcher_is_the_module():
    r = subprocess.run([LAUNCHER, "--help"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and "usage: thrustsched-sweep" in r.stdout


def test_ctrl_c_exits_four_within_seconds_and_resume_completes(serial_run, tmp_path):
    import signal
    import time

    out = tmp_path / "c"
    proc = subprocess.Popen([sys.executable, "-m", "thrustsched.sweep", str(CAMPAIGN), "--out", str(out),
                             "--workers", "1"], cwd=SOURCE_DIR, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    deadline = time.monotonic() + 300

    def finished_rows():  # ID.json; not a row being written (ID.json.tmpPID)
        return [n for n in os.listdir(out / "rows") if n.endswith(".json")] if (out / "rows").exists() else []

    while not finished_rows():
        assert proc.poll() is None and time.monotonic() < deadline
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGINT)  # as a terminal's Ctrl-C: the sweep and its task's process
    sent = time.monotonic()
    _, stderr = proc.communicate(timeout=120)
    assert time.monotonic() - sent < 15, stderr
    assert proc.returncode == 4, stderr
    assert "--resume runs the rest" in stderr
    finished = len(os.listdir(out / "rows"))  # ID.json each, nothing half-written
    assert finished == len(finished_rows())
    assert 1 <= finished < 6, (os.listdir(out / "rows"), stderr)
    r = sweep(CAMPAIGN, "--out", out, "--resume", "--workers", "1")
    assert r.returncode == 0, r.stderr
    assert f"{finished} of 6 tasks finished before" in r.stderr, (stderr, r.stderr)
    assert fixed(rows(out)) == fixed(rows(serial_run))


def test_a_ctrl_c_while_a_task_process_forks_is_the_interrupt_not_a_crash(monkeypatch, tmp_path):
    # The signal can land in the forked child's preexec_fn, which Popen then
    # reports as SubprocessError; with the sweep's Ctrl-C flag set that is the
    # interrupt (KeyboardInterrupt: exit 4 and a resumable folder), without it
    # an error that propagates.
    from thrustsched import _campaign_run as run

    def fork_fails(*args, **kwargs):
        raise subprocess.SubprocessError("Exception occurred in preexec_fn.")

    monkeypatch.setattr(run, "run_task", fork_fails)
    task = ts.sweep.tasks(ts.sweep.load(str(CAMPAIGN)))[0]
    outcome = types.SimpleNamespace(out=str(tmp_path))  # what run_task is given; nothing is recorded
    run._SIGINT_SEEN.set()
    try:
        with pytest.raises(KeyboardInterrupt):
            run._run_serial(outcome, [task], None, {})  # raises before the task is recorded
    finally:
        run._SIGINT_SEEN.clear()
    with pytest.raises(subprocess.SubprocessError):
        run._run_serial(outcome, [task], None, {})


def test_a_year_task_resumes_from_its_own_checkpoint(tmp_path):
    year = SOURCE_DIR / "data" / "scenarios" / "year" / "year_test_4cycles.json"
    spec = {"name": "years", "base": str(year), "job": {"kind": "simulate", "cycles": 2},
            "grid": {"horizon.step_s": [600]}}
    out = tmp_path / "c"
    ts.sweep.emit_tasks(spec, out, tmp_path / "tasks.txt")
    task = ts.sweep.tasks(spec)[0]
    scenario, task_dir = out / "scenarios" / f"{task.id}.json", out / "tasks" / task.id
    # The task's first cycle was run before (e.g. by a worker that then died).
    first = run_cli("simulate", scenario, "--out", task_dir, "--cycles", "1", "--quiet", "--no-plots")
    assert first.returncode == 0, first.stderr
    first_cycle = (task_dir / "cycles.csv").read_text().splitlines()[1]
    outcome = ts.sweep.run(spec, out=out, workers=1, resume=True, progress=False)
    assert outcome.exit_code == 0, outcome.failed
    cycles = (task_dir / "cycles.csv").read_text().splitlines()
    assert len(cycles) == 3 and cycles[1] == first_cycle  # cycle 1 kept, cycle 2 added
    # The same two cycles in one go, by the CLI.
    ref = run_cli("simulate", scenario, "--out", tmp_path / "ref", "--cycles", "2", "--quiet", "--no-plots")
    assert ref.returncode == 0, ref.stderr
    with open(tmp_path / "ref" / "year.json") as f:
        reference = json.load(f)
    row = rows(out)[0]
    assert row["status"] == "complete" and row["check_passed"] == "true"
    assert float(row["consumption_l1_m_s"]) == reference["consumption_l1_m_s"]
    assert float(row["thrust_days"]) == reference["thrust_days"]["total"]


def test_an_existing_dask_scheduler_runs_the_campaign(serial_run, tmp_path):
    from distributed import LocalCluster

    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0",
                      silence_logs=40, local_directory=str(tmp_path / "dask")) as cluster:
        r = sweep(CAMPAIGN, "--out", tmp_path / "c", "--scheduler", cluster.scheduler_address)
    assert r.returncode == 0, r.stderr
    assert "1 Dask worker," in r.stderr or "1 Dask worker\n" in r.stderr
    assert fixed(rows(tmp_path / "c")) == fixed(rows(serial_run))
