#!/usr/bin/env python3
"""Checks files written by tofsim's writeTalCapture with h5py, the library
y-tal's tal.io.read_capture (0.20.0) reads them with: exactly its 14 keys, and
each field's dtype and shape as tal render writes them
(shared/research/nlos-capture-format.md, section 1).

usage: tal_capture_h5py.py FILE.hdf5 [FILE.hdf5 ...]
Exits 77 (ctest's SKIP_RETURN_CODE) when h5py is not installed.
"""
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"SKIP: h5py/numpy not importable ({e}); apt-get install python3-h5py")
    sys.exit(77)

KEYS = {
    "H", "H_format", "sensor_xyz", "laser_xyz", "sensor_grid_xyz", "laser_grid_xyz",
    "sensor_grid_normals", "laser_grid_normals", "sensor_grid_format", "laser_grid_format",
    "delta_t", "t_start", "t_accounts_first_and_last_bounces", "scene_info",
}
H_FORMAT = {"UNKNOWN": 0, "T_Sx_Sy": 1, "T_Lx_Ly_Sx_Sy": 2, "T_Si": 3, "T_Li_Si": 4}
GRID_FORMAT = {"UNKNOWN": 0, "N_3": 1, "X_Y_3": 2}
H_RANK = {1: 3, 2: 5, 3: 2, 4: 3}
GRID_RANK = {1: 2, 2: 3}


def check_enum(f, key, members):
    ds = f[key]
    assert isinstance(ds, h5py.Dataset), key
    assert h5py.check_enum_dtype(ds.dtype) == members, (key, h5py.check_enum_dtype(ds.dtype))
    assert ds.dtype == np.int32, (key, ds.dtype)
    assert ds.shape == (1,), (key, ds.shape)
    value = int(ds[0])
    assert value in members.values(), (key, value)
    return value


def check_file(path):
    with h5py.File(path, "r") as f:
        assert set(f.keys()) == KEYS, f"keys: extra {set(f.keys()) - KEYS}, missing {KEYS - set(f.keys())}"
        for key in KEYS:
            assert isinstance(f[key], h5py.Dataset), f"{key} is not a dataset"

        h_format = check_enum(f, "H_format", H_FORMAT)
        H = f["H"]
        assert H.dtype == np.float32, H.dtype
        assert H.ndim == H_RANK[h_format], (H.shape, h_format)
        assert H.compression == "gzip" and H.shuffle and H.chunks is not None, \
            (H.compression, H.shuffle, H.chunks)
        assert H.chunks[0] >= 1 and all(c == 1 for c in H.chunks[1:-1]), H.chunks
        assert np.isfinite(H[()]).all()

        for key in ("sensor_xyz", "laser_xyz"):
            assert f[key].dtype == np.float32 and f[key].shape == (3,), (key, f[key].dtype, f[key].shape)

        grid_shapes = {}
        for prefix in ("sensor", "laser"):
            fmt = check_enum(f, f"{prefix}_grid_format", GRID_FORMAT)
            xyz, normals = f[f"{prefix}_grid_xyz"], f[f"{prefix}_grid_normals"]
            for ds in (xyz, normals):
                assert ds.dtype == np.float32, (ds.name, ds.dtype)
                assert ds.ndim == GRID_RANK[fmt] and ds.shape[-1] == 3, (ds.name, ds.shape)
            assert xyz.shape == normals.shape, (xyz.shape, normals.shape)
            grid_shapes[prefix] = xyz.shape[:-1]
        if h_format in (1, 3):
            assert H.shape[1:] == grid_shapes["sensor"], (H.shape, grid_shapes)
        else:
            n = len(grid_shapes["laser"])
            assert H.shape[1:1 + n] == grid_shapes["laser"], (H.shape, grid_shapes)
            assert H.shape[1 + n:] == grid_shapes["sensor"], (H.shape, grid_shapes)

        for key in ("delta_t", "t_start"):
            ds = f[key]
            assert ds.dtype == np.float64 and ds.shape == (), (key, ds.dtype, ds.shape)
        assert f["delta_t"][()] > 0

        flag = f["t_accounts_first_and_last_bounces"]
        assert flag.dtype == np.bool_ and flag.shape == (), (flag.dtype, flag.shape)
        assert isinstance(flag[()], np.bool_), type(flag[()])

        info = f["scene_info"]
        assert info.shape == (), info.shape
        string = h5py.check_string_dtype(info.dtype)
        assert string is not None and string.encoding == "utf-8" and string.length is None, string
        assert isinstance(info[()], bytes) and len(info[()]) > 0
        info[()].decode("utf-8")
        print(f"{path}: ok (H {H.shape}, H_format {h_format})")


def main(paths):
    if not paths:
        print(__doc__)
        return 2
    for path in paths:
        check_file(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
