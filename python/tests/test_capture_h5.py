"""output.format: hdf5: tofsim.render writes one capture.h5 and reads it back;
tofsim.load reads a folder of either format; h5py (where installed) sees the
datasets, their gzip + shuffle chunks and their attributes."""

import json

import numpy as np
import pytest

import tofsim


@pytest.fixture
def small(plane_config):
    plane_config["camera"]["resolution"] = [8, 8]
    plane_config["time"]["bins"] = 300
    plane_config["render"]["backend"] = "cpu"
    plane_config["output"]["components"] = ["direct", "indirect"]
    plane_config["sensors"] = [{"type": "spad", "cycles": 100, "pde": 0.3}]
    return plane_config


def render_both(config, tmp_path):
    npy = tofsim.render(config, output_dir=tmp_path / "npy")
    config["output"]["format"] = "hdf5"
    h5 = tofsim.render(config, output_dir=tmp_path / "h5")
    return npy, h5


def test_hdf5_render_holds_the_npy_arrays(small, tmp_path):
    npy, h5 = render_both(small, tmp_path)
    assert "capture.h5" in h5.files
    assert "transient.npy" not in h5.files and not (tmp_path / "h5" / "transient.npy").exists()
    for name in ("transient", "direct", "indirect"):
        np.testing.assert_array_equal(getattr(h5, name), getattr(npy, name))
        np.testing.assert_array_equal(getattr(h5, name), np.load(tmp_path / "npy" / (name + ".npy")))
    loaded_h5 = tofsim.load(tmp_path / "h5")
    loaded_npy = tofsim.load(tmp_path / "npy")
    for name in ("transient", "direct", "indirect", "depth"):
        np.testing.assert_array_equal(getattr(loaded_h5, name), getattr(loaded_npy, name))
    np.testing.assert_array_equal(loaded_h5.depth, np.load(tmp_path / "npy" / "depth.npy"))
    assert loaded_h5.time == npy.time
    assert loaded_h5.steady.shape == (8, 8, 3)
    np.testing.assert_allclose(loaded_h5.steady, loaded_npy.transient.sum(axis=2), rtol=1e-5)


def test_h5py_reads_datasets_filters_and_attributes(small, tmp_path):
    h5py = pytest.importorskip("h5py")
    render_both(small, tmp_path)
    meta = json.load(open(tmp_path / "h5" / "transient.json"))
    with h5py.File(tmp_path / "h5" / "capture.h5", "r") as f:
        transient = f["transient"]
        assert transient.shape == (8, 8, 300, 3)
        assert transient.dtype == np.float32
        assert transient.compression == "gzip" and transient.shuffle
        assert transient.chunks[0] == 1 and transient.chunks[2] <= 300
        np.testing.assert_array_equal(transient[...], np.load(tmp_path / "npy" / "transient.npy"))
        # A pixel's histogram and a time slice, through hyperslabs.
        full = np.load(tmp_path / "npy" / "transient.npy")
        np.testing.assert_array_equal(transient[3, 5], full[3, 5])
        np.testing.assert_array_equal(transient[:, :, 150], full[:, :, 150])
        attrs = transient.attrs
        assert json.loads(attrs["json"])["time"] == meta["time"]
        assert attrs["start_s"] == meta["time"]["start_s"]
        assert attrs["bin_width_s"] == meta["time"]["bin_width_s"]
        assert attrs["bins"] == 300
        assert attrs["units"] == meta["value_unit"]
        assert list(attrs["axes"]) == ["y", "x", "t", "c"]
        np.testing.assert_array_equal(f["depth"][...], np.load(tmp_path / "npy" / "depth.npy"))
        assert f["depth"].attrs["units"] == "m"
        counts = f["sensors/spad/spad_counts"]
        np.testing.assert_array_equal(
            counts[...], np.load(tmp_path / "npy" / "sensors" / "spad" / "spad_counts.npy"))
        sensor_meta = json.load(open(tmp_path / "npy" / "sensors" / "spad" / "spad_counts.json"))
        assert json.loads(counts.attrs["json"])["axes"] == sensor_meta["axes"]
        assert counts.compression == "gzip" and counts.shuffle
