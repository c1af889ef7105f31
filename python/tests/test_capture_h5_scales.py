"""capture.h5's dimension scales (issue 44, item 11): the time axis and the
pixel coordinates attached to the datasets' axes as HDF5 dimension scales,
as netCDF-aware readers (netCDF-4, xarray) expect; read back with h5py."""

import json

import numpy as np
import pytest

from test_capture_h5 import render_both, small  # noqa: F401 (a fixture)


def test_axes_carry_their_coordinates_as_dimension_scales(small, tmp_path):  # noqa: F811
    h5py = pytest.importorskip("h5py")
    small["sensors"][0]["name"] = "spad"
    render_both(small, tmp_path)
    meta = json.load(open(tmp_path / "h5" / "transient.json"))
    t = meta["time"]
    edges = t["start_s"] + t["bin_width_s"] * np.arange(t["bins"])
    with h5py.File(tmp_path / "h5" / "capture.h5", "r") as f:
        for name in ("t", "y", "x", "c"):
            assert h5py.h5ds.is_scale(f[name].id), name
        np.testing.assert_allclose(f["t"][...], edges, rtol=1e-12, atol=0)
        assert f["t"].attrs["units"] == "s"
        np.testing.assert_array_equal(f["y"][...], np.arange(8))
        np.testing.assert_array_equal(f["x"][...], np.arange(8))
        assert list(f["c"].attrs["names"]) == ["R", "G", "B"]
        for volume in ("transient", "direct", "indirect"):
            dims = f[volume].dims
            assert [d.label for d in dims] == ["y", "x", "t", "c"], volume
            for axis, scale in enumerate(("y", "x", "t", "c")):
                assert len(dims[axis]) == 1 and dims[axis][0].name == "/" + scale, (volume, axis)
        assert [d.label for d in f["steady"].dims] == ["y", "x", "c"]
        assert [d.label for d in f["depth"].dims] == ["y", "x"]
        assert f["depth"].dims[1][0].name == "/x"
        # A sensor image over the pixels: y and x.
        depth = f["sensors/spad/spad_depth_peak"]
        assert [d.label for d in depth.dims][:2] == ["y", "x"]
