"""``python3 -m thrustsched ARGS``: the thrustsched command line (the same
code as the ``thrustsched`` executable, from the package), e.g.

    python3 -m thrustsched solve data/scenarios/hcw_table41_1d.json --out out/one_day

Campaign workers (thrustsched.sweep) run their tasks this way, one process per
task, so that a task that crashes leaves its worker alive.
"""
import sys

from . import _core


def main() -> int:
    return _core.run_cli(["thrustsched", *sys.argv[1:]])


if __name__ == "__main__":
    sys.exit(main())
