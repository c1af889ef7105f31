#!/usr/bin/env python3
"""Writes the seed corpora in fuzz/corpus/<target>/: the shipped config and
scene, plus tiny hand-made inputs that reach each code path (indices, strips,
sparse accessors, a .glb, a .npy, a saved render), and a capture.h5 rendered
by build/apps/cli/tofsim when it is built. Re-run after changing it."""
import base64, json, os, shutil, struct, subprocess, sys, tempfile

root = os.path.dirname(os.path.abspath(__file__))
src = os.path.dirname(root)

def out(target, name, data):
    d = os.path.join(root, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())

def npy(shape, values):
    header = "{'descr': '<f4', 'fortran_order': False, 'shape': (%s), }" % "".join(
        "%d, " % s for s in shape)
    header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + struct.pack(
        "<%df" % len(values), *values)

# config: the shipped demo and a minimal one
out("fuzz_config", "cornell_box.yaml", open(os.path.join(src, "configs/cornell_box.yaml")).read())
out("fuzz_config", "minimal.yaml", "scene: scenes/cornell_box.gltf\ncamera:\n  gltf_camera: cornell_camera\n"
    "  resolution: [8, 8]\nlight:\n  type: point\n  position: [0.3, 0.5, -0.5]\n"
    "time:\n  bins: 16\n  bin_width: \"1 m\"\nrender:\n  memory_budget: \"64 MiB\"\n"
    "  indirect:\n    visibility: exact\noutput:\n  components: [direct]\n")

# config: a medium (issue 42), given by its coefficients (per channel, a
# unit, Henyey-Greenstein, its index of refraction) and as fog by its
# visibility, and the shipped fog lidar
out("fuzz_config", "medium.yaml", "scene: scenes/cornell_box.gltf\ncamera: {gltf_camera: cornell_camera, "
    "resolution: [8, 8]}\nlight: {type: point, position: [0.3, 0.5, -0.5]}\n"
    "time: {bins: 16, bin_width: 1 m}\nmedium:\n  sigma_a: [0.3, 0.05, 0.02 /m]\n  sigma_s: 0.1\n"
    "  phase: {model: henyey_greenstein, g: 0.6}\n  index_of_refraction: 1.33\n")
out("fuzz_config", "medium_fog.yaml", "scene: scenes/cornell_box.gltf\ncamera: {gltf_camera: cornell_camera, "
    "resolution: [8, 8]}\nlight: {type: point, position: [0.3, 0.5, -0.5]}\n"
    "time: {bins: 16, bin_width: 1 m, index_of_refraction: 1}\n"
    "medium: {visibility: 50 m, albedo: [0.9, 0.95, 1], phase: rayleigh}\n")
out("fuzz_config", "fog_lidar.yaml", open(os.path.join(src, "configs/fog_lidar.yaml")).read())
# config: per-region media (issue 42's `media:`): the shipped water tank, an
# absorbing region on the CPU backend, and an open mesh named as a region
out("fuzz_config", "water_tank.yaml", open(os.path.join(src, "configs/water_tank.yaml")).read())
out("fuzz_config", "media_cpu.yaml", "scene: scenes/water_tank.gltf\ncamera: {gltf_camera: lidar_camera, "
    "resolution: [8, 8]}\nlight: {type: point, position: [0, 0.35, 0.8]}\n"
    "time: {bins: 16, bin_width: 1 m}\nrender: {backend: cpu}\n"
    "media:\n  - {region: water_tank, sigma_a: [0.3, 0.05, 0.02 /m], index_of_refraction: 1.33}\n")
out("fuzz_config", "media_open_region.yaml", "scene: scenes/water_tank.gltf\ncamera: {gltf_camera: lidar_camera, "
    "resolution: [8, 8]}\nlight: {type: point, position: [0, 0.35, 0.8]}\n"
    "time: {bins: 16, bin_width: 1 m}\nrender: {renderer: reference}\n"
    "media:\n  - {region: floor, visibility: 5 m}\n")

