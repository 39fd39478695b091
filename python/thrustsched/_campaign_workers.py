"""The campaign's handshake with the workers of an existing Dask cluster
(thrustsched.sweep --scheduler), and the worker a failed task ran on.

    check_workers(client, out)            # CampaignError naming every worker that cannot run tasks
    where = erred_workers(client, keys)   # {key: "tcp://10.0.0.5:40123"}

A worker can run campaign tasks when it imports thrustsched at the version
of this process (the task function is unpickled from it and each task runs
``python3 -m thrustsched`` with the worker's interpreter) and can write into
the folder that holds the out folder, at the same path (a shared file
system): data/campaigns/README.md, "Workers".
"""
from __future__ import annotations

import os
from typing import Any, Dict, List

from . import _campaign_probe
from ._campaign_spec import CampaignError

_README = "data/campaigns/README.md, \"Workers\""


def _by_value() -> None:
    import cloudpickle

    cloudpickle.register_pickle_by_value(_campaign_probe)


def check_workers(client: Any, out: str, scheduler: str = "") -> int:
    """Asks every worker of the cluster what it runs (the probe); returns the
    number of workers. Raises CampaignError, naming each worker that cannot
    run tasks and why, when there is none or one cannot."""
    import thrustsched

    _by_value()
    where = scheduler or getattr(getattr(client, "scheduler", None), "address", "") or "the scheduler"
    parent = os.path.dirname(os.path.abspath(out))
    answers = client.run(_campaign_probe.probe, parent, on_error="return")
    if not answers:
        raise CampaignError(f"--scheduler {where}: no worker is connected; start workers "
                            f"(dask-worker {where}) with thrustsched importable ({_README})")
    problems = []
    for address, info in sorted(answers.items()):
        if isinstance(info, BaseException):
            problems.append(f"{address}: the check failed on the worker: {type(info).__name__}: {info}")
            continue
        if "error" in info:
            problems.append(f"{address}: cannot import thrustsched ({info['error']}; its python: "
                            f"{info['python']})")
        elif info.get("version") != thrustsched.__version__:
            problems.append(f"{address}: thrustsched {info.get('version')} from {info.get('package')}, "
                            f"this sweep is {thrustsched.__version__}")
        if not info.get("sees_out", False):
            problems.append(f"{address}: cannot write into {parent} on {info.get('host')} (the out "
                            f"folder must be on a file system the workers share, at the same path)")
    if problems:
        raise CampaignError(f"--scheduler {where}: {len(problems)} problem(s) with the workers, nothing "
                            f"was run ({_README}):\n  " + "\n  ".join(problems))
    return len(answers)


def erred_workers(client: Any, keys: List[str]) -> Dict[str, str]:
    """The worker address(es) each erred key ran on, as one string ("" when
    the scheduler no longer knows)."""
    if not keys:
        return {}
    _by_value()
    try:
        where = client.run_on_scheduler(_campaign_probe.erred_on, keys)
    except Exception:  # noqa: BLE001 - the address is a detail of the error, not needed for it
        return {}
    return {k: ", ".join(v) for k, v in where.items()}
