"""Run by test_transfer_interrupt.py in a child process: ts.transfer stopped by a real SIGINT.

    python3 transfer_interrupt_helper.py once|twice

The 0.2 N continuation from 60 N (17 steps, tens of seconds) is started; the
SIGINT (ctrl_c.py) is sent right after the first converged continuation step
is reported, so it lands mid-continuation whatever the machine's speed.
"twice": a second SIGINT once the transfer says it is stopping.
Prints one JSON line.
"""
import json
import sys

import thrustsched as ts
from ctrl_c import CtrlC

ctrl_c = CtrlC(sys.argv[1])
steps_seen = 0


def progress(d):
    global steps_seen
    ctrl_c.on_progress(d)
    if d.get("phase") == "continuation":
        steps_seen += 1
        if d.get("converged"):
            ctrl_c.trigger.set()


out = {}
try:
    res = ts.transfer("data/scenarios/transfer/gto_geo_caillau_0p2n.json", progress=progress)
    s = res.summary
    out = dict(returned=True, status=s["status"], interrupted=res.interrupted,
               converged=res.converged, steps_seen=steps_seen,
               steps=s["convergence"]["continuation_steps"],
               thrust_reached_n=s["convergence"]["continuation_thrust_reached_n"],
               duration_s=s["duration_s"], propellant_kg=s["propellant_kg"],
               residual=s["convergence"]["shooting_residual"],
               replay_a_m=s["replay"]["a_m"], replay_e=s["replay"]["e"],
               rows=len(res.trajectory),
               stop_s=ctrl_c.seconds_since_signal())
except KeyboardInterrupt:
    out = dict(returned=False, keyboard_interrupt=True)
print(json.dumps(out))
sys.stdout.flush()