# config: a lidar (issue 43): the shipped street, elevations as a list with
# every optional key, and the keys it refuses (a preset, a raster scan)
out("fuzz_config", "lidar_street.yaml", open(os.path.join(src, "configs/lidar_street.yaml")).read())
out("fuzz_config", "lidar_list.yaml", "scene: scenes/cornell_box.gltf\nlidar:\n"
    "  position: [0.3, 0.5, -0.5]\n  orientation: {look_at: [0.3, 0.5, 0.5], up: [0, 1, 0]}\n"
    "  channels: [-10, -2.5, 0, 4]\n  azimuth: {start: -30 deg, end: 0.5 rad, step: 1.5}\n"
    "  beam_divergence: 0.2 deg\n  beam_profile: tophat\n  beam_rays: 7\n  power: 2\n"
    "  rotation_rate: 20 Hz\n  plot_beams: [[0, 0], [3, 10.5]]\n"
    "  returns: {mode: all, max: 4, threshold: 1e-6, separation: 5 cm}\n"
    "time: {bins: 16, bin_width: 1 m}\nmedium: {sigma_a: 0.1}\noutput: {transient: false}\n")
out("fuzz_config", "lidar_refused.yaml", "scene: scenes/cornell_box.gltf\nlidar:\n"
    "  preset: vlp16\n  scan: raster\n  position: [0, 0, 0]\n"
    "  channels: {count: 0}\n  azimuth: {step: 0}\n  beam_divergence: 0 mrad\n"
    "camera: {}\ntime: {bins: 16, bin_width: 1 m}\n")
# config: a lidar's multipath (every key), and the values it refuses
out("fuzz_config", "lidar_multipath.yaml", "scene: scenes/cornell_box.gltf\nlidar:\n"
    "  position: [0.3, 0.5, -0.5]\n  orientation: {look_at: [0.3, 0.5, 0.5], up: [0, 1, 0]}\n"
    "  channels: [-10, 0]\n  azimuth: {start: -5, end: 5, step: 5}\n  beam_divergence: 3 mrad\n"
    "  multipath: {bounces: 2, spot_rays: 3, receiver_rays: 9, receiver_fov: 1 deg,"
    " vpls_per_bounce: 5}\ntime: {bins: 16, bin_width: 1 m}\n")
out("fuzz_config", "lidar_multipath_refused.yaml", "scene: scenes/cornell_box.gltf\nlidar:\n"
    "  position: [0, 0, 0]\n  channels: [0]\n  orientation: {look_at: [1, 0, 0]}\n"
    "  multipath: {bounces: 9, spot_rays: 0, receiver_fov: 1 mrad}\n"
    "time: {bins: 16, bin_width: 1 m}\n")
# config: lidar presets and grid scans (zones43): the shipped multizone
# sensor, a raster with every grid key, zones overriding a preset
out("fuzz_config", "multizone_8x8.yaml", open(os.path.join(src, "configs/multizone_8x8.yaml")).read())
out("fuzz_config", "lidar_raster.yaml", "scene: scenes/cornell_box.gltf\nlidar:\n"
    "  scan: raster\n  position: [0.3, 0.3, -0.8]\n  orientation: {look_at: [0.3, 0.3, 0], up: [0, 1, 0]}\n"
    "  grid: {rows: 3, columns: 5}\n  field_of_view: {horizontal: 30 deg, vertical: 0.2 rad}\n"
    "  beam_rays: 4\n  plot_beams: [[1, 4]]\ntime: {bins: 16, bin_width: 1 m}\n")
out("fuzz_config", "lidar_zones_preset.yaml", "scene: scenes/cornell_box.gltf\nlidar:\n"
    "  preset: spinning-64\n  scan: zones\n  position: [0, 0, 0]\n  orientation: {look_at: [0, 0, 1]}\n"
    "  grid: {rows: 2, columns: 0}\n  field_of_view: {horizontal: 170}\n  zone_rays: 65\n"
    "time: {}\n")

