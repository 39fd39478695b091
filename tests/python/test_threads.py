"""Solves in threads: the GIL is released, two solves run at once and agree.

    pytest tests/python/test_threads.py
"""
import threading
import time

import pandas as pd
import pytest

import thrustsched as ts
from conftest import SCENARIOS, TABLE41_2D_M_S


def test_two_solves_in_threads_agree():
    scn = ts.Scenario.load(SCENARIOS / "hcw_table41_2d.json")
    results, spans = [None, None], [None, None]
    barrier = threading.Barrier(2)

    def work(k):
        barrier.wait()
        t0 = time.monotonic()
        results[k] = ts.solve(scn, threads=1)
        spans[k] = (t0, time.monotonic())

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        assert r.status == "optimal"
        assert r.objective == pytest.approx(TABLE41_2D_M_S, abs=5e-8)
        assert r.check.passed
    assert results[0].objective == results[1].objective
    pd.testing.assert_frame_equal(results[0].schedule, results[1].schedule)
    # Both were inside ts.solve at the same time.
    assert max(s[0] for s in spans) < min(s[1] for s in spans)


def test_the_gil_is_free_during_a_solve():
    # A Python thread ticking during the solve: if the GIL were held by the
    # C++ code, its longest pause would be the whole solve.
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    time.sleep(0.05)
    t0 = time.monotonic()
    res = ts.solve(SCENARIOS / "hcw_table41_2d.json", threads=1)
    t1 = time.monotonic()
    stop.set()
    t.join()
    assert res.status == "optimal"
    during = [x for x in ticks if t0 <= x <= t1]
    gaps = [b - a for a, b in zip(during, during[1:])]
    assert len(during) > 10
    assert max(gaps) < 0.25 * (t1 - t0), (max(gaps), t1 - t0)
