"""The CMake step of `pip install .` (the package's metadata is pyproject.toml).

    pip install --no-build-isolation --no-index .                         # a CMake build of its own
    pip install --no-build-isolation --no-index --config-settings=cmake-build-dir=build .   # reuse build/
    THRUSTSCHED_CMAKE_BUILD_DIR=build pip install --no-build-isolation --no-index .         # the same

The extension thrustsched._core is the CMake target thrustsched_python
(python/CMakeLists.txt). With a CMake build tree given (absolute, or relative
to this source tree), only that target is brought up to date there; the tree
must be configured from this source tree for the interpreter running pip
(its module's file name says which). Without one, the project is configured
in build-pip/cmake (Release, no tests, no benchmarks; CMAKE_ARGS adds
options, e.g. CMAKE_ARGS=-DCMAKE_CXX_COMPILER_LAUNCHER=ccache) and that
target built with CMAKE_BUILD_PARALLEL_LEVEL jobs (default: every core); a
second install rebuilds only what changed. The module and the package's
shipped data (the build tree's python/thrustsched/data) are copied into the
wheel. setuptools' own files go to build-pip/ (or, reusing a tree, to
<tree>/pip), never into the sources. Editable installs are refused: use the
build tree's package (PYTHONPATH=build/python) instead.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent
BUILD_DIR_VARIABLE = "THRUSTSCHED_CMAKE_BUILD_DIR"  # set from --config-settings=cmake-build-dir=... too
TARGET = "thrustsched_python"


def _version() -> str:
    text = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(thrustsched\s+VERSION\s+([0-9.]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no project(thrustsched VERSION ...) line")
    return match.group(1)


def _given_build_dir():
    value = os.environ.get(BUILD_DIR_VARIABLE, "").strip()
    if not value:
        return None
    path = Path(value).expanduser()
    return (path if path.is_absolute() else SOURCE_DIR / path).resolve()


def _cache_value(cache: Path, name: str):
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1]
    return None


def _check_given_build_dir(build_dir: Path) -> None:
    """A clear error unless build_dir is a CMake tree of this source tree."""
    cache = build_dir / "CMakeCache.txt"
    if not cache.is_file():
        raise RuntimeError(f"{BUILD_DIR_VARIABLE} (cmake-build-dir): {build_dir} is not a CMake build tree "
                           f"(no CMakeCache.txt); configure it first: cmake -S {SOURCE_DIR} -B {build_dir}")
    home = _cache_value(cache, "CMAKE_HOME_DIRECTORY")
    if home is None or Path(home).resolve() != SOURCE_DIR:
        raise RuntimeError(f"{BUILD_DIR_VARIABLE} (cmake-build-dir): {build_dir} was configured from {home}, "
                           f"not from this source tree ({SOURCE_DIR})")


def _run(command, what: str) -> None:
    print("setup.py:", " ".join(shlex.quote(str(c)) for c in command), flush=True)
    if subprocess.call([str(c) for c in command]) != 0:
        raise RuntimeError(f"{what} failed (command above)")


def _setuptools_dir() -> Path:
    given = _given_build_dir()
    return given / "pip" if given is not None else SOURCE_DIR / "build-pip"


class CMakeBuildExt(build_ext):
    """Builds thrustsched._core with CMake and copies it (and the shipped data) into the wheel."""

    def build_extension(self, ext: Extension) -> None:
        if self.inplace:
            raise RuntimeError("editable installs (pip install -e) are not supported: build with CMake and use "
                               "PYTHONPATH=build/python, or install without -e")
        build_dir = _given_build_dir()
        if build_dir is not None:
            _check_given_build_dir(build_dir)
        else:
            build_dir = SOURCE_DIR / "build-pip" / "cmake"
            _run(["cmake", "-S", SOURCE_DIR, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                  f"-DPython_EXECUTABLE={sys.executable}", "-DBUILD_TESTING=OFF",
                  "-DTHRUSTSCHED_BUILD_BENCHMARKS=OFF", *shlex.split(os.environ.get("CMAKE_ARGS", ""))],
                 "configuring the C++ project")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        _run(["cmake", "--build", build_dir, "--target", TARGET, "--parallel", jobs],
             f"building {TARGET} in {build_dir} (the Python package needs THRUSTSCHED_BUILD_PYTHON=ON, "
             "pybind11-dev, python3-dev and no sanitizers)")
        package = build_dir / "python" / "thrustsched"
        module = package / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not module.is_file():
            found = sorted(p.name for p in package.glob("_core*"))
            raise RuntimeError(f"{module} not found ({found or 'no module'}): {build_dir} was configured for "
                               f"another interpreter than {sys.executable}; configure it with "
                               f"-DPython_EXECUTABLE={sys.executable} or give no build tree")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, target)
        data = target.parent / "data"
        if data.exists():
            shutil.rmtree(data)
        shutil.copytree(package / "data", data)  # the build tree's links to data/ are followed


_SETUPTOOLS_DIR = _setuptools_dir()
_SETUPTOOLS_DIR.mkdir(parents=True, exist_ok=True)

setup(
    version=_version(),
    ext_modules=[Extension("thrustsched._core", sources=[])],
    cmdclass={"build_ext": CMakeBuildExt},
    options={"build": {"build_base": str(_SETUPTOOLS_DIR)}, "egg_info": {"egg_base": str(_SETUPTOOLS_DIR)}},
)
