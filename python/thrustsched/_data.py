"""The data shipped with the package (the source tree's data/scenarios and
data/campaigns), found from the package itself, never from the working
directory:

    scn = thrustsched.Scenario.load(thrustsched.data_path("scenarios/hcw_table41_2d.json"))
    campaign = thrustsched.data_path("campaigns", "hcw_quick.json")
"""
from __future__ import annotations

import os
import pathlib

# The package's data folder. An installed package (pip, or `cmake --install`)
# holds a copy of the source tree's folders there; the build tree's package
# (build/python/thrustsched) holds symbolic links to them, made by
# python/CMakeLists.txt, which lists the folders shipped.
_DATA_DIR = pathlib.Path(__file__).resolve().parent / "data"


def data_path(*parts: "str | os.PathLike[str]") -> pathlib.Path:
    """The path of a shipped data file or folder, e.g.
    ``data_path("scenarios/hcw_table41_1d.json")`` or ``data_path("scenarios",
    "year", "year_anzel4_fixed.json")``; ``data_path()`` is the data folder
    itself (``scenarios/``, ``campaigns/``: the source tree's ``data/``
    folders of those names).

    It looks in one place, the ``data`` folder next to the package's modules
    (``thrustsched/data``), whatever the working directory. Raises
    FileNotFoundError naming the path when the file is not shipped, and
    ValueError for an absolute path or one that leaves the data folder.
    """
    relative = pathlib.PurePath(*[os.fspath(p) for p in parts])
    if relative.is_absolute() or ".." in relative.parts:
        raise ValueError(f"data_path: {str(relative)!r} must be a relative path inside the shipped data "
                         f"folder (no '..'), e.g. 'scenarios/hcw_table41_1d.json'")
    path = _DATA_DIR / relative
    if not path.exists():
        raise FileNotFoundError(f"data_path: {str(relative)!r} is not shipped with the package "
                                f"(looked in {_DATA_DIR})")
    return path
