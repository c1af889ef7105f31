"""tofsim.sense on synthetic transients: the SPAD pile-up law, outputs, errors."""

import math
import os

import numpy as np
import pytest

import tofsim
from conftest import SOURCE_DIR

CORNELL = os.path.join(SOURCE_DIR, "configs", "cornell_box.yaml")
AXIS = {"start_s": 0.0, "bin_width_s": 100e-12, "bins": 64}


def synthetic_flux():
    """Detections per cycle and bin: a return at bin 20 over a weak background,
    strong enough that pile-up reshapes the histogram."""
    t = np.arange(AXIS["bins"])
    return 0.01 + 0.4 * np.exp(-0.5 * ((t - 20) / 2.0) ** 2)


def first_photon_probabilities(flux):
    """Synchronous SPAD: the first detection of a cycle is in bin i with
    probability q_i prod_{j<i} (1 - q_j), q = 1 - exp(-flux); none otherwise."""
    q = -np.expm1(-flux)
    survive = np.concatenate(([1.0], np.cumprod(1 - q)))
    return q * survive[:-1], survive[-1]


def chi_square(counts, expected_counts):
    """Pearson's statistic over bins expecting >= 5 counts, the others pooled."""
    keep = expected_counts >= 5
    obs = np.append(counts[keep], counts[~keep].sum())
    exp = np.append(expected_counts[keep], expected_counts[~keep].sum())
    if exp[-1] < 5:  # nothing (or too little) to pool: fold it into the smallest bin
        obs, exp = obs[:-1], exp[:-1]
    return float(((obs - exp) ** 2 / exp).sum()), len(obs) - 1


def chi_square_quantile(df, z=3.090):
    """Wilson-Hilferty approximation of the chi-square quantile; z = 3.09: 0.999."""
    a = 2.0 / (9.0 * df)
    return df * (1 - a + z * math.sqrt(a)) ** 3


def spad_counts(flux, pixels=(2, 2), cycles=1e5, seed=7):
    transient = np.broadcast_to(flux[None, None, :, None], (*pixels, flux.size, 1))
    sensor = {"type": "spad", "mode": "synchronous", "cycles": cycles, "pde": 1.0}
    return tofsim.sense(np.ascontiguousarray(transient, np.float32), AXIS, sensor, seed=seed)


def test_spad_reproduces_the_first_photon_distribution():
    flux = synthetic_flux().astype(np.float32).astype(np.float64)
    result = spad_counts(flux)
    counts = result["spad_counts"]
    assert counts.shape == (2, 2, 64)
    pooled = counts.reshape(-1, 64).sum(axis=0).astype(np.float64)
    cycles = 4 * 100000
    p, none = first_photon_probabilities(flux)
    detected = np.append(pooled, cycles - pooled.sum())
    stat, df = chi_square(detected, cycles * np.append(p, none))
    assert stat < chi_square_quantile(df), (stat, df)
    # The test can fail: the histogram is not the flux's shape (no pile-up).
    naive = cycles * np.append(-np.expm1(-flux), 0.0)
    naive[-1] = cycles - naive[:-1].sum()
    stat_naive, df_naive = chi_square(detected, naive)
    assert stat_naive > 100 * chi_square_quantile(df_naive)


def test_same_seed_same_counts_other_seed_other_counts():
    flux = synthetic_flux()
    a = spad_counts(flux, seed=3)["spad_counts"]
    np.testing.assert_array_equal(a, spad_counts(flux, seed=3)["spad_counts"])
    assert not np.array_equal(a, spad_counts(flux, seed=4)["spad_counts"])


def test_outputs_come_with_metadata():
    result = spad_counts(synthetic_flux())
    assert {"spad_counts", "spad_depth_peak", "spad_depth_coates", "spad_intensity",
            "spad_histograms"} <= set(result)
    assert result.metadata["spad_counts"]["unit"] == "counts"
    assert result.metadata["spad_depth_peak"]["unit"] == "m"
    assert result.metadata["spad_depth_peak"]["picture"]["colormap"] == "turbo"
    assert result.sensor["type"] == "spad"
    assert result.sensor["time"] == {"start_s": 0.0, "bin_width_s": 100e-12, "bins": 64}
    # The return is centred on bin 20 of 100 ps (20.5 bins of round trip);
    # Coates' correction undoes the pile-up that pulls the raw peak earlier.
    depth = result["spad_depth_coates"]
    assert depth.shape == (2, 2)
    np.testing.assert_allclose(depth, 299792458 * 20.5 * 100e-12 / 2, atol=0.1 * 0.015)


def test_metadata_says_each_arrays_axes_time_and_parameters():
    result = spad_counts(synthetic_flux(), cycles=1e5, seed=5)
    for name, array in result.items():
        meta = result.metadata[name]
        assert tuple(meta["shape"]) == array.shape, name
        assert len(meta["axes"]) == array.ndim, name
        assert meta["sensor"]["seed"] == 5
    counts = result.metadata["spad_counts"]
    assert counts["axes"] == ["y", "x", "t"]
    time = counts["time"]
    assert (time["start_s"], time["bin_width_s"], time["bins"]) == (0.0, 100e-12, 64)
    assert time["bin_width_m"] == pytest.approx(299792458 * 100e-12)
    assert counts["sensor"]["parameters"]["cycles"] == 100000
    assert counts["sensor"]["parameters"]["pde"] == 1.0
    assert "files" not in counts  # the module writes none
    assert result.metadata["spad_histograms"]["axes"] == ["pixel", "t"]


