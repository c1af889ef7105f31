"""tofsim.sense: one sensor model on any transient array."""

import json
import warnings

from . import _tofsim
from ._config import to_json


class SensorResult(dict):
    """Output name -> float32 NumPy array (spad_counts, cwtof_depth, ...), with

    metadata: output name -> dict, the same as the CLI's
      sensors/<sensor>/<output>.json (less its "files"): shape, axes (names
      of the dimensions: y, x, t, frequency, phase_step, pixel), axes_doc,
      unit, description, signed, attributes (e.g. frequency_Hz, range_m),
      time (the instrument's axis: start_s, bin_width_s, bins, end_s and the
      same in metres) where an axis is t, picture (colormap) where the CLI
      draws one, and sensor (name, type, seed, parameters in SI units,
      render_time, warnings)
    sensor: {name, type, seed, parameters, render_time, warnings, time}; time
      is the instrument's axis {start_s, bin_width_s, bins} for streak and
      SPAD, else None
    warnings: what the model says about these inputs (e.g. a scene deeper
      than a CW-ToF's unambiguous range); each is also issued as a
      SensorWarning through Python's warnings module
    """

    def __init__(self, arrays, metadata, sensor, warnings):
        super().__init__(arrays)
        self.metadata = metadata
        self.sensor = sensor
        self.warnings = warnings


class SensorWarning(UserWarning):
    """A sensor's outputs may mislead for these inputs (see the message)."""


def _sensor_info(metadata):
    first = next(iter(metadata.values()))
    sensor = dict(first["sensor"])
    sensor["time"] = None
    for meta in metadata.values():
        if "time" in meta:
            t = meta["time"]
            sensor["time"] = {k: t[k] for k in ("start_s", "bin_width_s", "bins")}
            break
    return sensor


def read_array(path):
    """A tofsim output array as a float32 NumPy array: a .npy file, or an
    OpenEXR image (.exr, read by tofsim itself: (H, W, C))."""
    import os

    import numpy

    path = os.fspath(path)
    if path.endswith(".exr"):
        return _tofsim._read_exr(path)
    return numpy.load(path)


def load_sensors(folder):
    """The sensors a render wrote under folder/sensors/<sensor>/ (the CLI's
    files, or render(..., output_dir=folder)): sensor name -> SensorResult,
    the arrays read from each output's .npy (every output has one: an
    Array's data, an Image's `files.npy`), the metadata from its JSON (less
    `files`, as tofsim.sense gives it). Pictures (.png) are not read; their
    metadata is there. {} when the run had no sensors."""
    import os

    root = os.path.join(os.fspath(folder), "sensors")
    if not os.path.isdir(root):
        return {}
    results = {}
    for name in sorted(os.listdir(root)):
        directory = os.path.join(root, name)
        if not os.path.isdir(directory):
            continue
        arrays, metadata = {}, {}
        for entry in sorted(os.listdir(directory)):
            if not entry.endswith(".json"):
                continue
            with open(os.path.join(directory, entry)) as f:
                meta = json.load(f)
            if meta.get("format") != "tofsim sensor output":
                continue
            files = meta.pop("files", {})
            data = files.get("npy") or files.get("data")
            if data is not None:
                arrays[meta["name"]] = read_array(os.path.join(directory, data))
            metadata[meta["name"]] = meta
        if metadata:
            info = _sensor_info(metadata)
            results[name] = SensorResult(arrays, metadata, info, list(info.get("warnings", [])))
    return results


def _axis_of(time):
    if isinstance(time, dict):
        return float(time["start_s"]), float(time["bin_width_s"]), int(time["bins"])
    return float(time.start_s), float(time.bin_width_s), int(time.bins)


def sense(transient, time, sensor, seed=0, direct=None, depth=None, bounces=None):
    """Runs one sensor on a transient.

    transient: (H, W, T, C) array of radiance per bin (float32; converted if not).
    time: a RenderResult's TimeAxis or a dict with start_s, bin_width_s, bins (= T).
    sensor: a dict in the config's sensor format (sensors/README.md), e.g.
      {"type": "spad", "cycles": 100000, "pde": 0.3}.
    seed: the random seed (the CLI uses render.seed); same inputs and seed give
      the same numbers.
    direct: optional (H, W, T, C) direct component; depth: optional (H, W)
      ground-truth depth in metres (both feed CW-ToF's multipath error).
    bounces: optional list of N (H, W, T, C) arrays, the light of exactly
      1 .. N indirect bounces (a render's bounce1.npy .. bounce<N>.npy, written
      with output.components); a cwtof sensor with multipath_by_order needs
      them with direct and depth, and returns cwtof_multipath_error_by_order
      ((N + 1, H, W): order k = the depth of direct + bounces 1..k - depth).

    Raises ConfigError naming the sensor key for a bad parameter (key
    multipath_by_order when bounces, direct or depth is missing for it); issues a
    SensorWarning for each of the model's warnings (also in result.warnings).
    """
    start_s, bin_width_s, bins = _axis_of(time)
    shape = getattr(transient, "shape", None)
    if shape is not None and len(shape) == 4 and shape[2] != bins:
        raise ValueError(f"transient has {shape[2]} time bins but time has bins={bins}")
    arrays, texts, messages = _tofsim._sense(
        transient, start_s, bin_width_s, to_json(sensor), int(seed), direct, depth,
        None if bounces is None else list(bounces),
    )
    result = sensor_result(arrays, texts, messages)
    for message in result.warnings:
        warnings.warn(f"sensor '{result.sensor['name']}' ({result.sensor['type']}): {message}",
                      SensorWarning, stacklevel=2)
    return result


def sensor_result(arrays, texts, messages):
    """A SensorResult from what the native module returns (arrays, metadata
    as JSON text, warnings)."""
    metadata = {name: json.loads(text) for name, text in texts.items()}
    return SensorResult(arrays, metadata, _sensor_info(metadata), list(messages))
