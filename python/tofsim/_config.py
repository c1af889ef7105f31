"""tofsim.load_config: a config from a file, a YAML string or a dict."""

import json
import os

from . import _tofsim

# Names of configs that have no file: errors name them, and a relative scene
# path is taken from the current folder.
DICT_FILE = "<dict>"
TEXT_FILE = "<string>"


def _json_default(value):
    # NumPy scalars and arrays (a resolution from numpy, a bin count).
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"{type(value).__name__} is not a config value")


def to_json(value):
    """Config values as JSON text, which YAML reads."""
    return json.dumps(value, default=_json_default)


def _yaml_value(value):
    """An override value as YAML text: strings as they are (so "10 ps" keeps
    its unit), everything else as JSON."""
    return value if isinstance(value, str) else to_json(value)


def _override_pairs(overrides):
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [(str(k), _yaml_value(v)) for k, v in overrides.items()]
    pairs = []
    for item in overrides:  # "key.path=value" strings, as the CLI's --set
        key, sep, value = str(item).partition("=")
        if not sep or not key:
            raise ValueError(f"override {item!r} is not key.path=value")
        pairs.append((key, value))
    return pairs


def _is_yaml_text(text):
    # A path has no line breaks and names an existing file; a one-line
    # mapping ("{scene: a.gltf, ...}") is text.
    return "\n" in text or (not os.path.exists(text) and ":" in text and text.lstrip()[:1] == "{")


def load_config(source, overrides=None):
    """Loads and validates a run config, as `tofsim render` does.

    source: a path (str or os.PathLike) to a YAML file, YAML text (a str with
    a line break), a dict in the config's format (configs/README.md), or a
    Config (returned with the overrides applied, when there are any).
    overrides: {"key.path": value} (values: Python numbers, lists, bools, or
    strings with units such as "10 ps") or a list of "key.path=value" strings,
    applied before validation as the CLI's --set.

    Raises ConfigError naming the file, line and column (for a dict: the key
    path only) and the key.
    """
    pairs = _override_pairs(overrides)
    if isinstance(source, _tofsim.Config):
        origin = getattr(source, "_origin", None)
        if origin is None:
            raise ValueError("this Config cannot be reloaded with overrides")
        if not pairs:
            return source
        kind, value, earlier = origin
        return _load(kind, value, earlier + pairs)
    if isinstance(source, dict):
        return _load("dict", to_json(source), pairs)
    if isinstance(source, os.PathLike):
        return _load("file", os.fspath(source), pairs)
    if isinstance(source, str):
        return _load("text" if _is_yaml_text(source) else "file", source, pairs)
    raise TypeError(f"load_config expects a path, YAML text or a dict, not {type(source).__name__}")


def _load(kind, value, pairs):
    if kind == "file":
        config = _tofsim._load_config_file(value, pairs)
    elif kind == "dict":
        config = _tofsim._load_config_text(value, DICT_FILE, pairs, False)
    else:
        config = _tofsim._load_config_text(value, TEXT_FILE, pairs, True)
    # Kept so that render(renderer=...) can reload with one more override.
    config._origin = (kind, value, pairs)
    return config
