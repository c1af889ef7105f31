"""tofsim: transient (time-of-flight) rendering and ToF sensor models in Python.

    import tofsim
    config = tofsim.load_config("configs/cornell_box.yaml", overrides={"time.bins": 300})
    result = tofsim.render(config)           # NumPy arrays, no files
    renderer = tofsim.Renderer(config)       # the scene prepared once
    moved = renderer.render({"light.position": [0.3, 0.5, -0.8]})
    result.transient.shape                   # (H, W, T, C) float32
    spad = tofsim.sense(result.transient, result.time,
                        {"type": "spad", "cycles": 10000, "pde": 0.3})
    spad["spad_counts"].shape                # (H, W, bins)
    saved = tofsim.load("out")               # a render's folder (.npy or capture.h5)
    saved.sensors["spad"]["spad_depth_first"]  # its sensors' outputs, with .metadata
    tofsim.read_array("out/sensors/spad/spad_confidence.exr")  # .npy or .exr

Configs are validated exactly as by the `tofsim` command (configs/README.md);
bad input raises ConfigError (a ValueError) with file, line, column and key.
"""

from ._tofsim import Config, ConfigError
from ._config import load_config
from ._render import NlosResult, Renderer, RenderResult, SequenceResult, TimeAxis, load, render
from ._sense import SensorResult, SensorWarning, load_sensors, read_array, sense

__all__ = [
    "Config",
    "ConfigError",
    "NlosResult",
    "Renderer",
    "RenderResult",
    "SensorResult",
    "SequenceResult",
    "SensorWarning",
    "TimeAxis",
    "load",
    "load_config",
    "load_sensors",
    "read_array",
    "render",
    "sense",
]
