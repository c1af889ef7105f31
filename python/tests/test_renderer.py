"""tofsim.Renderer: a scene prepared once and rendered many times, against
tofsim.render's bytes and the plane's closed form."""

import os

import numpy as np
import pytest

import tofsim
from conftest import SOURCE_DIR, write_plane_gltf
from test_render import expected_bins, peak_bins

CORNELL = os.path.join(SOURCE_DIR, "configs", "cornell_box.yaml")
SMALL_CORNELL = {"camera.resolution": [16, 16], "time.bins": 120, "time.bin_width": "20 ps",
                 "sensors": [], "output.video": False, "render.indirect.rsm_resolution": 8,
                 "render.backend": "cpu"}


def test_each_render_is_render_s_bytes_and_the_scene_is_prepared_once():
    renderer = tofsim.Renderer(CORNELL, overrides=SMALL_CORNELL)
    seen = []
    for x in (0.2, 0.3, 0.4):
        moved = {"light.attach_to_camera": False, "light.position": [x, 0.273, -0.8],
                 "light.direction": [0, 0, 1]}
        kept = renderer.render(moved)
        fresh = tofsim.render(tofsim.load_config(CORNELL, {**SMALL_CORNELL, **moved}))
        np.testing.assert_array_equal(kept.transient, fresh.transient)
        np.testing.assert_array_equal(kept.depth, fresh.depth)
        assert kept.files == [] and kept.output_dir is None
        assert kept.transient.sum() > 0
        seen.append(kept.transient)
    # The light moved: each render differs from the one before.
    assert not np.array_equal(seen[0], seen[1])
    assert not np.array_equal(seen[1], seen[2])
    assert renderer.scene_preparations == 1


def test_a_moved_camera_sees_the_plane_at_its_closed_form_bins(plane_config):
    renderer = tofsim.Renderer(plane_config)
    for z in (1.5, 1.2):
        moved = {"camera.position": [0, 0, z], "light.position": [0, 0, z]}
        result = renderer.render(moved)
        config = dict(plane_config, camera=dict(plane_config["camera"], position=[0, 0, z]))
        expected = expected_bins(config, result.time)
        checked = expected >= 0
        assert checked.sum() > 900
        np.testing.assert_array_equal(peak_bins(result.direct)[checked], expected[checked])
    assert renderer.scene_preparations == 1


def test_what_the_renderer_was_made_from_cannot_change(plane_config, tmp_path):
    renderer = tofsim.Renderer(plane_config)
    other = write_plane_gltf(tmp_path / "other.gltf", side=2.0)
    with pytest.raises(ValueError, match="the scene"):
        renderer.render({"scene": other})
    with pytest.raises(ValueError, match="render.renderer"):
        renderer.render({"render.renderer": "reference"})
    # A bad override is the config's located error, and the renderer goes on.
    with pytest.raises(tofsim.ConfigError, match="bin_width"):
        renderer.render({"time.bin_width": "-3 ps"})
    assert renderer.render().transient.shape == (30, 40, 1200, 3)
