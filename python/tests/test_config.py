"""tofsim.load_config: the CLI's validation, errors as ConfigError."""

import os

import pytest

import tofsim
from conftest import SOURCE_DIR

CORNELL = os.path.join(SOURCE_DIR, "configs", "cornell_box.yaml")


def test_a_file_loads_as_the_cli_loads_it():
    config = tofsim.load_config(CORNELL, overrides={"camera.resolution": [24, 16], "time.bins": 50,
                                                  "sensors": []})
    assert config.resolution == (24, 16)
    assert config.time_axis["bins"] == 50
    assert config.scene_file.endswith("cornell_box.gltf")
    assert "bins: 50" in config.effective_yaml()


def test_cli_style_overrides_and_path_objects():
    import pathlib

    config = tofsim.load_config(pathlib.Path(CORNELL), overrides=["time.bin_width=20 ps"])
    assert config.time_axis["bin_width_s"] == pytest.approx(20e-12)


def test_a_bad_value_in_a_dict_names_the_key_path(plane_config):
    plane_config["camera"]["fov_y"] = 200
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.load_config(plane_config)
    err = e.value
    assert isinstance(err, ValueError)
    assert err.key == "camera.fov_y"
    assert err.file == "<dict>"
    assert err.line is None and err.column is None  # the JSON text is ours, not the user's
    assert "(0, 180)" in err.message
    assert "camera.fov_y" in str(err)


def test_a_bad_value_in_yaml_text_names_line_and_column(plane_config):
    text = (
        f"scene: {plane_config['scene']}\n"
        "camera: {resolution: [4, 4]}\n"
        "light: {}\n"
        "time:\n"
        "  bins: 64\n"
        "  bin_width: -3 ps\n"
    )
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.load_config(text)
    assert e.value.key == "time.bin_width"
    assert (e.value.file, e.value.line, e.value.column) == ("<string>", 6, 14)


def test_a_bad_value_in_a_file_names_the_file_and_line(tmp_path, plane_config):
    path = tmp_path / "bad.yaml"
    path.write_text(
        f"scene: {plane_config['scene']}\ncamera: {{}}\nlight: {{}}\ntime: {{bins: 64}}\n"
        "render: {renderr: ir}\n"
    )
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.load_config(str(path))
    assert (e.value.file, e.value.line, e.value.key) == (str(path), 5, "render.renderr")
    assert e.value.message == "unknown key (did you mean 'renderer'?)"


def test_an_override_is_named_as_the_source(plane_config):
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.load_config(plane_config, overrides={"time.bins": 0})
    assert e.value.key == "time.bins"
    assert e.value.file == "--set time.bins=0"


def test_integer_keys_take_integral_floats(plane_config):
    plane_config["time"]["bins"] = 64.0
    plane_config["sensors"] = [{"type": "spad", "cycles": 1e5}]
    assert tofsim.load_config(plane_config).time_axis["bins"] == 64
    plane_config["time"]["bins"] = 64.5
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.load_config(plane_config)
    assert e.value.key == "time.bins"
    assert "integer" in e.value.message


def test_a_missing_file_is_a_config_error():
    with pytest.raises(tofsim.ConfigError) as e:
        tofsim.load_config("/no/such/config.yaml")
    assert e.value.file == "/no/such/config.yaml"
