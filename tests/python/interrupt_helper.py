"""Run by test_interrupt.py in a child process: a solve stopped by a real SIGINT.

    python3 interrupt_helper.py once|twice

The SIGINT (ctrl_c.py) is sent right after the solve's first incumbent, so
it lands mid-search whatever the machine's speed. "twice": a second SIGINT
once the solve says it is stopping. Prints one JSON line.
"""
import json
import sys

import thrustsched as ts
from ctrl_c import CtrlC

ctrl_c = CtrlC(sys.argv[1])
scn = ts.Scenario.load("tests/app/data/geo_2day_5min.json")


def progress(d):
    ctrl_c.on_progress(d)
    if d.get("new_incumbent"):
        ctrl_c.trigger.set()


out = {}
try:
    # CBC alone on the whole MILP with a zero gap (as the CLI's SIGINT test):
    # without the interrupt it would run until the proof of optimality.
    res = ts.solve(scn, relative_gap=0, time_limit_s=250, search=False, threads=1, progress=progress)
    out = dict(returned=True, status=res.status, interrupted=res.interrupted, gap=res.gap,
               burns=len(res.schedule), operational_ok=res.check.operational_ok,
               stop_s=ctrl_c.seconds_since_signal() - res.summary["check_seconds"],
               utc=str(res.schedule["start_utc"].iloc[0]))
except KeyboardInterrupt:
    out = dict(returned=False, keyboard_interrupt=True)
print(json.dumps(out))
sys.stdout.flush()
