"""A real Ctrl-C for the interrupt helpers (interrupt_helper.py,
transfer_interrupt_helper.py), run as scripts in a child process.

    ctrl_c = CtrlC(mode)               # "once" | "twice"
    def progress(d):
        ctrl_c.on_progress(d)
        if <the moment to interrupt>: ctrl_c.trigger.set()

Another thread sends SIGINT to this process once `trigger` is set, so the
signal goes through Python's own handler like a Ctrl-C in a terminal and
lands where the caller chose whatever the machine's speed. "twice": a second
SIGINT once the run reports it is stopping (progress phase "stopping").
"""
import os
import signal
import threading
import time


class CtrlC:
    def __init__(self, mode):
        self.mode = mode
        self.trigger = threading.Event()
        self.events = {}
        threading.Thread(target=self._send, daemon=True).start()

    def _send(self):
        self.trigger.wait()
        self.events["sigint"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)

    def on_progress(self, d):
        if d.get("phase") == "stopping":
            self.events["stopping"] = time.monotonic()
            if self.mode == "twice":
                os.kill(os.getpid(), signal.SIGINT)
                time.sleep(1.0)  # the handler runs in this thread: KeyboardInterrupt here

    def seconds_since_signal(self):
        return time.monotonic() - self.events["sigint"]