# glTF: the shipped scene, a triangle with indices, a strip with a sparse
# POSITION accessor, and the triangle as .glb
out("fuzz_gltf", "cornell_box.gltf", open(os.path.join(src, "configs/scenes/cornell_box.gltf")).read())
pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
idx = struct.pack("<3H", 0, 1, 2) + b"\0\0"
buf = pos + idx
doc = {
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "scale": [1, 2, 1]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}],
    "buffers": [{"byteLength": len(buf)}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
}
embedded = json.loads(json.dumps(doc))
embedded["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buf).decode()
out("fuzz_gltf", "triangle.gltf", json.dumps(embedded))
strip = json.loads(json.dumps(embedded))
strip["meshes"][0]["primitives"][0]["mode"] = 5
strip["meshes"][0]["primitives"][0].pop("indices")
strip["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},
                                   "values": {"bufferView": 0}}
out("fuzz_gltf", "strip_sparse.gltf", json.dumps(strip))
jsonChunk = json.dumps(doc).encode()
jsonChunk += b" " * ((4 - len(jsonChunk) % 4) % 4)
binChunk = buf + b"\0" * ((4 - len(buf) % 4) % 4)
body = struct.pack("<I4s", len(jsonChunk), b"JSON") + jsonChunk + struct.pack("<I4s", len(binChunk), b"BIN\0") + binChunk
out("fuzz_gltf", "triangle.glb", b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body)

# capture sequences (fuzz/SequenceInput.h): the shipped moving block (its
# config alone, the scene through the scenes/ link), and a config, NUL, the
# triangle moved by a LINEAR translation, a CUBICSPLINE rotation and a STEP
# scale channel (times accessor 2, outputs 3 to 5).
out("fuzz_sequence", "moving_block.yaml", open(os.path.join(src, "configs/moving_block.yaml")).read())
times = struct.pack("<2f", 0, 1)
moves = {"translation": struct.pack("<6f", 0, 0, 0, 0.1, 0, 0),
         "rotation": struct.pack("<24f", *([0] * 4 + [0, 0, 0, 1] + [0] * 4) * 2),
         "scale": struct.pack("<6f", 1, 1, 1, 2, 2, 2)}
animated = json.loads(json.dumps(embedded))
abuf = buf + times + b"".join(moves.values())
animated["buffers"] = [{"byteLength": len(abuf), "uri": "data:application/octet-stream;base64," +
                        base64.b64encode(abuf).decode()}]
offset = len(buf)
for data in [times] + list(moves.values()):
    animated["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": len(data)})
    offset += len(data)
animated["accessors"].append({"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
                              "min": [0], "max": [1]})
animated["accessors"] += [{"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"},
                          {"bufferView": 4, "componentType": 5126, "count": 6, "type": "VEC4"},
                          {"bufferView": 5, "componentType": 5126, "count": 2, "type": "VEC3"}]
animated["animations"] = [{"name": "move", "channels": [
    {"sampler": i, "target": {"node": 0, "path": p}} for i, p in enumerate(moves)], "samplers": [
    {"input": 2, "output": 3, "interpolation": "LINEAR"},
    {"input": 2, "output": 4, "interpolation": "CUBICSPLINE"},
    {"input": 2, "output": 5, "interpolation": "STEP"}]}]
out("fuzz_sequence", "triangle_moving", "scene: input.gltf\ncamera: {position: [0, 0, 3], look_at: [0, 0, 0], "
    "resolution: [4, 4]}\nlight: {position: [0, 0, 3]}\ntime: {bins: 8}\n"
    "sequence: {rate: 4 Hz, count: 5, video: false}\n\0" + json.dumps(animated))

# npy and a saved render (transient.json, NUL, transient.npy)
out("fuzz_npy", "volume.npy", npy((2, 1, 2, 3), [float(i) for i in range(12)]))
out("fuzz_npy", "scalar.npy", npy((), [1.5]))
meta = json.dumps({"time": {"start_s": 5e-9, "bin_width_s": 1e-11, "bins": 2}, "channels": ["R", "G", "B"]})
out("fuzz_saved_volume", "render", meta.encode() + b"\0" + npy((2, 1, 2, 3), [float(i) for i in range(12)]))

