"""pip's build backend for thrustsched (pyproject.toml): setuptools' own,
plus one config setting, cmake-build-dir (a CMake build tree to reuse,
absolute or relative to the source tree), handed to setup.py as the
environment variable THRUSTSCHED_CMAKE_BUILD_DIR:

    pip install --no-build-isolation --no-index --config-settings=cmake-build-dir=build .
"""
import os

from setuptools import build_meta as _setuptools
from setuptools.build_meta import *  # noqa: F401,F403 (the hooks this module does not wrap)

_SETTING = "cmake-build-dir"
_VARIABLE = "THRUSTSCHED_CMAKE_BUILD_DIR"


def _take_setting(config_settings):
    """config_settings without ours (setuptools would pass it on to setup.py's
    command line); ours, when given, goes into the environment."""
    if not config_settings or _SETTING not in config_settings:
        return config_settings
    rest = dict(config_settings)
    value = rest.pop(_SETTING)
    if isinstance(value, list):  # given more than once: the last one
        value = value[-1]
    os.environ[_VARIABLE] = str(value)
    return rest


def get_requires_for_build_wheel(config_settings=None):
    return _setuptools.get_requires_for_build_wheel(_take_setting(config_settings))


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _setuptools.prepare_metadata_for_build_wheel(metadata_directory, _take_setting(config_settings))


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    return _setuptools.build_wheel(wheel_directory, _take_setting(config_settings), metadata_directory)
