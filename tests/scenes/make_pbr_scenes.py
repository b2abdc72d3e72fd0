#!/usr/bin/env python3
"""Writes the conformance scenes of glTF's metallic-roughness materials (tests/scenes/pbr_*.json
and their textures): a grid of spheres from smooth to rough, dielectric and metal, under a
directional and a point light; a textured floor and sphere with base color,
metallic-roughness, occlusion and emissive maps; spot and point lights over PBR shapes with
4x MSAA. ctest renders each with softraster and with Mesa llvmpipe (tests/reference) and
compares. Run it again after editing; the files it writes are committed."""
import json, math

from make_scenes import texture, write


def scene(name, lights, objects, camera, width=192, height=128, **image):
    img = {"width": width, "height": height, "background": [0.04, 0.04, 0.06, 1], **image}
    s = {"version": 2, "image": img, "camera": camera, "lights": lights, "objects": objects}
    write('pbr_' + name + '.json', json.dumps(s, indent=1))


def main():
    # Metallic-roughness: roughness (G) in bands across, metallic (B) on in alternate rows.
    texture('pbr_mr64.png', 64, 64, lambda x, y: [0, 40 + (x // 8) * 30, 255 if (y // 16) % 2 else 0, 255])
    # Occlusion (R): darker toward the cell edges.
    texture('pbr_ao64.png', 64, 64, lambda x, y: [int(255 * (0.3 + 0.7 * math.sin(math.pi * (x % 16 + 0.5) / 16) *
                                                               math.sin(math.pi * (y % 16 + 0.5) / 16))), 0, 0, 255])
    # Emissive: a few glowing dots.
    texture('pbr_emissive64.png', 64, 64, lambda x, y: [255, 160, 40, 255] if (x % 16 - 8) ** 2 + (y % 16 - 8) ** 2 < 6 else [0, 0, 0, 255])
    texture('pbr_base64.png', 64, 64, lambda x, y: [200, 90 + (x * 2) % 100, 60, 255] if (x // 16 + y // 16) % 2 else [70, 120, 190, 255])

    sun = {"direction": [-0.4, -0.6, -0.7], "color": [0.9, 0.88, 0.85]}
    lights = {"ambient": [0.06, 0.06, 0.07], "directional": [sun],
              "point": [{"position": [1.5, 1.2, 2.0], "color": [0.6, 0.7, 1.0], "intensity": 3}]}
    spheres = []
    for row, metallic in enumerate((0.0, 1.0)):
        for col, roughness in enumerate((0.05, 0.25, 0.5, 0.75, 1.0)):
            spheres.append({"builtin": {"type": "uv_sphere", "radius": 0.42, "rings": 32, "segments": 64},
                            "transform": {"translate": [-2.0 + col, 0.5 - row, 0]},
                            "material": {"shading": "pbr", "color": [0.9, 0.55, 0.3, 1], "metallic": metallic, "roughness": roughness}})
    scene('spheres', lights, spheres, {"eye": [0, 0, 4.6], "target": [0, 0, 0], "fov_y": 40})

    maps = {"shading": "pbr", "color": [1, 1, 1, 1], "texture": "textures/pbr_base64.png", "metallic": 1, "roughness": 1,
            "metallic_roughness_texture": "textures/pbr_mr64.png", "occlusion_texture": "textures/pbr_ao64.png",
            "occlusion_strength": 0.8, "emissive": [1, 1, 1], "emissive_texture": "textures/pbr_emissive64.png", "filter": "trilinear"}
    scene('textured_maps', {"ambient": [0.3, 0.3, 0.3], "directional": [sun],
                            "point": [{"position": [0.5, 1.0, 1.0], "color": [1, 1, 1], "intensity": 2, "range": 4}]},
          [{"builtin": {"type": "plane", "size": 4, "divisions": 8}, "material": maps},
           {"builtin": {"type": "uv_sphere", "radius": 0.6, "rings": 32, "segments": 64}, "transform": {"translate": [0, 0.6, -0.3]},
            "material": maps}],
          {"eye": [0, 1.8, 2.8], "target": [0, 0.2, -0.3], "fov_y": 50})

    # Only the maps: no base color texture, the metallic-roughness map alone.
    mr_only = {"shading": "pbr", "color": [0.8, 0.8, 0.85, 1], "metallic": 1, "roughness": 1,
               "metallic_roughness_texture": "textures/pbr_mr64.png"}
    shapes = [{"builtin": {"type": "plane", "size": 5, "divisions": 20}, "material": {"shading": "pbr", "color": [0.7, 0.7, 0.7, 1], "roughness": 0.6}},
              {"builtin": {"type": "torus", "major": 0.5, "minor": 0.2, "rings": 48, "segments": 24},
               "transform": {"translate": [-0.8, 0.5, 0], "rotate": [60, 0, 0]}, "material": mr_only},
              {"builtin": {"type": "cube", "size": 0.7}, "transform": {"translate": [0.8, 0.35, -0.2], "rotate": [0, 30, 0]},
               "material": {"shading": "pbr", "color": [0.2, 0.6, 0.3, 1], "metallic": 0.3, "roughness": 0.35}}]
    spots = {"ambient": [0.03, 0.03, 0.03], "directional": [{"direction": [0.5, -0.5, -0.7], "color": [0.2, 0.2, 0.25]}],
             "spot": [{"position": [-0.5, 2.5, 1.2], "direction": [0.2, -1, -0.4], "color": [1, 0.95, 0.85], "intensity": 5,
                       "inner_angle": 20, "outer_angle": 32}],
             "point": [{"position": [1.4, 0.8, 0.9], "color": [0.3, 0.5, 1.0], "intensity": 1.5, "range": 3}]}
    scene('spot_msaa', spots, shapes, {"eye": [0, 1.6, 3.2], "target": [0, 0.3, 0], "fov_y": 50}, samples=4)


if __name__ == '__main__':
    main()
