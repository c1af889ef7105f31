"""A config's sensors come back from tofsim.render, tofsim.Renderer and
tofsim.load as result.sensors[name][output] NumPy arrays with their metadata,
the same numbers `tofsim render` writes (issue 44, items 1 and 2)."""

import json

import numpy as np
import pytest

import tofsim

SPAD = {"type": "spad", "name": "spad", "cycles": 2000, "pde": 0.3, "dark_count_rate": "1 kHz",
        "channel_weights": [1, 1, 1]}
CWTOF = {"type": "cwtof", "name": "tof", "frequencies": ["20 MHz", "100 MHz"],
         "channel_weights": [1, 1, 1], "source_scale": 10000}


def sensed_config(plane_config):
    plane_config["camera"]["resolution"] = [8, 6]
    plane_config["time"] = {"start": "2.5 m", "bin_width": "20 mm", "bins": 120}
    plane_config["sensors"] = [SPAD, CWTOF]
    return plane_config


def written(out, sensor, output):
    """The CLI's numbers of an output: its .npy (every output has one)."""
    return np.load(out / "sensors" / sensor / (output + ".npy"))


def test_render_returns_the_configs_sensors_as_the_cli_writes_them(plane_config, tmp_path):
    config = sensed_config(plane_config)
    result = tofsim.render(config)
    assert set(result.sensors) == {"spad", "tof"}
    spad = result.sensors["spad"]
    assert spad["spad_counts"].shape == (6, 8, 120) and spad["spad_counts"].sum() > 0
    assert spad.metadata["spad_counts"]["axes"] == ["y", "x", "t"]
    assert spad.sensor["type"] == "spad"
    assert result.output_dir is None and result.files == []
    saved = tofsim.render(config, output_dir=tmp_path / "cli")
    for name, outputs in result.sensors.items():
        assert set(outputs) == set(saved.sensors[name])
        for output, array in outputs.items():
            np.testing.assert_array_equal(array, written(tmp_path / "cli", name, output))


def test_load_reads_every_sensor_output_and_its_metadata(plane_config, tmp_path):
    out = tmp_path / "cli"
    tofsim.render(sensed_config(plane_config), output_dir=out)
    loaded = tofsim.load(out)
    tof = loaded.sensors["tof"]
    depth_names = [n for n in tof if n.startswith("cwtof_depth")]
    assert depth_names, sorted(tof)
    for name in depth_names:
        meta = json.loads((out / "sensors" / "tof" / (name + ".json")).read_text())
        assert meta["files"]["npy"] == name + ".npy" and meta["files"]["data"] == name + ".exr"
        # The image's .npy holds the .exr's numbers.
        exr = tofsim.read_array(out / "sensors" / "tof" / (name + ".exr"))
        np.testing.assert_array_equal(tof[name], exr.reshape(tof[name].shape))
        assert tof.metadata[name]["unit"] == "m" and "files" not in tof.metadata[name]
    # Depth on the plane: finite where the camera sees it.
    assert np.isfinite(tof[depth_names[0]]).any()
    assert loaded.sensors["spad"]["spad_counts"].sum() > 0


def test_a_kept_renderer_senses_in_memory_the_numbers_the_cli_writes(plane_config, tmp_path):
    config = sensed_config(plane_config)
    saved = tofsim.render(config, output_dir=tmp_path / "cli")
    kept = tofsim.Renderer(config).render()
    assert set(kept.sensors) == {"spad", "tof"}
    for name, outputs in saved.sensors.items():
        assert set(kept.sensors[name]) >= set(outputs) - {"spad_histograms"}
        for output in outputs:
            if output in kept.sensors[name]:
                np.testing.assert_array_equal(kept.sensors[name][output], outputs[output],
                                              err_msg=f"{name}/{output}")


def test_a_config_without_sensors_has_none(plane_config):
    plane_config["camera"]["resolution"] = [4, 3]
    assert tofsim.render(plane_config).sensors == {}
