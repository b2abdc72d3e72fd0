#!/usr/bin/env python3
"""Writes the conformance scenes of shadow maps (tests/scenes/shadow_*.json): directional
and spot lights with their maps, point lights with their cubes (shadows across the faces'
seams), PCF kernels from one texel to 9 x 9, the bias and the
slope bias, shadows on every shading model that reads P (flat and lambert go through
blinn_phong's shader, pbr), with MSAA and in an sRGB picture. ctest renders each with
softraster and with Mesa llvmpipe (tests/reference) and compares. Run it again after
editing; the files it writes are committed."""
import json

from make_scenes import write


def scene(name, objects, lights, camera=None, width=192, height=128, **image):
    img = {"width": width, "height": height, "background": [0.05, 0.06, 0.08, 1], **image}
    camera = camera or {"eye": [0, 3.2, 4.2], "target": [0, 0.2, 0], "fov_y": 50}
    s = {"version": 2, "image": img, "camera": camera, "lights": lights, "objects": objects}
    write('shadow_' + name + '.json', json.dumps(s, indent=1))


def props(shading, extra=None):
    m = dict({"shading": shading, "color": [0.85, 0.8, 0.75, 1]}, **(extra or {}))
    floor = {"builtin": {"type": "plane", "size": 5, "divisions": 4}, "material": m}
    cube = {"builtin": {"type": "cube", "size": 0.8}, "transform": {"translate": [-0.9, 0.4, 0.2], "rotate": [0, 30, 0]},
            "material": dict(m, color=[0.9, 0.5, 0.3, 1])}
    ball = {"builtin": {"type": "uv_sphere", "radius": 0.5, "rings": 24, "segments": 48}, "transform": {"translate": [0.8, 0.9, -0.3]},
            "material": dict(m, color=[0.3, 0.6, 0.9, 1])}
    ring = {"builtin": {"type": "torus", "major": 0.45, "minor": 0.12}, "transform": {"translate": [0.2, 0.35, 1.0], "rotate": [60, 0, 20]},
            "material": dict(m, color=[0.5, 0.85, 0.4, 1])}
    return [floor, cube, ball, ring]


def main():
    sun = {"direction": [-0.5, -1.0, -0.4], "color": [0.9, 0.88, 0.85]}
    scene('directional', props("blinn_phong", {"specular": [0.4, 0.4, 0.4], "shininess": 24}),
          {"ambient": [0.15, 0.15, 0.18], "directional": [dict(sun, shadow={"size": 512})]})
    # One texel (hard edges) and 9 x 9 (soft); a low-resolution map magnifies the texels.
    scene('pcf0_lambert', props("lambert"), {"ambient": [0.15, 0.15, 0.18], "directional": [dict(sun, shadow={"size": 256, "pcf": 0})]})
    scene('pcf4_flat', props("flat"), {"ambient": [0.15, 0.15, 0.18],
                                       "directional": [dict(sun, shadow={"size": 1024, "pcf": 4, "bias": 0.03, "slope_bias": 3})]})
    # A spot light's perspective map and an unshadowed fill light, phong.
    spot = {"position": [1.5, 3.0, 1.5], "direction": [-1.5, -3.0, -1.5], "color": [1, 0.9, 0.7], "intensity": 14,
            "outer_angle": 40, "inner_angle": 30}
    fill = {"direction": [0.6, -0.3, -0.8], "color": [0.2, 0.22, 0.3]}
    scene('spot_phong', props("phong", {"specular": [0.3, 0.3, 0.3], "shininess": 16}),
          {"ambient": [0.05, 0.05, 0.05], "directional": [fill], "spot": [dict(spot, shadow={"size": 512, "pcf": 2})]})
    # Two shadowed lights on pbr, 4x MSAA, sRGB with ACES.
    pbr = props("pbr", {"metallic": 0.0, "roughness": 0.5})
    pbr[2]["material"] = dict(pbr[2]["material"], metallic=1.0, roughness=0.3)
    scene('pbr_two_lights_msaa', pbr,
          {"ambient": [0.1, 0.1, 0.12], "directional": [dict(sun, color=[2, 1.9, 1.8], shadow={"size": 1024})],
           "spot": [dict(spot, shadow={"size": 512})]},
          samples=4, color_space="srgb", tone_mapping="aces")
    # Gouraud lights the vertices: shadows do not reach it; the pbr floor beside it shows them.
    mixed = props("gouraud")
    mixed[0]["material"] = {"shading": "pbr", "color": [0.85, 0.8, 0.75, 1], "roughness": 0.7}
    scene('gouraud_unshadowed', mixed, {"ambient": [0.15, 0.15, 0.18], "directional": [dict(sun, shadow={"size": 512})]})
    # A point light's cube among the props: the floor below is in the -y face, beyond it in the
    # side faces, so shadows cross the seams; lambert with one texel, pbr with 5 x 5 and MSAA.
    bulb = {"position": [0.0, 1.5, 0.2], "color": [1, 0.95, 0.85], "intensity": 5}
    scene('point_cube_lambert', props("lambert"),
          {"ambient": [0.1, 0.1, 0.12], "point": [dict(bulb, shadow={"size": 256, "pcf": 0})]})
    scene('point_cube_blinn_phong', props("blinn_phong", {"specular": [0.4, 0.4, 0.4], "shininess": 24}),
          {"ambient": [0.1, 0.1, 0.12], "directional": [fill], "point": [dict(bulb, shadow={"size": 512})]})
    low = dict(bulb, position=[0.3, 1.0, 0.3], intensity=3)
    scene('point_cube_pbr_msaa', pbr,
          {"ambient": [0.1, 0.1, 0.12], "point": [dict(low, shadow={"size": 512, "pcf": 2, "bias": 0.05, "slope_bias": 3})]},
          samples=4, color_space="srgb", tone_mapping="aces")


if __name__ == '__main__':
    main()
