#!/usr/bin/env python3
"""Writes the bench scenes of scene format version 2 (1080p):
  bench_stencil      a stencil-masked reflection: a mirror floor marks the stencil, the
                     reflected objects draw only inside it, then the mirror and the objects
  bench_blend_modes  twelve full-screen layers, each with another blend equation and factors
  bench_msaa16       bench_msaa's sphere with 16 samples (llvmpipe cannot: softraster only)
  bench_ibl          60 pbr spheres lit by an environment alone (image-based lighting), their
                     roughness across, metallic down: the environment term at every pixel
Run it again after editing; the files it writes are committed."""
import json, os

HERE = os.path.dirname(os.path.abspath(__file__))
LIGHTS = {"ambient": [0.12, 0.12, 0.14], "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.9, 0.85, 0.8]}]}


def write(name, scene):
    with open(os.path.join(HERE, name + '.json'), 'w') as f:
        json.dump(scene, f, indent=1)


def stencil(func, ref, op="keep"):
    return {"func": func, "ref": ref, "pass": op}


objects, reflected = [], []
for i in range(6):
    x, z = -2.5 + i, -0.5 - 0.6 * (i % 2)
    obj = {"builtin": {"type": "uv_sphere", "radius": 0.42, "rings": 96, "segments": 192} if i % 2 == 0 else
           {"type": "torus", "major": 0.38, "minor": 0.14, "rings": 128, "segments": 64},
           "material": {"shading": "blinn_phong", "color": [0.3 + 0.12 * i, 0.8 - 0.1 * i, 0.5, 1], "specular": [0.4, 0.4, 0.4],
                        "shininess": 24}}
    objects.append(dict(obj, transform={"translate": [x, 0.5, z], "rotate": [30 * i, 20, 0]}))
    # mirrored in the floor (y = 0): scale y by -1, which flips the windings
    reflected.append(dict(obj, transform={"translate": [x, -0.5, z], "rotate": [-30 * i, -20, 0], "scale": [1, -1, 1]},
                          front_face="cw", stencil=stencil("equal", 1)))
mirror = {"builtin": {"type": "plane", "size": 7}, "cull": "none"}
write('bench_stencil', {
    "version": 2, "draw_order": "file",
    "image": {"width": 1920, "height": 1080, "background": [0.08, 0.09, 0.12, 1]},
    "camera": {"eye": [0, 2.2, 4.5], "target": [0, 0, -0.5], "fov_y": 50},
    "lights": LIGHTS,
    "objects": [dict(mirror, material={"shading": "unlit", "color_mask": [False] * 4}, depth={"write": False},
                     stencil=stencil("always", 1, "replace"))] + reflected +
               [dict(mirror, material={"shading": "lambert", "color": [0.5, 0.6, 0.8, 0.4], "blend": "alpha"})] + objects})

eqs = ["add", "subtract", "reverse_subtract", "min", "max"]
factors = [("src_alpha", "one_minus_src_alpha"), ("one", "one"), ("dst_color", "zero"), ("constant_color", "one_minus_src_color"),
           ("one_minus_dst_alpha", "src_alpha"), ("src_alpha_saturate", "one")]
layers = []
for i in range(12):
    src, dst = factors[i % len(factors)]
    layers.append({"builtin": {"type": "plane", "size": 4}, "transform": {"translate": [0, 0, -7 + 0.5 * i], "rotate": [90, 0, 0]},
                   "material": {"shading": "lambert", "color": [0.2 + 0.06 * i, 0.9 - 0.05 * i, 0.5, 0.35 + 0.04 * i],
                                "blend": {"equation": eqs[i % len(eqs)], "src": src, "dst": dst, "src_alpha": "one",
                                          "dst_alpha": "one_minus_src_alpha", "constant": [0.3, 0.5, 0.7, 0.5]}},
                   "depth": {"test": False}})
write('bench_blend_modes', {
    "version": 2, "draw_order": "file",
    "image": {"width": 1920, "height": 1080, "background": [0.2, 0.2, 0.25, 1]},
    "camera": {"projection": "orthographic", "eye": [0, 0, 10], "target": [0, 0, 0], "height": 2, "near": 1, "far": 50},
    "lights": {"ambient": [0.3, 0.3, 0.3], "directional": [{"direction": [0, 0, -1], "color": [0.7, 0.7, 0.7]}]},
    "objects": layers})

msaa = json.load(open(os.path.join(HERE, 'bench_msaa.json')))
msaa["version"] = 2
msaa["image"]["samples"] = 16
write('bench_msaa16', msaa)

spheres = []
for r in range(6):
    for c in range(10):
        spheres.append({"builtin": {"type": "uv_sphere", "radius": 0.56, "rings": 32, "segments": 64},
                        "transform": {"translate": [round((c - 4.5) * 1.25, 3), round((2.5 - r) * 1.25, 3), 0]},
                        "material": {"shading": "pbr", "color": [round(0.55 + 0.04 * c, 3), round(0.5 + 0.05 * r, 3), 0.45, 1],
                                     "metallic": round(r / 5, 3), "roughness": round(0.05 + 0.95 * c / 9, 3)}})
write('bench_ibl', {
    "version": 2,
    "image": {"width": 1920, "height": 1080, "background": [0.05, 0.06, 0.08, 1], "color_space": "srgb", "tone_mapping": "aces"},
    "camera": {"eye": [0, 0, 9.8], "target": [0, 0, 0], "fov_y": 45},
    "environment": {"file": "../../tests/scenes/textures/sky_128.hdr"},
    "objects": spheres})
