"""What a campaign asks of a Dask worker and of the scheduler before and
after its tasks run (thrustsched._campaign_workers). Standard library only,
and pickled by value (cloudpickle.register_pickle_by_value): these functions
must run on a worker that cannot import thrustsched, to say so.

    probe(out_parent)                     # on each worker: its interpreter, thrustsched version, paths
    erred_on(keys, dask_scheduler=...)    # on the scheduler: the workers each erred task ran on
"""
from typing import Any, Dict, List


def probe(out_parent: str) -> Dict[str, Any]:
    """The worker's interpreter, the thrustsched it imports (version and
    location, or the import's error) and whether it can write into the
    folder that holds the campaign's out folder."""
    import os
    import sys

    info: Dict[str, Any] = {"python": sys.executable, "host": os.uname().nodename}
    try:
        import thrustsched

        info["version"] = thrustsched.__version__
        info["package"] = os.path.dirname(os.path.abspath(thrustsched.__file__))
    except Exception as e:  # noqa: BLE001 - the worker's message is the answer
        info["error"] = f"{type(e).__name__}: {e}"
    info["sees_out"] = os.path.isdir(out_parent) and os.access(out_parent, os.W_OK | os.X_OK)
    return info


def erred_on(keys: List[str], dask_scheduler: Any = None) -> Dict[str, List[str]]:
    """For each key the scheduler still holds: the addresses of the workers
    it erred on (Client.run_on_scheduler passes dask_scheduler by name)."""
    out = {}
    for k in keys:
        ts = dask_scheduler.tasks.get(k)
        if ts is not None:
            out[k] = sorted(getattr(ts, "erred_on", ()) or ())
    return out
