#!/usr/bin/env python3
"""Writes the conformance scenes of screen-space ambient occlusion (tests/scenes/ao_*.json):
objects resting on a floor and in a corner, under perspective and orthographic cameras, in
linear and sRGB pictures, with MSAA and supersampling, and each setting of the effect.
ctest renders each with softraster and with Mesa llvmpipe (tests/reference) and compares.
Run it again after editing; the files it writes are committed."""
import json

from make_scenes import write


def scene(name, objects, ao, camera=None, width=192, height=128, lights=None, **image):
    img = {"width": width, "height": height, "background": [0.55, 0.6, 0.7, 1], **image}
    camera = camera or {"eye": [0, 2.6, 4.2], "target": [0, 0.3, 0], "fov_y": 45}
    lights = lights or {"ambient": [0.45, 0.45, 0.45], "directional": [{"direction": [-0.4, -1.0, -0.6], "color": [0.5, 0.5, 0.5]}]}
    s = {"version": 2, "image": img, "camera": camera, "lights": lights, "objects": objects, "ambient_occlusion": ao}
    write('ao_' + name + '.json', json.dumps(s, indent=1))


def props(shading="lambert"):
    m = {"shading": shading, "color": [0.85, 0.82, 0.78, 1]}
    floor = {"builtin": {"type": "plane", "size": 5, "divisions": 4}, "material": m}
    back = {"builtin": {"type": "plane", "size": 5, "divisions": 4}, "transform": {"translate": [0, 2.5, -1.2], "rotate": [90, 0, 0]},
            "material": m, "cull": "none"}
    cube = {"builtin": {"type": "cube", "size": 0.8}, "transform": {"translate": [-0.9, 0.4, -0.2], "rotate": [0, 30, 0]},
            "material": dict(m, color=[0.9, 0.6, 0.4, 1])}
    ball = {"builtin": {"type": "uv_sphere", "radius": 0.5, "rings": 24, "segments": 48}, "transform": {"translate": [0.8, 0.5, 0.1]},
            "material": dict(m, color=[0.4, 0.65, 0.9, 1])}
    ring = {"builtin": {"type": "torus", "major": 0.45, "minor": 0.12}, "transform": {"translate": [0.1, 0.12, 1.0]},
            "material": dict(m, color=[0.5, 0.85, 0.4, 1])}
    return [floor, back, cube, ball, ring]


def main():
    scene('corner', props(), {"radius": 0.5})
    scene('strong_wide', props(), {"radius": 1.0, "intensity": 4, "bias": 0.05})
    scene('ortho_supersample', props(), {"radius": 0.4, "intensity": 3},
          camera={"eye": [2.5, 3.0, 4.0], "target": [0, 0.3, 0], "projection": "orthographic", "height": 4.0}, supersample=2)
    scene('srgb_msaa_blinn', props("blinn_phong"), {"radius": 0.6}, samples=4, color_space="srgb")


if __name__ == '__main__':
    main()
