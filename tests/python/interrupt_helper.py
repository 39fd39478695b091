"""Run by test_interrupt.py in a child process: a solve stopped by a real SIGINT.

    python3 interrupt_helper.py once|twice

The SIGINT is sent to this process by another thread right after the solve's
first incumbent (so it lands mid-search whatever the machine's speed), and
goes through Python's own handler like a Ctrl-C in a terminal. "twice": a
second SIGINT once the solve says it is stopping. Prints one JSON line.
"""
import json
import os
import signal
import sys
import threading
import time

import thrustsched as ts

mode = sys.argv[1]
scn = ts.Scenario.load("tests/app/data/geo_2day_5min.json")
first_incumbent = threading.Event()
events = {}


def progress(d):
    if d.get("new_incumbent") and not first_incumbent.is_set():
        first_incumbent.set()
    if d.get("phase") == "stopping":
        events["stopping"] = time.monotonic()
        if mode == "twice":
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(1.0)  # the handler runs in this thread: KeyboardInterrupt here


def ctrl_c():
    first_incumbent.wait()
    events["sigint"] = time.monotonic()
    os.kill(os.getpid(), signal.SIGINT)


threading.Thread(target=ctrl_c, daemon=True).start()
out = {}
try:
    # CBC alone on the whole MILP with a zero gap (as the CLI's SIGINT test):
    # without the interrupt it would run until the proof of optimality.
    res = ts.solve(scn, relative_gap=0, time_limit_s=250, search=False, threads=1, progress=progress)
    out = dict(returned=True, status=res.status, interrupted=res.interrupted, gap=res.gap,
               burns=len(res.schedule), operational_ok=res.check.operational_ok,
               stop_s=time.monotonic() - events["sigint"] - res.summary["check_seconds"],
               utc=str(res.schedule["start_utc"].iloc[0]))
except KeyboardInterrupt:
    out = dict(returned=False, keyboard_interrupt=True)
print(json.dumps(out))
sys.stdout.flush()
