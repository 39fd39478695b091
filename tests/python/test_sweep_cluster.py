"""thrustsched-sweep --scheduler on a Dask cluster started by hand: a
scheduler and workers as separate processes (`python3 -m
distributed.cli.dask_scheduler` / `dask_worker`) on loopback, random free
ports, one worker without thrustsched importable (data/campaigns/README.md,
"Workers"):

- the sweep's handshake refuses the cluster up front (exit 2, nothing
  written), naming the worker that cannot import thrustsched and why, and
  not the one that can;
- a task that fails on such a worker anyway (the handshake skipped) is
  recorded as failed with the worker's message and its address; the campaign
  finishes with exit 1, results.csv and report.md;
- with only workers that have the package, the same campaign runs every task.

Every process started here is stopped at the end (its process group), also
when an assertion fails.
"""
import csv
import json
import os
import signal
import socket
import subprocess
import sys
import time

import pytest

from conftest import SCENARIOS

distributed = pytest.importorskip("distributed")

from thrustsched._campaign_run import run_campaign  # noqa: E402
from thrustsched._campaign_spec import load_spec  # noqa: E402

# Two one-day HCW solves (thesis Table 4.1 set-up), node-limited: a few seconds.
CAMPAIGN = {"name": "cluster_two", "base": str(SCENARIOS / "hcw_table41_1d.json"),
            "job": {"kind": "solve", "solver": {"max_nodes": 2000}},
            "zip": {"operations.min_burn_s": [300, 600]}}


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _env(with_package):
    env = dict(os.environ)
    if not with_package:
        env.pop("PYTHONPATH", None)
    return env


class Cluster:
    """A scheduler and named workers, each a process group of its own."""

    def __init__(self, tmp_path):
        self.tmp = tmp_path
        self.procs = {}
        self.address = f"tcp://127.0.0.1:{_free_port()}"

    def _start(self, name, args, with_package):
        log = open(self.tmp / f"{name}.log", "w")
        self.procs[name] = subprocess.Popen([sys.executable, "-m", *args], env=_env(with_package),
                                            cwd=self.tmp, stdout=log, stderr=subprocess.STDOUT,
                                            start_new_session=True)
        log.close()

    def start_scheduler(self):
        port = self.address.rsplit(":", 1)[1]
        self._start("scheduler", ["distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", port,
                                  "--no-dashboard"], with_package=False)
        deadline = time.monotonic() + 30
        while True:  # until it listens
            try:
                socket.create_connection(("127.0.0.1", int(port)), timeout=1).close()
                return
            except OSError:
                if time.monotonic() > deadline:
                    raise AssertionError("the scheduler did not start: " + self.log("scheduler"))
                time.sleep(0.2)

    def start_worker(self, name, with_package):
        self._start(name, ["distributed.cli.dask_worker", self.address, "--name", name, "--nworkers", "1",
                           "--nthreads", "1", "--host", "127.0.0.1", "--no-dashboard",
                           "--local-directory", str(self.tmp / name)], with_package)

    def stop(self, name):
        p = self.procs.pop(name)
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGTERM)
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()

    def stop_all(self):
        for name in list(self.procs):
            self.stop(name)

    def log(self, name):
        return (self.tmp / f"{name}.log").read_text()


def _workers(client, names, timeout=40.0):
    """Waits until exactly the named workers are connected; name -> address."""
    deadline = time.monotonic() + timeout
    while True:
        info = client.scheduler_info()["workers"]
        found = {w["name"]: addr for addr, w in info.items()}
        if sorted(found) == sorted(names):
            return found
        if time.monotonic() > deadline:
            raise AssertionError(f"workers {sorted(found)} connected, expected {sorted(names)}")
        time.sleep(0.2)


@pytest.fixture
def cluster(tmp_path):
    c = Cluster(tmp_path)
    try:
        yield c
    finally:
        c.stop_all()


def _sweep(*args):
    return subprocess.run([sys.executable, "-m", "thrustsched.sweep", *map(str, args)], capture_output=True,
                          text=True, timeout=120)


def test_a_worker_without_the_package_is_refused_then_recorded(cluster, tmp_path):
    from distributed import Client

    spec_path = tmp_path / "two.json"
    spec_path.write_text(json.dumps(CAMPAIGN))
    cluster.start_scheduler()
    cluster.start_worker("good", with_package=True)
    cluster.start_worker("bare", with_package=False)
    client = Client(cluster.address, timeout="30s")
    try:
        where = _workers(client, ["good", "bare"])

        # The handshake: exit 2 before anything is written, the bare worker named.
        r = _sweep(spec_path, "--out", tmp_path / "refused", "--scheduler", cluster.address)
        assert r.returncode == 2, r.stderr
        assert f"{where['bare']}: cannot import thrustsched (ModuleNotFoundError: No module named " \
               f"'thrustsched'" in r.stderr, r.stderr
        assert where["good"] not in r.stderr, r.stderr
        assert "data/campaigns/README.md" in r.stderr
        assert not (tmp_path / "refused").exists()

        # Only the bare worker left, the handshake skipped: every task fails on
        # it, is recorded with the worker's message and address, and the
        # campaign finishes with its table.
        cluster.stop("good")
        _workers(client, ["bare"])
        out = tmp_path / "failed"
        outcome = run_campaign(load_spec(CAMPAIGN), str(out), client=client, progress=False,
                               _check_workers=False)
        assert outcome.exit_code == 1
        assert len(outcome.failed) == 2
        for row in outcome.failed:
            assert "No module named 'thrustsched'" in row["error"], row["error"]
            assert f"(on worker {where['bare']})" in row["error"], row["error"]
        with open(out / "results.csv", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        assert [r["status"] for r in rows] == ["failed", "failed"]
        assert all(where["bare"] in r["error"] for r in rows)
        assert "No module named 'thrustsched'" in (out / "report.md").read_text()
        assert sorted(os.listdir(out / "rows")) == sorted(f"{t.id}.failed.json" for t in outcome.tasks)

        # Workers with the package only: the handshake passes and every task runs.
        cluster.stop("bare")
        cluster.start_worker("good2", with_package=True)
        _workers(client, ["good2"])
        r = _sweep(spec_path, "--out", tmp_path / "ok", "--scheduler", cluster.address, "--quiet")
        assert r.returncode == 0, r.stdout + r.stderr
        assert "2 of 2 tasks finished, 0 failed" in r.stdout, r.stdout
        with open(tmp_path / "ok" / "results.csv", encoding="utf-8") as f:
            ok = list(csv.DictReader(f))
        assert [r["status"] for r in ok] == ["optimal", "optimal"], ok
        assert {r["worker"] for r in ok} == {"good2"}
    finally:
        client.close()


def test_a_scheduler_without_workers_is_refused(cluster, tmp_path):
    spec_path = tmp_path / "two.json"
    spec_path.write_text(json.dumps(CAMPAIGN))
    cluster.start_scheduler()
    r = _sweep(spec_path, "--out", tmp_path / "none", "--scheduler", cluster.address)
    assert r.returncode == 2, r.stderr
    assert "no worker is connected" in r.stderr, r.stderr
    assert not (tmp_path / "none").exists()