# SPAD table files (fuzz/SpadTablesInput.h: first byte 0 DNL .csv, 1 DNL .npy,
# 2 dark count map .npy, 3 afterpulse delay table .csv, 4 the same as .npy),
# each fitting its config (8 TDC bins, 4 x 4 pixels)
dnl = [0.25, -0.25, 0.1, -0.1, 0.0, 0.5, -0.5, 0.0]
out("fuzz_spad_tables", "dnl_csv", b"\0" + ("# DNL per bin\ndnl\n" + "".join("%g\n" % d for d in dnl)).encode())
out("fuzz_spad_tables", "dnl_npy", b"\1" + npy((8,), dnl))
out("fuzz_spad_tables", "dcr_npy", b"\2" + npy((4, 4), [25.0 * (1 + i) for i in range(16)]))
ap = [(1e-9 * (k + 0.5), 2.0 ** -k) for k in range(6)]
out("fuzz_spad_tables", "afterpulse_csv", b"\3" + ("delay_s,density\n" + "".join("%g,%g\n" % r for r in ap)).encode())
out("fuzz_spad_tables", "afterpulse_npy", b"\4" + npy((6, 2), [v for r in ap for v in r]))

# measured scattering-delay kernels (fuzz/ResponseTableInput.h: first byte
# even a .csv, odd an (n, 2) .npy; (byte / 2) mod 5 the delay unit s, ms, us,
# ns, ps): an exponential of 2.5 ns sampled every 0.25 ns
decay = [(0.25 * k, 2.718281828 ** (-0.25 * k / 2.5)) for k in range(40)]
out("fuzz_response_table", "exponential_csv_s",
    b"\0" + ("# delay_s,weight\n" + "".join("%g,%g\n" % (t * 1e-9, w) for t, w in decay)).encode())
out("fuzz_response_table", "exponential_npy_ns", b"\7" + npy((40, 2), [v for r in decay for v in r]))

# camera files (fuzz/CameraFilesInput.h: first byte 0 OpenCV calibration YAML,
# 1 correlation waveform .csv, 2 the same as .npy, 3 vignetting map .npy,
# 4 PSF kernel .npy, 5 delay map .npy, 6 companding .csv, 7 noise table .csv)
out("fuzz_camera_files", "calibration_yaml", b"\0" + (
    "%YAML:1.0\n---\nimage_width: 8\nimage_height: 6\n"
    "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
    "   data: [ 7.5, 0., 3.5, 0., 7.5, 2.5, 0., 0., 1. ]\n"
    "distortion_coefficients: !!opencv-matrix\n   rows: 5\n   cols: 1\n   dt: d\n"
    "   data: [ -0.1, 0.02, 0.001, -0.002, 0. ]\n").encode())
wave = [1.0, 0.5, -0.25, -1.0, -0.25, 0.5]
out("fuzz_camera_files", "waveform_csv", b"\1" + ("phase_rad,value\n" + "".join(
    "%.6f,%g\n" % (2 * 3.141592653589793 * j / len(wave), v) for j, v in enumerate(wave))).encode())
out("fuzz_camera_files", "waveform_npy", b"\2" + npy((len(wave),), wave))
out("fuzz_camera_files", "vignetting_npy", b"\3" + npy((4, 4), [1.0 - 0.03 * i for i in range(16)]))
out("fuzz_camera_files", "psf_npy", b"\4" + npy((3, 3), [0, 1, 0, 1, 4, 1, 0, 1, 0]))
out("fuzz_camera_files", "delay_npy", b"\5" + npy((4, 4), [1e-11 * i for i in range(16)]))
out("fuzz_camera_files", "companding_csv", b"\6" + b"in_dn,out_dn\n0,0\n1000,1000\n4095,2000\n")
out("fuzz_camera_files", "noise_csv", b"\7" + b"mean_e,raw_e\n10,9\n10,12\n12,11\n")

