"""`pip install .` into a virtual environment, offline, reusing this build
tree (pyproject.toml, setup.py); then the installed package, not the build
tree's, solves a shipped scenario from an unrelated folder.

    pytest tests/python/test_pip_install.py

The environment is made in the build tree (<build>/pip_install_test), as
the README says: Debian's /usr/bin/python3 -m venv --system-site-packages
(numpy, pandas from Debian), pip --no-build-isolation --no-index (Debian's
setuptools and wheel, no network).
"""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import thrustsched as ts
from conftest import SLOT_M_S, SOURCE_DIR

# The build tree of the package under test: build/python/thrustsched/_core*.so.
BUILD_DIR = pathlib.Path(ts._core.__file__).resolve().parents[2]

SOLVE = """
import thrustsched as ts
scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_1d.json"))
res = ts.solve(scn, threads=1)
print(ts.__file__)
print(res.status, repr(res.objective), res.check.operational_ok)
"""


def _environment(extra=None):
    """No PYTHONPATH (the build tree's package must not be seen), no user
    pip configuration, no pip cache in the home folder."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "THRUSTSCHED_CMAKE_BUILD_DIR")}
    env.update(PIP_CONFIG_FILE=os.devnull, PIP_NO_CACHE_DIR="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.update(extra or {})
    return env


def _venv(name):
    if not (BUILD_DIR / "CMakeCache.txt").is_file():
        pytest.skip(f"the package under test is not in a CMake build tree ({BUILD_DIR})")
    if not os.path.exists("/usr/bin/python3"):
        pytest.skip("Debian's /usr/bin/python3 is missing")
    venv = BUILD_DIR / "pip_install_test" / name
    shutil.rmtree(venv, ignore_errors=True)
    r = subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(venv)],
                       capture_output=True, text=True, timeout=300, env=_environment())
    assert r.returncode == 0, r.stdout + r.stderr
    return venv


def _pip_install(venv, *options, env=None):
    return subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "--no-index", *options,
                           str(SOURCE_DIR)], capture_output=True, text=True, timeout=900,
                          env=_environment(env), cwd=venv)


@pytest.mark.parametrize("how", ["config_setting", "environment"])
def test_installed_package_solves_from_another_folder(tmp_path, how):
    venv = _venv(how)
    generated = [SOURCE_DIR / g for g in ("build-pip", "python/thrustsched.egg-info", "thrustsched.egg-info")]
    before = [g for g in generated if g.exists()]
    if how == "config_setting":
        r = _pip_install(venv, f"--config-settings=cmake-build-dir={BUILD_DIR}")
    else:
        r = _pip_install(venv, env={"THRUSTSCHED_CMAKE_BUILD_DIR": str(BUILD_DIR)})
    assert r.returncode == 0, r.stdout + r.stderr
    # The sources stay clean: setuptools' files went into the build tree.
    assert [g for g in generated if g.exists()] == before
    assert (BUILD_DIR / "pip" / "thrustsched.egg-info").is_dir()

    r = subprocess.run([str(venv / "bin" / "python"), "-c", SOLVE], capture_output=True, text=True,
                       timeout=300, cwd=tmp_path, env=_environment())
    assert r.returncode == 0, r.stdout + r.stderr
    where, result = r.stdout.splitlines()[-2:]
    site = venv / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / "site-packages"
    assert pathlib.Path(where) == site / "thrustsched" / "__init__.py"
    status, objective, ok = result.split()
    # Thesis Table 4.1, one day: one 5-minute slot of one thruster, F / m * 300 s.
    assert status == "optimal" and ok == "True"
    assert float(objective) == pytest.approx(SLOT_M_S, rel=1e-9)
    # The shipped data is a copy inside the package, not a link to the sources.
    data = site / "thrustsched" / "data" / "scenarios"
    assert data.is_dir() and not data.is_symlink()
    assert (data / "hcw_table41_1d.json").read_bytes() == (SOURCE_DIR / "data/scenarios/hcw_table41_1d.json"
                                                           ).read_bytes()
    assert (site / "thrustsched" / "data" / "campaigns" / "hcw_quick.json").is_file()

    # The commands: the CLI (bad input: exit 2 naming the file) and the campaign runner.
    cli = subprocess.run([str(venv / "bin" / "thrustsched"), "solve", "missing.json", "--out", "o"],
                         capture_output=True, text=True, timeout=120, cwd=tmp_path, env=_environment())
    assert cli.returncode == 2 and "missing.json" in cli.stderr, cli.stdout + cli.stderr
    sweep = subprocess.run([str(venv / "bin" / "thrustsched-sweep"), "--help"], capture_output=True, text=True,
                           timeout=120, cwd=tmp_path, env=_environment())
    assert sweep.returncode == 0 and sweep.stdout.startswith("usage: thrustsched-sweep"), sweep.stderr


def test_a_folder_that_is_not_a_build_tree_is_refused(tmp_path):
    venv = _venv("refused")
    r = _pip_install(venv, f"--config-settings=cmake-build-dir={tmp_path}")
    assert r.returncode != 0
    assert f"{tmp_path} is not a CMake build tree (no CMakeCache.txt)" in r.stdout + r.stderr
    assert not list(venv.glob("lib/python*/site-packages/thrustsched"))
