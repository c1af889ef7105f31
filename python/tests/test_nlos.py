"""tofsim.render of nlos configs: H and its grids as arrays, the same values
in memory and from the files, and capture.hdf5 with the dtypes and shapes
y-tal's reader expects (shared/research/nlos-capture-format.md, section 1)."""

import os

import numpy as np
import pytest

import tofsim
from conftest import SOURCE_DIR

CONFOCAL = os.path.join(SOURCE_DIR, "configs", "nlos_confocal.yaml")
SMALL = {"nlos.sensor_grid": [8, 6], "time.bins": 256, "time.bin_width": "1 cm",
         "render.indirect.rsm_resolution": 32}


def test_confocal_h_and_grids_come_back_as_arrays(tmp_path):
    result = tofsim.render(tofsim.load_config(CONFOCAL, SMALL))
    assert isinstance(result, tofsim.NlosResult)
    assert result.H.shape == (256, 8, 6) and result.H.dtype == np.float32
    assert result.H_format == "T_Sx_Sy" and result.scan == "confocal"
    np.testing.assert_array_equal(result.sensor_grid_xyz, result.laser_grid_xyz)
    assert result.sensor_grid_xyz.shape == (8, 6, 3)
    # tal's grid over the 1 m wall at z = 0: cell centres, x index major.
    np.testing.assert_allclose(result.sensor_grid_xyz[:, 0, 0], -0.5 + (np.arange(8) + 0.5) / 8,
                               atol=1e-6)
    np.testing.assert_allclose(result.sensor_grid_xyz[0, :, 1], -0.5 + (np.arange(6) + 0.5) / 6,
                               atol=1e-6)
    assert result.wall_normal == pytest.approx([0, 0, 1])
    assert result.stats["captures"] == 48
    # The letter T at z = 0.5: nothing arrives before 2 x 0.5 m of path.
    arrival = result.time.start_m + result.time.bin_width_m * np.arange(result.time.bins)
    assert result.H[arrival < 0.99].sum() == 0
    assert result.H.sum() > 0
    assert result.files == []

    on_disk = tofsim.render(tofsim.load_config(CONFOCAL, SMALL), output_dir=tmp_path / "out")
    np.testing.assert_array_equal(on_disk.H, result.H)
    assert "capture.hdf5" in on_disk.files


def test_capture_hdf5_has_the_y_tal_layout(tmp_path):
    h5py = pytest.importorskip("h5py", reason="python3-h5py (Debian) reads the HDF5 file")
    config = tofsim.load_config(CONFOCAL, {**SMALL, "nlos.scan": "exhaustive",
                                           "nlos.laser_grid": [2, 3]})
    result = tofsim.render(config, output_dir=tmp_path / "out")
    with h5py.File(tmp_path / "out" / "capture.hdf5", "r") as f:
        assert set(f.keys()) == {
            "H", "H_format", "sensor_xyz", "sensor_grid_xyz", "sensor_grid_normals",
            "sensor_grid_format", "laser_xyz", "laser_grid_xyz", "laser_grid_normals",
            "laser_grid_format", "delta_t", "t_start", "t_accounts_first_and_last_bounces",
            "scene_info"}
        assert f["H"].dtype == np.float32 and f["H"].shape == (256, 2, 3, 8, 6)
        np.testing.assert_array_equal(f["H"][()], result.H)
        assert h5py.check_enum_dtype(f["H_format"].dtype) is not None
        assert f["H_format"].shape == (1,) and int(f["H_format"][0]) == 2  # T_Lx_Ly_Sx_Sy
        assert int(f["sensor_grid_format"][0]) == 2 and int(f["laser_grid_format"][0]) == 2  # X_Y_3
        assert f["sensor_grid_xyz"].shape == (8, 6, 3) and f["laser_grid_xyz"].shape == (2, 3, 3)
        assert f["sensor_xyz"].shape == (3,) and f["sensor_xyz"].dtype == np.float32
        assert f["delta_t"].shape == () and f["delta_t"].dtype == np.float64
        assert f["delta_t"][()] == pytest.approx(0.01)
        assert f["t_start"][()] == pytest.approx(0.0)
        assert f["t_accounts_first_and_last_bounces"][()] is np.False_ or \
            not bool(f["t_accounts_first_and_last_bounces"][()])
        assert f["t_accounts_first_and_last_bounces"].dtype == np.bool_
        assert "tofsim_version" in f["scene_info"][()].decode()
