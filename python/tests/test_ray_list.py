"""A capture of rays from a file (`rays:` in place of `camera:`) through
tofsim.render and tofsim.Renderer: each ray's light arrives after light ->
hit -> the ray's own origin."""

import numpy as np

import tofsim
from conftest import write_plane_gltf


def ray_config(tmp_path, rays):
    np.save(tmp_path / "rays.npy", rays)  # float64 (N, 6)
    return {
        "scene": write_plane_gltf(tmp_path / "plane.gltf"),
        "rays": {"file": str(tmp_path / "rays.npy")},
        "light": {"type": "point", "position": [0, 0, 1.5], "intensity": [2.0, 1.0, 0.5]},
        "time": {"start": "0 m", "bin_width": "2 mm", "bins": 2500},
        "render": {"indirect": {"enabled": False}, "pixel_footprint": False},
        "output": {"directory": str(tmp_path / "out")},
    }


def test_rays_from_their_own_origins_arrive_after_light_to_hit_to_origin(tmp_path):
    origins = np.array([[0.0, 0.0, 1.0], [0.5, -0.3, 2.0], [-0.4, 0.6, 0.7]])
    hits = np.array([[0.1, 0.2, 0.0], [-0.3, 0.1, 0.0], [0.4, -0.5, 0.0]])
    d = hits - origins
    rays = np.hstack([origins, 3.0 * d])  # unnormalised: the loader normalises
    config = ray_config(tmp_path, rays)
    result = tofsim.render(config)
    assert result.transient.shape == (1, 3, 2500, 3)
    light = np.array([0.0, 0.0, 1.5])
    path = np.linalg.norm(light - hits, axis=1) + np.linalg.norm(hits - origins, axis=1)
    expected = np.floor(path / 0.002).astype(int)
    peaks = result.transient[0, :, :, 0].argmax(axis=1)
    assert np.all(np.abs(peaks - expected) <= 1), (peaks, expected)
    renderer = tofsim.Renderer(config)
    again = renderer.render()
    np.testing.assert_array_equal(again.transient, result.transient)
