"""tofsim.sense: one sensor model on any transient array."""

from . import _tofsim
from ._config import to_json


class SensorResult(dict):
    """Output name -> float32 NumPy array (spad_counts, cwtof_depth, ...), with

    metadata: output name -> {kind, unit, description, colormap, and for
      histogram plots labels, axis_start, axis_step, axis_unit}
    sensor: {name, type, seed, time}; time is the instrument's axis
      {start_s, bin_width_s, bins} for streak and SPAD, else None
    """

    def __init__(self, arrays, metadata, sensor):
        super().__init__(arrays)
        self.metadata = metadata
        self.sensor = sensor


def _axis_of(time):
    if isinstance(time, dict):
        return float(time["start_s"]), float(time["bin_width_s"]), int(time["bins"])
    return float(time.start_s), float(time.bin_width_s), int(time.bins)


def sense(transient, time, sensor, seed=0, direct=None, depth=None):
    """Runs one sensor on a transient.

    transient: (H, W, T, C) array of radiance per bin (float32; converted if not).
    time: a RenderResult's TimeAxis or a dict with start_s, bin_width_s, bins (= T).
    sensor: a dict in the config's sensor format (sensors/README.md), e.g.
      {"type": "spad", "cycles": 100000, "pde": 0.3}.
    seed: the random seed (the CLI uses render.seed); same inputs and seed give
      the same numbers.
    direct: optional (H, W, T, C) direct component; depth: optional (H, W)
      ground-truth depth in metres (both feed CW-ToF's multipath error).

    Raises ConfigError naming the sensor key for a bad parameter.
    """
    start_s, bin_width_s, bins = _axis_of(time)
    shape = getattr(transient, "shape", None)
    if shape is not None and len(shape) == 4 and shape[2] != bins:
        raise ValueError(f"transient has {shape[2]} time bins but time has bins={bins}")
    arrays, metadata, info = _tofsim._sense(
        transient, start_s, bin_width_s, to_json(sensor), int(seed), direct, depth
    )
    return SensorResult(arrays, metadata, info)