def test_cwtof_warns_when_the_scene_is_deeper_than_its_range():
    # A return at 2.2 m seen at 100 MHz (1.5 m unambiguous range).
    axis = {"start_s": 0.0, "bin_width_s": 10e-12, "bins": 2000}
    transient = np.zeros((1, 2, 2000, 1), np.float32)
    transient[:, :, int(2 * 2.2 / 299792458 / 10e-12), 0] = 1e4
    depth = np.full((1, 2), 2.2, np.float32)
    sensor = {"type": "cwtof", "frequencies": ["100 MHz"], "shot_noise": False}
    with pytest.warns(tofsim.SensorWarning, match="unambiguous range"):
        result = tofsim.sense(transient, axis, sensor, depth=depth)
    assert len(result.warnings) == 1
    assert result.metadata["cwtof_depth"]["sensor"]["warnings"] == result.warnings
    meta = result.metadata["cwtof_depth_100MHz"]
    assert meta["attributes"]["frequency_Hz"] == 100e6
    assert meta["attributes"]["range_m"] == pytest.approx(299792458 / 2 / 100e6)
    assert result.metadata["cwtof_mpi_error"]["signed"]
    assert result.metadata["cwtof_raw"]["axes"] == ["frequency", "phase_step", "y", "x"]


def test_cwtof_on_a_single_return_measures_its_depth():
    # One pixel, one bin of light at 2 m round trip... 1 m depth.
    axis = {"start_s": 0.0, "bin_width_s": 10e-12, "bins": 2000}
    transient = np.zeros((1, 2, 2000, 1), np.float32)
    t_bin = int(round(2.0 / 299792458 / 10e-12))
    transient[:, :, t_bin, 0] = 1e4
    result = tofsim.sense(transient, axis, {"type": "cwtof", "frequencies": ["20 MHz"],
                                            "shot_noise": False})
    assert result["cwtof_depth"].shape == (1, 2)
    np.testing.assert_allclose(result["cwtof_depth"], (t_bin + 0.5) * 10e-12 * 299792458 / 2,
                               atol=2e-3)


def test_a_bad_sensor_value_names_the_key():
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.sense(np.zeros((1, 1, 64, 1), np.float32), AXIS, {"type": "spad", "pde": 2})
    assert e.value.key == "pde"
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.sense(np.zeros((1, 1, 64, 1), np.float32), AXIS, {"type": "spad", "cycles": 1.5})
    assert e.value.key == "cycles"
    with pytest.raises(ValueError):
        tofsim.sense(np.zeros((1, 1, 32, 1), np.float32), AXIS, {"type": "spad"})


def test_sense_runs_on_a_render_result(plane_config):
    plane_config["camera"]["resolution"] = [8, 6]
    result = tofsim.render(plane_config)
    spad = tofsim.sense(result.transient, result.time,
                        {"type": "spad", "cycles": 1000, "channel_weights": [1, 1, 1]})
    assert spad["spad_counts"].shape == (6, 8, 1200)
    assert spad["spad_counts"].sum() > 0


CWTOF_BY_ORDER = {"type": "cwtof", "name": "cwtof", "frequencies": ["20 MHz", "100 MHz"],
                  "channel_weights": [1, 1, 1], "source_scale": 10000, "shot_noise": False,
                  "read_noise": 0.0, "multipath_by_order": True}


def render_bounces(tmp_path):
    """A 12 x 12 Cornell box of two IR bounces, written with its components and
    the CW-ToF error by bounce order (the CLI's sensors/cwtof/ files)."""
    config = tofsim.load_config(CORNELL, overrides={
        "camera.resolution": [12, 12], "render.indirect.bounces": 2,
        "output.components": ["direct", "bounce1", "bounce2"], "output.video": False,
        "sensors": [CWTOF_BY_ORDER]})
    out = tmp_path / "render"
    return tofsim.render(config, renderer="ir", output_dir=out), out


def test_cwtof_by_bounce_order_is_the_renders(tmp_path):
    result, out = render_bounces(tmp_path)
    bounces = [np.load(out / "bounce1.npy"), np.load(out / "bounce2.npy")]
    assert result.indirect is None and bounces[1].sum() > 0  # not written; bounce 2 has light
    sensed = tofsim.sense(result.transient, result.time, CWTOF_BY_ORDER, seed=1,
                          direct=result.direct, depth=result.depth, bounces=bounces)
    errors = sensed["cwtof_multipath_error_by_order"]
    assert errors.shape == (3, 12, 12)
    assert sensed.metadata["cwtof_multipath_error_by_order"]["shape"] == [3, 12, 12]
    assert sensed.metadata["cwtof_multipath_error_by_order"]["axes"][0] == "order"
    # The same model on the same floats as the render's sensor: the same bytes.
    written = np.load(out / "sensors" / "cwtof" / "cwtof_multipath_error_by_order.npy")
    assert np.isfinite(written).any()
    np.testing.assert_array_equal(errors, written)


def test_cwtof_by_bounce_order_names_what_is_missing(tmp_path):
    volume = np.zeros((2, 2, 64, 1), np.float32)
    depth = np.ones((2, 2), np.float32)
    sensor = dict(CWTOF_BY_ORDER, channel_weights=[1])
    with pytest.raises(tofsim.ConfigError, match="missing: bounces") as e:
        tofsim.sense(volume, AXIS, sensor, direct=volume, depth=depth)
    assert e.value.key == "multipath_by_order"
    with pytest.raises(tofsim.ConfigError, match="missing: direct, depth"):
        tofsim.sense(volume, AXIS, sensor, bounces=[volume])
    with pytest.raises(ValueError, match=r"bounces\[1\] must have the transient's shape"):
        tofsim.sense(volume, AXIS, sensor, direct=volume, depth=depth,
                     bounces=[volume, np.zeros((2, 2, 64, 3), np.float32)])
