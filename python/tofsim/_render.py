"""tofsim.render: a config rendered into NumPy arrays."""

from dataclasses import dataclass, field

from . import _tofsim
from ._config import load_config
from ._sense import load_sensors, sensor_result


@dataclass(frozen=True)
class TimeAxis:
    """Bin i covers arrival times [start_s + i bin_width_s, start_s + (i+1) bin_width_s),
    measured from the light's emission; *_m are the same as optical path length (c t)."""

    start_s: float
    bin_width_s: float
    bins: int
    start_m: float
    bin_width_m: float

    def bin_starts_s(self):
        """Leading edge of every bin, seconds (a NumPy array of `bins` values)."""
        import numpy

        return self.start_s + self.bin_width_s * numpy.arange(self.bins)


@dataclass
class RenderResult:
    """What tofsim.render returns. Arrays are float32 NumPy arrays that own
    their memory; a volume the run did not produce is None.

    transient: (H, W, T, C) radiance per time bin, direct + indirect
    direct, indirect: (H, W, T, C) the components (transient == direct + indirect)
    bounces: list of N (H, W, T, C) arrays, the light of exactly 1 .. N indirect
      bounces (IR with render.indirect.bounces N; indirect == their float sum;
      for N = 1 the list holds the indirect array itself); with output_dir the
      bounce<k>.npy the run wrote (output.components); None otherwise (the
      reference renderer, indirect light off). In memory, N > 1 costs N more
      volumes.
    depth: (H, W) camera-to-surface distance, metres; 0 where no surface
    steady: (H, W, C) transient summed over time
    time: the TimeAxis of the T bins
    stats: transient.json's stats (seconds, segments, vpls, sampled_pixels
        (render.adaptive_pixel_samples), energy_on_axis, energy_before/after_axis,
        fraction_before/after_axis, rejected_non_finite_values, pass_seconds (IR's
        time by pass), ...), and off_axis_before/after (= energy_before/after_axis)
    device: what rendered it (GL renderer string, or the CPU reference)
    files: written files, relative to output_dir (empty without one)
    sensors: the config's sensors: name -> SensorResult (output name -> array,
      with .metadata, .sensor and .warnings, as tofsim.sense returns), the
      CLI's outputs read back from sensors/<name>/; {} without sensors
    """

    transient: object
    direct: object
    indirect: object
    bounces: object
    depth: object
    steady: object
    time: TimeAxis
    stats: dict
    device: str
    files: list
    output_dir: object = None
    sensors: dict = field(default_factory=dict)


@dataclass
class NlosResult:
    """What tofsim.render returns for an `nlos:` config (configs/README.md,
    `nlos`), in y-tal's vocabulary (tal.io.read_capture's fields).

    H: float32, (T, sx, sy) for single and confocal scans, (T, lx, ly, sx, sy)
      for exhaustive ones: radiance per bin at each sensor point, summed over
      R, G, B; None with output_dir when output.transient is false
    H_format: "T_Sx_Sy" or "T_Lx_Ly_Sx_Sy"
    scan: "single", "confocal" or "exhaustive"
    sensor_grid_xyz, laser_grid_xyz: (X, Y, 3) wall points, x index major
    wall_normal, sensor_xyz, laser_xyz: [x, y, z]
    t_accounts_first_and_last_bounces: the time convention (nlos.account_first_and_last_bounces)
    time: the TimeAxis of the T bins (start_m, bin_width_m: y-tal's t_start, delta_t)
    stats: H.json's stats (render_seconds, captures (laser positions),
        scene_preparations, vpls, device), and seconds (= render_seconds)
    device, files, output_dir: as for RenderResult
    """

    H: object
    H_format: str
    scan: str
    sensor_grid_xyz: object
    laser_grid_xyz: object
    wall_normal: list
    sensor_xyz: list
    laser_xyz: list
    t_accounts_first_and_last_bounces: bool
    time: TimeAxis
    stats: dict
    device: str
    files: list
    output_dir: object = None


@dataclass
class SequenceResult:
    """What tofsim.render returns for a `sequence:` config (configs/README.md,
    `sequence`): each frame's arrays stacked along a leading frame axis F,
    frame k at times_s[k]; an array the run did not write is None.

    times_s: (F,) float64, the frames' times, seconds of scene time
    transient, direct, indirect: (F, H, W, T, C), as RenderResult's per frame
    depth: (F, H, W) camera-to-surface distance, metres (depth_sequence.npy)
    steady: (F, H, W, C) each frame's steady image (steady.exr, output.steady)
    scene_flow: (F, H, W, 3) metres, optical_flow: (F, H, W, 2) pixels: the
      motion of each pixel's surface to the next frame (frame k's
      scene_flow.npy, optical_flow.npy); NaN where no surface and all of the
      last frame, which has no next one
    time: the TimeAxis of the T bins
    frames: sequence.json's frame records (index, time_s, seed, folder)
    files: written files, relative to output_dir
    output_dir: where the frames were written (None: a temporary folder,
      removed once read)
    """

    times_s: object
    transient: object
    direct: object
    indirect: object
    depth: object
    steady: object
    scene_flow: object
    optical_flow: object
    time: TimeAxis
    frames: list
    files: list
    output_dir: object = None


