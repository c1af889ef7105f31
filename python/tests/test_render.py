"""tofsim.render against closed forms, and the arrays' memory."""

import gc
import os
import signal
import threading
import time

import numpy as np
import pytest

import tofsim
from conftest import SOURCE_DIR, pixel_directions, write_plane_gltf

CORNELL = os.path.join(SOURCE_DIR, "configs", "cornell_box.yaml")


def expected_bins(config, time_axis):
    """Round-trip path camera -> plane -> camera (light at the camera) in bins;
    -1 within 2 % of a bin edge, where float rounding may pick either side."""
    cam = config["camera"]
    w, h = cam["resolution"]
    d = pixel_directions(cam["position"], cam["look_at"], cam["fov_y"], w, h)
    o = np.asarray(cam["position"], float)
    t = -o[2] / d[..., 2]
    r = np.linalg.norm(d * t[..., None], axis=2)
    f = (2 * r - time_axis.start_m) / time_axis.bin_width_m
    frac = f - np.floor(f)
    return np.where((frac < 0.02) | (frac > 0.98), -1, np.floor(f).astype(int))


def peak_bins(volume, channel=0):
    v = volume[..., channel]
    return np.where(v.max(axis=2) > 0, v.argmax(axis=2), -1)


def test_plane_peaks_land_in_the_bin_of_the_round_trip(plane_config):
    result = tofsim.render(plane_config)
    assert result.transient.shape == (30, 40, 1200, 3)
    assert result.transient.dtype == np.float32
    assert result.depth.shape == (30, 40)
    assert result.steady.shape == (30, 40, 3)
    assert result.time.bins == 1200
    assert result.time.bin_width_m == pytest.approx(0.002)
    assert result.time.start_m == pytest.approx(2.5)
    expected = expected_bins(plane_config, result.time)
    checked = expected >= 0
    assert checked.sum() > 1000
    np.testing.assert_array_equal(peak_bins(result.direct)[checked], expected[checked])
    np.testing.assert_array_equal(result.transient, result.direct + result.indirect)
    np.testing.assert_allclose(result.steady, result.transient.sum(axis=2, dtype=np.float64),
                               rtol=1e-6)
    assert result.files == []
    assert not os.path.exists(plane_config["output"]["directory"])


def test_depth_is_the_distance_to_the_plane(plane_config):
    result = tofsim.render(plane_config)
    cam = plane_config["camera"]
    d = pixel_directions(cam["position"], cam["look_at"], cam["fov_y"], 40, 30)
    expected = 1.5 / -d[..., 2]
    np.testing.assert_allclose(result.depth, expected, rtol=1e-4)


def test_output_dir_writes_the_cli_files_and_returns_the_same_arrays(plane_config, tmp_path):
    out = tmp_path / "files"
    plane_config["output"]["components"] = ["direct", "indirect"]
    in_memory = tofsim.render(plane_config)
    written = tofsim.render(plane_config, output_dir=out)
    for name in ("transient.npy", "direct.npy", "indirect.npy", "depth.exr", "depth.npy",
                 "steady.exr", "transient.json", "config.effective.yaml"):
        assert name in written.files
        assert (out / name).exists(), name
    np.testing.assert_array_equal(np.load(out / "transient.npy"), written.transient)
    np.testing.assert_array_equal(written.transient, in_memory.transient)
    np.testing.assert_array_equal(written.direct, in_memory.direct)
    np.testing.assert_array_equal(np.load(out / "depth.npy"), in_memory.depth)


def test_opencv_reads_depth_exr(plane_config, tmp_path):
    """cv2.imread sees depth.exr's Y channel (it ignores Z). Runs where
    python3-opencv is installed; the C++ test DepthExrOpenCvTest checks the
    same OpenCV reader everywhere."""
    os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")  # pip wheels need it
    cv2 = pytest.importorskip("cv2")
    out = tmp_path / "files"
    result = tofsim.render(plane_config, output_dir=out)
    depth = cv2.imread(str(out / "depth.exr"), cv2.IMREAD_UNCHANGED)
    assert depth is not None and depth.dtype == np.float32
    np.testing.assert_array_equal(depth, result.depth)


def test_reference_renderer_by_argument(plane_config):
    plane_config["camera"]["resolution"] = [8, 6]
    plane_config["time"]["bins"] = 200
    plane_config["time"]["bin_width"] = "1 cm"
    result = tofsim.render(plane_config, renderer="reference")
    assert "reference" in result.device.lower() or "cpu" in result.device.lower()
    assert result.transient.shape == (6, 8, 200, 3)
    assert result.steady.sum() > 0


