"""The writer of the quad scenes (make_corner.py, make_flim_slide.py,
make_fog_range.py, make_fog_box.py): Lambertian materials, quads as meshes,
one camera, written atomically through gltf_common.py. Each script keeps only
its geometry, materials and camera."""

import math

from gltf_common import add_camera, add_quads, finish, look_rotation, new_gltf, write_gltf


def rect_facing_z(x0, x1, y0, y1, z):
    """A rectangle in the plane z facing +z: corners counter-clockwise seen from +z."""
    return [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]


def quad_scene(script, scene_name, materials, quads, camera, extras=None):
    """The glTF document of `quads` (add_quads' rows) in Lambertian
    `materials` ((name, (r, g, b)): metallic 0, roughness 1) with one camera
    (name, vertical fov in degrees, position, view direction; +y up). extras:
    a material name's `extras` (a scene's own scattering delay)."""
    blob = bytearray()
    gltf = new_gltf("tofsim scripts/" + script, scene_name,
                    [(name, rgb, 0.0, 1.0) for name, rgb in materials])
    for m in gltf["materials"]:
        if extras and m["name"] in extras:
            m["extras"] = extras[m["name"]]
    add_quads(gltf, blob, quads)
    name, fov_y_deg, position, forward = camera
    add_camera(gltf, name, math.radians(fov_y_deg), position, look_rotation(forward))
    return finish(gltf, blob)


def write_quad_scene(default_name, *args, **kwargs):
    """quad_scene(...) written to argv[1] or configs/scenes/<default_name>:
    a script's whole main."""
    write_gltf(quad_scene(*args, **kwargs), default_name)