def _stack_frames(folder, frames, name):
    """The frames' `name` arrays stacked on a leading axis (name.npy, or its
    dataset of the frame's capture.h5); None when frame 0 has none; frames
    without one (the last frame's flow) are NaN."""
    import os

    import numpy

    arrays = []
    for f in frames:
        path = os.path.join(folder, f["folder"], name)
        capture = os.path.join(folder, f["folder"], "capture.h5")  # output.format hdf5
        if os.path.exists(path):
            arrays.append(numpy.load(path))
        elif os.path.exists(capture):
            arrays.append(_tofsim._read_capture(capture, name[: -len(".npy")]))
        else:
            arrays.append(None)
    present = [a for a in arrays if a is not None]
    if not present:
        return None
    nan = numpy.full(present[0].shape, numpy.nan, dtype=present[0].dtype)
    return numpy.stack([nan if a is None else a for a in arrays])


def _stack_steady(folder, frames):
    """The frames' steady.exr (output.steady) on a leading axis, or None."""
    import os

    import numpy

    paths = [os.path.join(folder, f["folder"], "steady.exr") for f in frames]
    if not all(os.path.exists(p) for p in paths):
        return None
    return numpy.stack([_tofsim._read_exr(p) for p in paths])


def _render_sequence(config, output_dir, quiet):
    import json
    import os
    import tempfile

    import numpy

    with tempfile.TemporaryDirectory(prefix="tofsim-sequence-") as scratch:
        folder = scratch if output_dir is None else str(output_dir)
        out = _tofsim._render(config, folder, quiet)
        with open(os.path.join(folder, "sequence.json"), encoding="utf-8") as f:
            frames = json.load(f)["frames"]
        transient = _stack_frames(folder, frames, "transient.npy")
        depth_file = os.path.join(folder, "depth_sequence.npy")
        return SequenceResult(
            times_s=numpy.array([f["time_s"] for f in frames], dtype=numpy.float64),
            transient=transient,
            direct=_stack_frames(folder, frames, "direct.npy"),
            indirect=_stack_frames(folder, frames, "indirect.npy"),
            depth=numpy.load(depth_file) if os.path.exists(depth_file) else None,
            steady=_stack_steady(folder, frames),
            scene_flow=_stack_frames(folder, frames, "scene_flow.npy"),
            optical_flow=_stack_frames(folder, frames, "optical_flow.npy"),
            time=TimeAxis(**out["time"]),
            frames=frames,
            files=out["files"],
            output_dir=output_dir,
        )


def render(config, renderer=None, backend=None, output_dir=None, quiet=True):
    """Renders a config (a Config, or anything load_config takes): a
    RenderResult, an NlosResult for a config with `nlos:`, or a
    SequenceResult (arrays with a leading frame axis) for one with
    `sequence:` (written to output_dir, or to a temporary folder that is
    removed once read).

    renderer: "ir" or "reference", overriding render.renderer.
    backend: overrides render.backend (rejected as an unknown key where this
    build has no such key).
    output_dir: also write every output of `tofsim render` there (the arrays
    are then read back from those files: a volume the config does not write
    is None). Without it nothing is written, except for a config with
    sensors: it runs as `tofsim render` into a temporary folder, removed once
    read, so that result.sensors are the CLI's numbers (its volumes are then
    those the config writes).
    quiet: False prints progress and warnings on stderr, as the CLI does.

    The GIL is released while rendering; Ctrl-C raises KeyboardInterrupt
    (and, with output_dir, leaves earlier results there untouched).
    """
    overrides = {}
    if renderer is not None:
        overrides["render.renderer"] = renderer
    if backend is not None:
        overrides["render.backend"] = backend
    config = load_config(config, overrides)
    if config.frame_times_s is not None:
        return _render_sequence(config, output_dir, quiet)
    if output_dir is None and config.sensors and not config.is_nlos:
        return _render_with_sensors(config, quiet)
    out = _tofsim._render(config, None if output_dir is None else str(output_dir), quiet)
    out["time"] = TimeAxis(**out["time"])
    out["output_dir"] = output_dir
    if "H_format" in out:
        return NlosResult(**out)
    if output_dir is not None:
        out["sensors"] = load_sensors(output_dir)
    return RenderResult(**out)


