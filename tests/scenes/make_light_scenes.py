#!/usr/bin/env python3
"""Writes the conformance scenes of point and spot lights and of Phong shading
(tests/scenes/light_*.json): point lights with and without a range over every lit shading
model, spot lights with hard and soft cones on a floor, Phong beside Blinn-Phong, 64
colored point lights over a floor, and lights with directional ones together. ctest renders
each with softraster and with Mesa llvmpipe (tests/reference) and compares. Run it again
after editing; the files it writes are committed."""
import json, math

from make_scenes import write

CAM = {"eye": [0, 2.2, 4.2], "target": [0, 0, -0.3], "fov_y": 50}
FLOOR = {"builtin": {"type": "plane", "size": 6, "divisions": 24}}


def scene(name, lights, objects, camera=CAM, width=160, height=120, **image):
    img = {"width": width, "height": height, "background": [0.05, 0.05, 0.08, 1], **image}
    s = {"version": 2, "image": img, "camera": camera, "lights": lights, "objects": objects}
    write('light_' + name + '.json', json.dumps(s, indent=1))


def mat(shading, color, **extra):
    return dict({"shading": shading, "color": color}, **extra)


def shapes(shading, **extra):
    """A floor, a sphere, a torus and a cube, all with one shading model."""
    return [dict(FLOOR, material=mat(shading, [0.8, 0.8, 0.8, 1], **extra)),
            {"builtin": {"type": "uv_sphere", "radius": 0.55, "rings": 24, "segments": 48},
             "transform": {"translate": [-1.0, 0.55, -0.4]}, "material": mat(shading, [0.9, 0.5, 0.3, 1], **extra)},
            {"builtin": {"type": "torus", "major": 0.45, "minor": 0.17, "rings": 40, "segments": 20},
             "transform": {"translate": [0.9, 0.45, 0.1], "rotate": [70, 20, 0]}, "material": mat(shading, [0.3, 0.7, 0.9, 1], **extra)},
            {"builtin": {"type": "cube", "size": 0.6}, "transform": {"translate": [0.2, 0.3, -1.3], "rotate": [0, 35, 0]},
             "material": mat(shading, [0.6, 0.9, 0.4, 1], **extra)}]


def main():
    spec = {"specular": [0.6, 0.6, 0.6], "shininess": 24}
    points = {"ambient": [0.05, 0.05, 0.05],
              "point": [{"position": [-0.3, 1.4, 0.9], "color": [1, 0.9, 0.7], "intensity": 3},
                        {"position": [1.6, 0.6, -1.0], "color": [0.4, 0.6, 1], "intensity": 2.5, "range": 3}]}
    for shading in ("lambert", "flat", "gouraud", "blinn_phong", "phong"):
        scene('point_' + shading, points, shapes(shading, **(spec if 'phong' in shading else {})))

    spots = {"ambient": [0.03, 0.03, 0.03],
             "spot": [{"position": [-1.2, 2.5, 0.5], "direction": [0.3, -1, -0.2], "color": [1, 0.95, 0.8], "intensity": 6,
                       "inner_angle": 15, "outer_angle": 25},
                      {"position": [1.5, 2.0, -0.5], "direction": [-0.6, -1, 0.1], "color": [0.5, 0.7, 1], "intensity": 5,
                       "range": 5, "outer_angle": 35}]}
    scene('spot_lambert', spots, shapes("lambert"))
    scene('spot_blinn_phong', spots, shapes("blinn_phong", **spec))

    # Phong and Blinn-Phong side by side under one directional light: Phong's highlight is
    # smaller for the same exponent.
    sun = {"ambient": [0.08, 0.08, 0.1], "directional": [{"direction": [-0.5, -0.6, -0.7], "color": [0.9, 0.9, 0.85]}]}
    pair = []
    for x, shading in ((-0.7, "phong"), (0.7, "blinn_phong")):
        pair.append({"builtin": {"type": "uv_sphere", "radius": 0.6, "rings": 32, "segments": 64}, "transform": {"translate": [x, 0.6, 0]},
                     "material": mat(shading, [0.7, 0.3, 0.3, 1], specular=[0.8, 0.8, 0.8], shininess=16)})
    scene('phong_vs_blinn', sun, pair, camera={"eye": [0, 1.0, 3.2], "target": [0, 0.5, 0], "fov_y": 45})

    # 64 small colored point lights in a ring over a floor, each with a short range.
    many = {"ambient": [0.02, 0.02, 0.02], "point": []}
    for i in range(64):
        a = 2 * math.pi * i / 64
        r = 1.0 + 1.2 * (i % 4) / 3
        many["point"].append({"position": [round(r * math.cos(a), 4), 0.25 + 0.1 * (i % 3), round(r * math.sin(a) - 0.5, 4)],
                              "color": [0.5 + 0.5 * math.cos(a), 0.5 + 0.5 * math.cos(a + 2.1), 0.5 + 0.5 * math.cos(a + 4.2)],
                              "intensity": 0.35, "range": 1.1})
    scene('64_points', many, [dict(FLOOR, material=mat("blinn_phong", [0.9, 0.9, 0.9, 1], specular=[0.3, 0.3, 0.3], shininess=8)),
                              {"builtin": {"type": "uv_sphere", "radius": 0.5, "rings": 24, "segments": 48},
                               "transform": {"translate": [0, 0.5, -0.5]}, "material": mat("lambert", [0.8, 0.8, 0.8, 1])}])

    # Every kind together, with a texture and 4x MSAA.
    mixed = {"ambient": [0.06, 0.06, 0.06], "directional": sun["directional"], "point": points["point"][:1], "spot": spots["spot"][:1]}
    scene('mixed_msaa', mixed, shapes("blinn_phong", **spec) + [], samples=4)


if __name__ == '__main__':
    main()