def test_backend_is_a_config_key(plane_config):
    # render.backend is validated like any key.
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.render(plane_config, backend="no-such-backend")
    assert e.value.key == "render.backend"


def test_both_backends_render_the_same_plane(plane_config):
    cpu = tofsim.render(plane_config, backend="cpu")
    gl = tofsim.render(plane_config, backend="gl")
    # Same peak bins everywhere the plane is lit, the same energy within float rounding.
    lit = cpu.steady[..., 0] > 0
    assert lit.sum() > 1000
    assert (cpu.transient[..., 0].argmax(axis=2)[lit] == gl.transient[..., 0].argmax(axis=2)[lit]).mean() > 0.999
    assert abs(cpu.steady.sum() / gl.steady.sum() - 1) < 1e-3


def test_arrays_keep_their_memory_after_the_result_is_gone(plane_config):
    plane_config["camera"]["resolution"] = [8, 6]
    result = tofsim.render(plane_config)
    transient, depth = result.transient, result.depth
    expected = transient.copy()
    assert transient.base is not None  # a view of memory the array's base owns
    del result
    gc.collect()
    filler = [np.full(transient.shape, 7.0, np.float32) for _ in range(4)]  # reuse freed memory
    np.testing.assert_array_equal(transient, expected)
    assert depth.min() > 1.0
    del filler


def test_ctrl_c_interrupts_a_render():
    # A render that takes minutes: the reference path tracer in the Cornell
    # box at many paths per pixel, in many segments.
    config = tofsim.load_config(CORNELL, overrides={
        "sensors": [], "camera.resolution": [64, 64], "render.memory_budget": "1 MiB",
        "render.reference": {"samples_per_pixel": 1 << 16, "bounces": 4}})
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            tofsim.render(config, renderer="reference")
    finally:
        timer.cancel()
    assert time.monotonic() - start < 60
    # Python's own handler is back: the next Ctrl-C raises at once.
    with pytest.raises(KeyboardInterrupt):
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(5)


def test_the_gil_is_released_while_rendering(plane_config):
    # Python keeps running beside a render: the main thread's longest pause
    # is much shorter than the render (it would be all of it with the GIL held).
    done = {}
    # Big enough to take a second or more on any backend, so the pause
    # measured below is small against it.
    config = dict(plane_config)
    config["camera"] = dict(plane_config["camera"], resolution=[256, 192])
    config["render"] = {"indirect": {"enabled": True, "rsm_resolution": 16,
                                     "visibility": "exact"},
                        "shadow_map_resolution": 256}

    def work():
        start = time.monotonic()
        tofsim.render(config)
        done["seconds"] = time.monotonic() - start

    thread = threading.Thread(target=work)
    last, longest = time.monotonic(), 0.0
    thread.start()
    while thread.is_alive():
        now = time.monotonic()
        longest, last = max(longest, now - last), now
    thread.join()
    assert done["seconds"] > 0.2
    assert longest < 0.5 * done["seconds"], (longest, done["seconds"])


def test_bounces_add_up_to_the_indirect_light_and_match_the_files(tmp_path):
    """IR with 2 bounces: result.bounces is bounce 1 and 2, their float sum is
    the indirect light exactly, and the in-memory arrays are those the CLI
    writes as bounce<k>.npy."""
    overrides = {"camera.resolution": [12, 12], "sensors": [], "output.video": False,
                 "render.backend": "cpu", "render.indirect.bounces": 2,
                 "render.indirect.rsm_resolution": 8,
                 "output.components": ["direct", "indirect", "bounce1", "bounce2"]}
    config = tofsim.load_config(CORNELL, overrides)
    result = tofsim.render(config)
    assert len(result.bounces) == 2
    for b in result.bounces:
        assert b.shape == result.indirect.shape and b.dtype == np.float32
    assert result.bounces[1].sum() > 0
    assert np.array_equal(result.bounces[0] + result.bounces[1], result.indirect)
    written = tofsim.render(config, output_dir=tmp_path / "run")
    for k in (1, 2):
        on_disk = np.load(tmp_path / "run" / f"bounce{k}.npy")
        assert np.array_equal(on_disk, result.bounces[k - 1])
        assert np.array_equal(written.bounces[k - 1], on_disk)
    single = dict(overrides, **{"render.indirect.bounces": 1,
                                "output.components": ["direct", "indirect"]})
    one = tofsim.render(tofsim.load_config(CORNELL, single))
    assert len(one.bounces) == 1 and one.bounces[0] is one.indirect
    reference = dict(single, **{"render.reference.samples_per_pixel": 1})
    assert tofsim.render(tofsim.load_config(CORNELL, reference), renderer="reference").bounces is None


