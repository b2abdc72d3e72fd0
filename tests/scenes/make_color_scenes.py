#!/usr/bin/env python3
"""Writes the conformance scenes of color spaces and tone mapping (tests/scenes/color_*.json):
sRGB textures minified with mipmaps averaged in linear light, blending in linear light, the
MSAA resolve and the supersampling filter of an sRGB picture, PBR with sRGB base color and
emissive maps, a model file in an sRGB scene, and the Reinhard and ACES curves with
exposure. ctest renders each with softraster and with Mesa llvmpipe (tests/reference) and
compares. Run it again after editing; the files it writes are committed."""
import json

from make_scenes import write

SUN = {"direction": [-0.4, -0.6, -0.7], "color": [0.9, 0.88, 0.85]}


def scene(name, objects, camera, lights=None, width=192, height=128, draw_order=None, **image):
    img = {"width": width, "height": height, "background": [0.05, 0.06, 0.08, 1], **image}
    s = {"version": 2, "image": img, "camera": camera, "objects": objects}
    if draw_order:
        s["draw_order"] = draw_order
    if lights:
        s["lights"] = lights
    write('color_' + name + '.json', json.dumps(s, indent=1))


def quad(x, y, z, size, material, rotate=0):
    return {"builtin": {"type": "plane", "size": size}, "transform": {"translate": [x, y, z], "rotate": [90, 0, rotate]},
            "material": material}


