"""scripts/plot_lidar_multipath.py (issue 43): the README's multipath
picture on a log axis. A synthetic lidar folder (waveforms.npy and
lidar.json as a `lidar:` render writes them): the script reads the beam the
azimuth names, draws it against range with the decades below its peak, and
refuses a beam outside the scan. Standard library only, as the script."""

import importlib
import json
import math
import os
import struct
import subprocess
import sys
import zlib

from conftest import SOURCE_DIR

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "plot_lidar_multipath.py")
sys.path.insert(0, os.path.dirname(SCRIPT))
plot = importlib.import_module("plot_lidar_multipath")


def _write_npy(path, shape, values):
    header = "{'descr': '<f4', 'fortran_order': False, 'shape': %r, }" % (shape,)
    header += " " * (63 - (10 + len(header)) % 64) + "\n"
    with open(path, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode("latin1"))
        f.write(struct.pack("<%df" % len(values), *values))


def _lidar_folder(tmp_path, T=200):
    """2 rings x 3 azimuths (0, 10, 20 deg), bins of 5 cm of depth: beam (1,
    20 deg) an echo at bin 100 (5.025 m) with a tail 1e-3 of it after."""
    values = [0.0] * (2 * 3 * T)
    first = (1 * 3 + 2) * T
    values[first + 100] = 1.0
    for k in range(101, 120):
        values[first + k] = 1e-3 * 0.8 ** (k - 101)
    _write_npy(tmp_path / "waveforms.npy", (2, 3, T), values)
    meta = {"lidar": {"azimuth_start_deg": 0.0, "azimuth_step_deg": 10.0},
            "time": {"depth_start_m": 0.0, "depth_bin_width_m": 0.05}}
    (tmp_path / "lidar.json").write_text(json.dumps(meta))
    return tmp_path / "waveforms.npy", values


def _png_size(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_the_named_beam_is_read_and_drawn(tmp_path):
    npy, values = _lidar_folder(tmp_path)
    shape, read = plot.read_npy(str(npy))
    assert shape == (2, 3, 200)
    wave = plot.beam_waveform(shape, read, 1, 2)
    assert wave[100] == 1.0 and abs(wave[101] - 1e-3) < 1e-9
    out = tmp_path / "p.png"
    r = subprocess.run([sys.executable, SCRIPT, str(npy), str(out), "--beam", "1", "20",
                        "--range", "0", "10", "--size", "400", "300"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "peak 1" in r.stdout
    assert _png_size(out) == (400, 300)
    # The tail is drawn: pixels of the beam's colour well below the peak's row.
    data = out.read_bytes()
    raw = zlib.decompress(data[data.index(b"IDAT") + 4:])
    rows = [raw[y * (1 + 400 * 3) + 1:(y + 1) * (1 + 400 * 3)] for y in range(300)]
    red = [y for y, row in enumerate(rows)
           if any(row[3 * x:3 * x + 3] == bytes(plot.COLOURS[0]) for x in range(400))]
    assert red and max(red) - min(red) > 100  # from the peak down past 1e-3
    # On the log axis: bin 110 (5.525 m), 1.34e-4 of the peak, is 0.3 + 3.87
    # of the 6.3 decades down the plot (rows 20 .. 260, columns 70 .. 380 over
    # 0 .. 10 m); a linear axis draws it on the floor.
    x, y = round(70 + 5.525 / 10 * 310), round(20 + (0.3 - math.log10(1e-3 * 0.8 ** 9)) / 6.3 * 240)
    near = [rows[j][3 * i:3 * i + 3] for j in range(y - 3, y + 4) for i in range(x - 2, x + 3)]
    assert bytes(plot.COLOURS[0]) in near


def test_a_beam_outside_the_scan_is_refused(tmp_path):
    npy, _ = _lidar_folder(tmp_path)
    r = subprocess.run([sys.executable, SCRIPT, str(npy), str(tmp_path / "p.png"),
                        "--beam", "2", "0"], capture_output=True, text=True)
    assert r.returncode != 0
    assert "not in the scan" in r.stderr
