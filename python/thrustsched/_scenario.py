"""Scenario files as plain dicts, validated by the C++ parser (the CLI's).

    scn = Scenario.load("data/scenarios/geo_week_anzel4.json")
    scn["model"]["station_longitude_deg"] = 75      # same fields as the JSON
    scn.validate()                                  # ScenarioError (a ValueError) naming the field
"""
from __future__ import annotations

import copy
import json
import math
import os
from collections.abc import Mapping, MutableMapping
from typing import Any, Iterator, Optional, Tuple, Union

from . import _core

ScenarioError = _core.ScenarioError
PathLike = Union[str, "os.PathLike[str]"]


def _check_finite(value: Any, path: str) -> None:
    """JSON has no NaN or infinity: name the field as the parser would."""
    if isinstance(value, float) and not math.isfinite(value):
        raise ScenarioError(f"{path}: must be a finite number, got {value}")
    if isinstance(value, dict):
        for k, v in value.items():
            _check_finite(v, f"{path}.{k}")
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            _check_finite(v, f"{path}[{i}]")


def _document_text(document: Any, kind: str, caller: str) -> Tuple[str, Optional[str]]:
    """The JSON text of a file path or a dict, and the path (None for a
    dict): what the commands that take a whole document (transfer, fleet)
    hand to the C++ parser. ``kind`` names the document in messages."""
    if isinstance(document, (str, os.PathLike)):
        source = os.fspath(document)
        if os.path.isdir(source):
            raise ScenarioError(f"{source}: is a folder, not a {kind} file")
        with open(source, "r", encoding="utf-8") as f:
            return f.read(), source
    if isinstance(document, Mapping):
        _check_finite(dict(document), "scenario")
        return json.dumps(dict(document)), None
    raise TypeError(f"{caller}: scenario must be a path or a dict, got {type(document).__name__}")


class Scenario(MutableMapping):
    """A scenario: the content of a scenario file as a dict.

    Every field is the JSON file's (documented in data/scenarios/README.md);
    nested sections are plain dicts and lists, edited in place::

        scn = Scenario.load("data/scenarios/hcw_table41_1d.json")
        scn["horizon"]["duration_s"] = 2 * 86400
        res = thrustsched.solve(scn)

    Validation is the CLI's parser, run by :meth:`load` / :meth:`from_dict`
    (unless ``validate=False``) and again on every solve, check or export: a
    bad field raises :class:`ScenarioError` (a ``ValueError``) whose message
    starts with the field path and quotes the value, exactly as
    ``thrustsched solve`` prints it. ``path`` (the file it came from) names
    it in messages and resolves relative paths inside it (e.g. an OPM file).
    """

    def __init__(self, data: Optional[dict] = None, path: Optional[PathLike] = None):
        self._data: dict = copy.deepcopy(dict(data)) if data is not None else {}
        self.path: Optional[str] = os.fspath(path) if path is not None else None

    # -- construction ---------------------------------------------------------
    @classmethod
    def load(cls, path: PathLike, validate: bool = True) -> "Scenario":
        """Reads a scenario file. Raises ScenarioError (ValueError) on a bad field
        or malformed JSON (duplicate keys included), OSError if unreadable."""
        path = os.fspath(path)
        if os.path.isdir(path):
            raise ScenarioError(f"{path}: is a folder, not a scenario file")
        with open(path, "r", encoding="utf-8") as f:
            text = f.read()
        if validate:
            if '"long_horizon"' in text:
                cls(json.loads(text), path).validate()
            else:
                _core.parse_scenario(text, path)
        else:
            _core.parse_json_text(text, path)
        return cls(json.loads(text), path)

    @classmethod
    def from_dict(cls, data: dict, validate: bool = True, path: Optional[PathLike] = None) -> "Scenario":
        """A scenario from a dict (deep-copied). ``path``, if given, resolves
        relative paths inside it as if it had been read from there."""
        s = cls(data, path)
        if validate:
            s.validate()
        return s

    # -- the C++ view ------------------------------------------------------------
    def to_json(self, indent: Optional[int] = 2) -> str:
        _check_finite(self._data, "scenario")
        return json.dumps(self._data, indent=indent)

    def parsed(self) -> "_core.ParsedScenario":
        """The scenario as the C++ parser understands it (read-only; re-parsed each call)."""
        return _core.parse_scenario(self.to_json(indent=None), self.path or "scenario")

    def validate(self) -> "Scenario":
        """Parses with the CLI's parser (``simulate``'s when there is a
        "long_horizon" section); returns self. Raises ScenarioError."""
        if "long_horizon" in self._data:
            _core.parse_simulation(self.to_json(indent=None), self.path or "scenario")
        else:
            self.parsed()
        return self

    @property
    def info(self) -> "_core.ParsedScenario":
        """Parsed facts: grid, thruster names, window, model type, ..."""
        return self.parsed()

    @property
    def name(self) -> str:
        return str(self._data.get("name", ""))

    # -- dict interface ------------------------------------------------------------
    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self._data[key] = value

    def __delitem__(self, key: str) -> None:
        del self._data[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def to_dict(self) -> dict:
        """A deep copy of the content."""
        return copy.deepcopy(self._data)

    def copy(self) -> "Scenario":
        return Scenario(self._data, self.path)

    def save(self, path: PathLike) -> None:
        """Writes the scenario as JSON (indent 2)."""
        with open(os.fspath(path), "w", encoding="utf-8") as f:
            f.write(self.to_json() + "\n")

    def __repr__(self) -> str:
        where = f", path={self.path!r}" if self.path else ""
        return f"Scenario(name={self.name!r}{where})"


def as_scenario(obj: Any) -> Scenario:
    """A Scenario from a Scenario, a dict or a file path."""
    if isinstance(obj, Scenario):
        return obj
    if isinstance(obj, dict):
        return Scenario.from_dict(obj, validate=False)
    if isinstance(obj, (str, os.PathLike)):
        return Scenario.load(obj)
    raise TypeError(f"expected a Scenario, a dict or a scenario file path, got {type(obj).__name__}")