def test_adaptive_samples_are_counted_and_the_passes_timed():
    """render.adaptive_pixel_samples: stats.sampled_pixels counts the edge
    pixels (some, not all, on the Cornell box), as transient.json does, and
    stats.pass_seconds splits IR's time (their sum is at most the total)."""
    overrides = {"camera.resolution": [16, 16], "sensors": [], "output.video": False,
                 "render.backend": "cpu", "render.indirect.rsm_resolution": 8,
                 "render.pixel_samples": 2, "render.adaptive_pixel_samples": True}
    stats = tofsim.render(tofsim.load_config(CORNELL, overrides)).stats
    assert 0 < stats["sampled_pixels"] < 16 * 16
    passes = stats["pass_seconds"]
    assert set(passes) == {"surfaces", "vpls", "visibility", "direct", "indirect",
                           "read_back", "other"}
    assert all(v >= 0 for v in passes.values())
    assert passes["indirect"] > 0
    assert sum(passes.values()) <= stats["seconds"] * 1.000001
    uniform = dict(overrides, **{"render.adaptive_pixel_samples": False})
    assert tofsim.render(tofsim.load_config(CORNELL, uniform)).stats["sampled_pixels"] == 0


def test_strict_render_fails_on_light_off_the_time_axis_as_the_cli_does(plane_config, tmp_path):
    """render.strict's check after rendering runs in memory too: an axis that
    ends at 3.1 m of path, inside the plane's returns (only rendering shows how
    much is cut), fails as the CLI's run (output_dir) fails, with its message;
    without strict both warn and record the lost fraction in stats."""
    plane_config["camera"]["resolution"] = [16, 12]
    plane_config["time"]["bins"] = 300  # 2.5 m .. 3.1 m
    loose = tofsim.render(plane_config)
    assert loose.stats["fraction_after_axis"] > 0.01
    assert loose.stats["energy_on_axis"] > 0
    assert loose.stats["off_axis_after"] == loose.stats["energy_after_axis"]
    plane_config["render"]["strict"] = True
    with pytest.raises(tofsim.ConfigError) as in_memory:
        tofsim.render(plane_config)
    with pytest.raises(tofsim.ConfigError) as to_folder:
        tofsim.render(plane_config, output_dir=tmp_path / "strict")
    assert in_memory.value.key == to_folder.value.key == "time"
    assert "of the light arrives after the last bin" in in_memory.value.message
    assert in_memory.value.message == to_folder.value.message
    assert not (tmp_path / "strict" / "transient.npy").exists()


def test_a_sequence_returns_each_frames_arrays_on_a_leading_frame_axis(plane_config, tmp_path):
    # The plane moves away from the camera (1.5 m above it) at 0.2 m/s: at
    # t = 0.5 s every pixel's distance is (1.5 + 0.1) / 1.5 times frame 0's.
    plane_config["scene"] = write_plane_gltf(tmp_path / "moving.gltf", speed=0.2)
    plane_config["time"]["bins"] = 600
    plane_config["sequence"] = {"times": ["0 s", "0.5 s"]}
    result = tofsim.render(plane_config)
    assert isinstance(result, tofsim.SequenceResult)
    np.testing.assert_array_equal(result.times_s, [0.0, 0.5])
    assert result.transient.shape == (2, 30, 40, 600, 3)
    assert result.depth.shape == (2, 30, 40)
    assert result.steady.shape == (2, 30, 40, 3)
    np.testing.assert_allclose(result.steady, result.transient.sum(axis=3, dtype=np.float64),
                               rtol=1e-5, atol=1e-9)  # each frame's steady.exr
    np.testing.assert_allclose(result.depth[1] / result.depth[0], 1.6 / 1.5, rtol=1e-5)
    # Scene flow to the next frame: the plane's points move by (0, 0, -0.1) m;
    # the last frame has no next one.
    assert result.scene_flow.shape == (2, 30, 40, 3)
    np.testing.assert_allclose(result.scene_flow[0], np.broadcast_to([0, 0, -0.1], (30, 40, 3)),
                               atol=1e-5)
    assert np.isnan(result.scene_flow[1]).all() and np.isnan(result.optical_flow[1]).all()
    # The frames were written to a temporary folder, gone once read.
    assert result.output_dir is None
    assert not os.path.exists(plane_config["output"]["directory"])