# Inputs once taken without a word (issue 39), the regression files as they
# are: a key given twice, an alias bomb, a calibration with a key twice, a
# saved volume of NaN.
for target, name in [("fuzz_config", "config/duplicate_key.yaml"),
                     ("fuzz_config", "config/alias_bomb.yaml"),
                     ("fuzz_config", "config/medium_sigma_float_overflow.yaml"),
                     ("fuzz_config", "config/medium_visibility_subnormal.yaml"),
                     ("fuzz_config", "config/medium_g_nan.yaml"),
                     ("fuzz_config", "config/medium_sigma_infinite.yaml"),
                     ("fuzz_config", "config/medium_phase_list.yaml"),
                     ("fuzz_config", "config/medium_albedo_short.yaml"),
                     ("fuzz_camera_files", "camera_files/lens_duplicate_key_yaml"),
                     ("fuzz_saved_volume", "saved_volume/all_nan")]:
    out(target, os.path.basename(name),
        open(os.path.join(src, "tests", "regressions", name), "rb").read())

# batch files (fuzz/BatchInput.h: the bytes are the batch, beside tiny.yaml):
# a product and a zip sweep with `set` and named runs, runs alone (a sensor
# list as a value, a default name), a sweep of mappings, and the base alone
out("fuzz_batch", "sweep_and_runs.yaml",
    "base: tiny.yaml\noutput: out/sweep\nset: {time.bins: 12}\nsweep:\n  product:\n"
    "    light.position: [[0.28, 0.5, 0.28], [0.2, 0.5, 0.2]]\n    render.seed: [1, 2, 3]\n"
    "  zip:\n    camera.resolution: [[4, 4], [2, 2]]\n    time.bin_width: [10 ps, 20 ps]\n"
    "runs:\n  - name: baseline\n    set: {render.seed: 7}\n  - set: {time.bins: 8}\n")
out("fuzz_batch", "runs_only.yaml",
    "base: tiny.yaml\nruns:\n  - name: spad.1+a,b-c_d\n"
    "    set: {sensors: [{type: spad, bins: 8}]}\n  - {}\n")
out("fuzz_batch", "sweep_mappings.yaml",
    "base: tiny.yaml\nsweep:\n  product:\n    sensors.0: [{type: spad, bins: 4}, {type: cwtof}]\n"
    "    time: [{bins: 8}, {bins: 4, bin_width: 1 m}]\n")
out("fuzz_batch", "base_only.yaml", "base: tiny.yaml\n")

# capture.h5 (output.format: hdf5): HDF5 has no hand-writable form here (no
# h5py), so a 4 x 4 pixel, 8 bin render of the demo by the CLI, CPU backend,
# no sensors (transient, steady and depth: 18 KB, mostly HDF5's zero-padded
# chunk index), and its first half. Its transient.json attribute records the
# render's timings, so each run changes a few bytes.
cli = os.path.join(src, "build", "apps", "cli", "tofsim")
if os.path.exists(cli):
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([cli, "render", os.path.join(src, "configs", "cornell_box.yaml"),
                        "-o", os.path.join(tmp, "out"), "-q",
                        "--set", "camera.resolution=[4,4]", "--set", "time.bins=8",
                        "--set", "time.bin_width=25 cm", "--set", "render.backend=cpu",
                        "--set", "render.threads=1", "--set", "output.format=hdf5",
                        "--set", "output.video=false", "--set", "output.components=[]",
                        "--set", "sensors=[]"], check=True, stderr=subprocess.DEVNULL)
        capture = open(os.path.join(tmp, "out", "capture.h5"), "rb").read()
    out("fuzz_capture_h5", "render_4x4x8.h5", capture)
    out("fuzz_capture_h5", "truncated_half.h5", capture[:len(capture) // 2])
else:
    print("make_seeds.py: %s not built (bash scripts/build.sh): fuzz_capture_h5's seeds left as "
          "they are" % cli, file=sys.stderr)