def main():
    # A checkerboard floor to the horizon, trilinear: far away the texels average to gray,
    # which in linear light is lighter (the mean of black and white is 188, not 128).
    floor = {"builtin": {"type": "plane", "size": 40, "divisions": 4},
             "material": {"shading": "unlit", "texture": "textures/checker128.png", "filter": "trilinear"}}
    ball = {"builtin": {"type": "uv_sphere", "radius": 0.6, "rings": 24, "segments": 48}, "transform": {"translate": [0, 0.6, 0]},
            "material": {"shading": "lambert", "texture": "textures/grid64.png", "filter": "trilinear"}}
    scene('srgb_textured', [floor, ball], {"eye": [0, 1.2, 3], "target": [0, 0.3, -4], "fov_y": 55},
          {"ambient": [0.1, 0.1, 0.1], "directional": [SUN]}, color_space="srgb")

    # Blending in linear light: alpha, additive and custom equations over a ramp (general back end).
    ramp = quad(0, 0, -0.5, 3.2, {"shading": "unlit", "texture": "textures/alpha_ramp.png", "filter": "nearest"})
    layers = [ramp]
    blends = ["alpha", "additive", {"equation": "subtract", "src": "one", "dst": "one"},
              {"equation": "max", "src": "one", "dst": "one"}, {"equation": "add", "src": "dst_color", "dst": "zero"},
              {"equation": "reverse_subtract", "src": "src_alpha", "dst": "one", "equation_alpha": "add", "src_alpha": "one",
               "dst_alpha": "zero"}]
    # (A difference that lands near black shows llvmpipe's approximate sRGB decoding: the
    # encoding's slope there is 12.92, so 0.001 of light is 3 levels. The subtracted colors
    # below keep clear of it.)
    colors = [[0.9, 0.2, 0.1, 0.5], [0.1, 0.3, 0.9, 0.6], [1, 0.9, 0.8, 1], [0.1, 0.7, 0.3, 1], [0.8, 0.8, 0.3, 1],
              [0.3, 0.2, 0.1, 0.5]]
    for i, (blend, color) in enumerate(zip(blends, colors)):
        layers.append(quad(-1.0 + (i % 3) * 1.0, 0.45 - (i // 3) * 0.9, 0.1 * i, 0.8,
                           {"shading": "unlit", "color": color, "blend": blend}, rotate=10 * i))
    scene('srgb_blend', layers, {"projection": "orthographic", "eye": [0, 0, 3], "target": [0, 0, 0], "height": 2.2},
          color_space="srgb", draw_order="file")

    # Edges resolved in linear light: thin bright and dark slivers, 4x MSAA.
    slivers = []
    for i in range(9):
        slivers.append({"builtin": {"type": "plane", "size": 0.12 + 0.02 * i},
                        "transform": {"translate": [-1.6 + 0.4 * i, 0, 0], "rotate": [90, 0, 7 * i + 3], "scale": [1, 1, 14]},
                        "material": {"shading": "unlit", "color": [1, 1, 1, 1] if i % 2 else [0.9, 0.3, 0.05, 1]}})
    scene('srgb_msaa', slivers, {"projection": "orthographic", "eye": [0, 0, 3], "target": [0, 0, 0], "height": 2.2},
          samples=4, color_space="srgb", background=[0.0, 0.0, 0.02, 1])
    scene('srgb_supersample', slivers, {"projection": "orthographic", "eye": [0, 0, 3], "target": [0, 0, 0], "height": 2.2},
          supersample=2, color_space="srgb", background=[0.0, 0.0, 0.02, 1])

    # PBR with sRGB color maps (base color, emissive) and linear data maps, bright lights, ACES.
    maps = {"shading": "pbr", "color": [1, 1, 1, 1], "texture": "textures/pbr_base64.png", "metallic": 1, "roughness": 1,
            "metallic_roughness_texture": "textures/pbr_mr64.png", "occlusion_texture": "textures/pbr_ao64.png",
            "emissive": [2, 2, 2], "emissive_texture": "textures/pbr_emissive64.png", "filter": "trilinear"}
    bright = {"ambient": [0.2, 0.2, 0.2], "directional": [{"direction": [-0.4, -0.6, -0.7], "color": [3, 2.9, 2.8]}],
              "point": [{"position": [0.5, 1.0, 1.0], "color": [1, 0.9, 0.8], "intensity": 6, "range": 4}]}
    shapes = [{"builtin": {"type": "plane", "size": 4, "divisions": 8}, "material": maps},
              {"builtin": {"type": "uv_sphere", "radius": 0.6, "rings": 32, "segments": 64}, "transform": {"translate": [0, 0.6, -0.3]},
               "material": maps}]
    camera = {"eye": [0, 1.8, 2.8], "target": [0, 0.2, -0.3], "fov_y": 50}
    scene('srgb_pbr_aces', shapes, camera, bright, color_space="srgb", tone_mapping="aces", exposure=0.8)

    # The tone curves on their own (no sRGB): smooth to rough spheres under light far above 1.
    spheres = []
    for col, roughness in enumerate((0.1, 0.4, 0.8)):
        for row, metallic in enumerate((0.0, 1.0)):
            spheres.append({"builtin": {"type": "uv_sphere", "radius": 0.42, "rings": 32, "segments": 64},
                            "transform": {"translate": [-1.0 + col, 0.5 - row, 0]},
                            "material": {"shading": "pbr", "color": [0.9, 0.6, 0.35, 1], "metallic": metallic, "roughness": roughness}})
    spheres.append({"builtin": {"type": "cube", "size": 0.5}, "transform": {"translate": [1.9, 0, 0], "rotate": [30, 40, 0]},
                    "material": {"shading": "blinn_phong", "color": [0.3, 0.6, 0.9, 1], "specular": [1, 1, 1], "shininess": 40}})
    hot = {"ambient": [0.3, 0.3, 0.3], "directional": [{"direction": [-0.3, -0.5, -0.8], "color": [4, 4, 3.6]}],
           "point": [{"position": [1.0, 1.2, 1.5], "color": [0.5, 0.7, 1.0], "intensity": 8}]}
    sphere_camera = {"eye": [0.4, 0, 4.2], "target": [0.4, 0, 0], "fov_y": 40}
    scene('tone_reinhard', spheres, sphere_camera, hot, tone_mapping="reinhard", exposure=1.5)
    scene('tone_aces_srgb_msaa', spheres, sphere_camera, hot, tone_mapping="aces", color_space="srgb", samples=4)
    scene('exposure_only', spheres, sphere_camera, hot, exposure=0.35)

    # A glTF model (base color texture, lights of its own) in an sRGB scene.
    model = {"model": "models/textured.glb", "transform": {"rotate": [20, 35, 0]}}
    scene('srgb_model', [model], {"eye": [0, 0.5, 3.2], "target": [0, 0, 0], "fov_y": 40},
          {"ambient": [0.15, 0.15, 0.15], "directional": [SUN]}, color_space="srgb", tone_mapping="reinhard")


if __name__ == '__main__':
    main()