def _render_with_sensors(config, quiet):
    """A camera config with sensors and no output_dir: the CLI's run into a
    temporary folder (removed once read), so that result.sensors holds the
    CLI's numbers; the volumes are those the config writes (None where
    output.transient or output.components leave one out)."""
    import tempfile

    with tempfile.TemporaryDirectory(prefix="tofsim-render-") as scratch:
        out = _tofsim._render(config, scratch, quiet)
        out["time"] = TimeAxis(**out["time"])
        out["output_dir"] = None
        out["files"] = []
        out["sensors"] = load_sensors(scratch)
    return RenderResult(**out)


class Renderer:
    """A scene prepared once, rendered many times: for dataset generation,
    sweeps and optimisation loops, where tofsim.render would load the glTF,
    make the renderer (its GL context or CPU threads) and build the scene's
    buffers and BVH again for every capture.

        r = tofsim.Renderer("configs/cornell_box.yaml", overrides={"sensors": []})
        for x in numpy.linspace(0.1, 0.5, 100):
            result = r.render({"light.position": [x, 0.5, -0.8]})  # a RenderResult

    config, overrides, renderer, backend: as for tofsim.render; they fix the
    scene (render.scene), render.renderer, render.backend and render.threads.
    render(overrides) renders that config with further overrides (a dict or
    "key.path=value" strings: another camera, light, time axis or render
    settings, each render validated as tofsim.render's) into NumPy arrays,
    without files, the same bytes as tofsim.render of the same config, and
    the config's sensors run on them in memory (result.sensors, with the
    run's seed: the numbers `tofsim render` writes); an
    override of what the Renderer was made from raises ValueError. Camera
    captures only (not `nlos:` nor `sequence:` configs). Use it from one
    thread at a time.
    """

    def __init__(self, config, overrides=None, renderer=None, backend=None, quiet=True):
        extra = {}
        if renderer is not None:
            extra["render.renderer"] = renderer
        if backend is not None:
            extra["render.backend"] = backend
        self._config = load_config(config, overrides)
        if extra:
            self._config = load_config(self._config, extra)
        self._native = _tofsim._Renderer(self._config, quiet)

    @property
    def config(self):
        """The Config every render starts from."""
        return self._config

    @property
    def device(self):
        """What renders (the GL renderer string, or the CPU backend)."""
        return self._native.device()

    @property
    def scene_preparations(self):
        """How many times the scene was prepared (buffers, BVH): 1 after any
        number of renders with instant radiosity; 0 for the reference renderer."""
        return self._native.scene_preparations()

    def render(self, overrides=None):
        config = self._config if not overrides else load_config(self._config, overrides)
        out = self._native.render(config)
        out["time"] = TimeAxis(**out["time"])
        out["output_dir"] = None
        out["sensors"] = {
            name: sensor_result(*native) for name, native in out["sensors"].items()
        }
        return RenderResult(**out)


def load(folder):
    """Reads back the output folder of a camera render (`tofsim render -o
    folder` or render(..., output_dir=folder)) as a RenderResult: its .npy
    files, or with output.format hdf5 the datasets of its capture.h5 (read
    by tofsim itself: h5py is not needed). The time axis, stats and device
    come from transient.json; a volume the run did not write is None;
    steady is capture.h5's steady, else steady.exr, else the transient summed
    over time; sensors are the run's sensors/<name>/ outputs (load_sensors)."""
    import json
    import os

    import numpy

    folder = os.fspath(folder)
    with open(os.path.join(folder, "transient.json")) as f:
        meta = json.load(f)
    capture = os.path.join(folder, "capture.h5")
    in_capture = os.path.exists(capture)

    def read(name):
        if in_capture:
            return _tofsim._read_capture(capture, name)
        path = os.path.join(folder, name + ".npy")
        return numpy.load(path) if os.path.exists(path) else None

    bounces = []
    while len(bounces) < 8:
        bounce = read("bounce%d" % (len(bounces) + 1))
        if bounce is None:
            break
        bounces.append(bounce)
    transient = read("transient")
    depth = read("depth")
    if depth is None and os.path.exists(os.path.join(folder, "depth.npy")):
        depth = numpy.load(os.path.join(folder, "depth.npy"))
    steady = _tofsim._read_capture(capture, "steady") if in_capture else None
    if steady is None and os.path.exists(os.path.join(folder, "steady.exr")):
        steady = _tofsim._read_exr(os.path.join(folder, "steady.exr"))
    if steady is None and transient is not None:
        steady = transient.sum(axis=2)
    t = meta["time"]
    files = []
    for root, _, names in os.walk(folder):
        for name in names:
            if not name.startswith("."):
                files.append(os.path.relpath(os.path.join(root, name), folder))
    return RenderResult(
        transient=transient,
        direct=read("direct"),
        indirect=read("indirect"),
        bounces=bounces or None,
        depth=depth,
        steady=steady,
        time=TimeAxis(t["start_s"], t["bin_width_s"], t["bins"], t["start_m"], t["bin_width_m"]),
        stats=meta.get("stats", {}),
        device=meta.get("device", ""),
        files=sorted(files),
        output_dir=folder,
        sensors=load_sensors(folder),
    )
