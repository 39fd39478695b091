"""Run by test_transfer_interrupt.py in a child process: ts.transfer stopped by a real SIGINT.

    python3 transfer_interrupt_helper.py once|twice

The 0.2 N continuation from 60 N (17 steps, tens of seconds) is started;
another thread sends SIGINT to this process right after the first converged
continuation step is reported (so it lands mid-continuation whatever the
machine's speed) and it goes through Python's own handler like a Ctrl-C in
a terminal. "twice": a second SIGINT once the transfer says it is stopping.
Prints one JSON line.
"""
import json
import os
import signal
import sys
import threading
import time

import thrustsched as ts

mode = sys.argv[1]
first_step = threading.Event()
events = {"steps": 0}


def progress(d):
    if d.get("phase") == "continuation":
        events["steps"] += 1
        if d.get("converged"):
            first_step.set()
    if d.get("phase") == "stopping":
        events["stopping"] = time.monotonic()
        if mode == "twice":
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(1.0)  # the handler runs in this thread: KeyboardInterrupt here


def ctrl_c():
    first_step.wait()
    events["sigint"] = time.monotonic()
    os.kill(os.getpid(), signal.SIGINT)


threading.Thread(target=ctrl_c, daemon=True).start()
out = {}
try:
    res = ts.transfer("data/scenarios/transfer/gto_geo_caillau_0p2n.json", progress=progress)
    s = res.summary
    out = dict(returned=True, status=s["status"], interrupted=res.interrupted,
               converged=res.converged, steps_seen=events["steps"],
               steps=s["convergence"]["continuation_steps"],
               thrust_reached_n=s["convergence"]["continuation_thrust_reached_n"],
               duration_s=s["duration_s"], propellant_kg=s["propellant_kg"],
               residual=s["convergence"]["shooting_residual"],
               replay_a_m=s["replay"]["a_m"], replay_e=s["replay"]["e"],
               rows=len(res.trajectory),
               stop_s=time.monotonic() - events["sigint"])
except KeyboardInterrupt:
    out = dict(returned=False, keyboard_interrupt=True)
print(json.dumps(out))
sys.stdout.flush()
