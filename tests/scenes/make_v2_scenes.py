#!/usr/bin/env python3
"""Writes the conformance scenes of scene format version 2 (tests/scenes/v2_*.json and the
texture they share): together they draw every per-fragment operation version 2 adds
(stencil functions and operations on front and back faces, depth functions, depth test and
write switches, polygon offset, every blend equation and a spread of factors, color masks,
alpha cutoff, alpha-to-coverage, scissor, supersampling with and without MSAA, affine
interpolation, file draw order). ctest renders each with softraster and with Mesa llvmpipe
(tests/reference) and compares. Run it again after editing; the files it writes are committed."""
import json, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
LIGHTS = {"ambient": [0.15, 0.15, 0.17],
          "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.85, 0.82, 0.78]}]}
FRONT_CAM = {"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y": 50}
SKEW_CAM = {"eye": [2.2, 1.8, 3.6], "target": [0, 0, 0], "fov_y": 45}


def write(rel, data):
    path = os.path.join(HERE, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'wb') as f:
        f.write(data.encode() if isinstance(data, str) else data)


def scene(name, objects, camera=FRONT_CAM, width=160, height=120, lights=LIGHTS, background=(0.1, 0.12, 0.16, 1),
          draw_order=None, **image):
    img = {"width": width, "height": height, "background": list(background), **image}
    s = {"version": 2, "image": img, "camera": camera, "lights": lights, "objects": objects}
    if draw_order:
        s["draw_order"] = draw_order
    write('v2_' + name + '.json', json.dumps(s, indent=1))


def png(w, h, pixels):
    raw = b''.join(b'\x00' + bytes(pixels[y * w * 4:(y + 1) * w * 4]) for y in range(h))
    chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 6, 0, 0, 0)) +
            chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))


# A 64 x 64 texture: alpha rises from 0 at the left to 1 at the right, colors in bands.
px = []
for y in range(64):
    for x in range(64):
        px += [255 if (y // 16) % 2 == 0 else 60, 120 + 2 * y, 255 - 3 * x, min(255, x * 4)]
write('textures/alpha_ramp.png', png(64, 64, px))


def quad(translate, size=2.0, color=(1, 1, 1, 1), shading="unlit", rotate=(90, 0, 0), **extra):
    """A square facing the camera (the builtin plane turned up), with a material."""
    o = {"builtin": {"type": "plane", "size": size},
         "transform": {"translate": list(translate), "rotate": list(rotate)},
         "material": {"shading": shading, "color": list(color)}, "cull": "none"}
    for k, v in extra.items():
        if k in ("blend", "color_mask", "alpha_cutoff", "alpha_to_coverage", "interpolation", "texture", "filter"):
            o["material"][k] = v
        else:
            o[k] = v
    return o


def stencil(func="always", ref=0, op="keep", fail="keep", depth_fail="keep", read_mask=255, write_mask=255):
    return {"func": func, "ref": ref, "pass": op, "fail": fail, "depth_fail": depth_fail,
            "read_mask": read_mask, "write_mask": write_mask}


# ---- stencil: a mirror (portal) that shows a reflection only inside its frame
torus = {"builtin": {"type": "torus", "major": 0.6, "minor": 0.22}, "material": {"shading": "blinn_phong",
         "color": [0.9, 0.5, 0.2, 1], "specular": [0.5, 0.5, 0.5], "shininess": 24}}
mirror_rot = [-90, 0, 0]
scene("stencil_mirror", [
    # 1. the mirror's area marks the stencil (no color, no depth)
    {"builtin": {"type": "plane", "size": 2.4}, "transform": {"translate": [0, -0.9, 0], "rotate": [0, 0, 0]},
     "material": {"shading": "unlit", "color_mask": [False, False, False, False]}, "cull": "none",
     "depth": {"write": False}, "stencil": stencil("always", 1, "replace")},
    # 2. the reflection (mirrored in y: windings flip) only where the stencil is 1
    dict(torus, transform={"translate": [0, -1.8, 0], "rotate": [30, 20, 0], "scale": [1, -1, 1]}, front_face="cw",
         stencil=stencil("equal", 1)),
    # 3. the mirror's surface, blended over the reflection
    {"builtin": {"type": "plane", "size": 2.4}, "transform": {"translate": [0, -0.9, 0]},
     "material": {"shading": "unlit", "color": [0.6, 0.7, 0.9, 0.35], "blend": "alpha"}, "cull": "none"},
    # 4. the object itself
    dict(torus, transform={"translate": [0, 0, 0], "rotate": [-30, 20, 0]}),
], camera={"eye": [0, 1.5, 4.2], "target": [0, -0.4, 0], "fov_y": 50}, draw_order="file")

# ---- stencil: an outline (the object marks the stencil, a bigger copy draws where it did not)
scene("stencil_outline", [
    dict(torus, transform={"rotate": [50, 10, 0]}, stencil=stencil("always", 7, "replace")),
    {"builtin": {"type": "torus", "major": 0.6, "minor": 0.22}, "transform": {"rotate": [50, 10, 0], "scale": 1.12},
     "material": {"shading": "unlit", "color": [1, 0.95, 0.3, 1]}, "depth": {"test": False},
     "stencil": stencil("not_equal", 7)},
], camera=SKEW_CAM, draw_order="file")

# ---- stencil operations on front and back faces: a torus with culling off counts layers
# (front faces increment, back faces decrement with wrap), then flat quads show the counts.
layers = [
    {"builtin": {"type": "torus", "major": 0.7, "minor": 0.3}, "transform": {"rotate": [60, 0, 20]},
     "material": {"shading": "lambert", "color_mask": [False, False, False, False]}, "cull": "none",
     "depth": {"test": False, "write": False},
     "stencil": {"front": stencil("always", 0, "incr"), "back": stencil("always", 0, "decr_wrap")}},
]
for i, (ref, color) in enumerate([(1, [1, 0.3, 0.3, 1]), (2, [0.3, 1, 0.3, 1]), (0, [0.2, 0.2, 0.8, 1]),
                                  (255, [1, 1, 0.2, 1]), (254, [1, 0.3, 1, 1])]):
    layers.append(quad([0, 0, 0], size=4, color=color, depth={"test": False}, stencil=stencil("equal", ref)))
scene("stencil_front_back", layers, camera=SKEW_CAM, draw_order="file")

# ---- every stencil operation and the masks: five columns (scissored), each applies one set of
# operations to a cleared value, then quads colored by the resulting value.
ops = [("zero", 5, 255), ("replace", 9, 255), ("incr", 0, 255), ("decr", 0, 255), ("incr_wrap", 0, 255),
       ("decr_wrap", 0, 255), ("invert", 0, 0x0f), ("replace", 0xf0, 0x3c)]
objs = []
for i, (op, ref, wmask) in enumerate(ops):
    x = i * 20
    # two passes of the op (so incr on 254 saturates at 255, incr_wrap wraps to 0 then 1)
    for _ in range(2):
        objs.append(quad([0, 0, 0], size=4, color=[0, 0, 0, 1], color_mask=[False] * 4, depth={"test": False},
                         stencil=stencil("always", ref, op, write_mask=wmask), scissor=[x, 0, 20, 120]))
for value, color in [(255, [1, 1, 1, 1]), (0, [0.1, 0.1, 0.1, 1]), (254, [0.5, 0.5, 0.5, 1]), (253, [0.4, 0.2, 0.2, 1]),
                     (9, [0.2, 0.6, 1, 1]), (1, [0.9, 0.1, 0.1, 1]), (0xf1, [0.1, 0.9, 0.1, 1]),
                     (0xf2, [0.9, 0.5, 0.1, 1]), (0xfe, [0.5, 0.1, 0.9, 1]), (0xf0, [0.2, 0.9, 0.9, 1]),
                     (0xb0, [0.9, 0.9, 0.2, 1])]:
    objs.append(quad([0, 0, 0], size=4, color=color, depth={"test": False}, stencil=stencil("equal", value)))
# the read mask: a band where only the low nibble is compared
objs.append(quad([0, -0.8, 0], size=0.5, color=[1, 0, 0.5, 1], depth={"test": False},
                 stencil=stencil("equal", 0x0e, read_mask=0x0f)))
scene("stencil_ops", objs, clear_stencil=254, draw_order="file")

# ---- the eight stencil functions: a pattern of stencil values, then one column per function
objs = [quad([-0.6, 0.2, 0], size=1.6, color_mask=[False] * 4, depth={"write": False}, stencil=stencil("always", 3, "replace")),
        quad([0.5, -0.3, 0], size=1.4, color_mask=[False] * 4, depth={"write": False}, stencil=stencil("always", 5, "replace"))]
for i, func in enumerate(["never", "less", "equal", "less_equal", "greater", "not_equal", "greater_equal", "always"]):
    objs.append(quad([0, 0, 0], size=4, color=[0.1 + 0.11 * i, 0.9 - 0.1 * i, 0.5, 1], depth={"test": False},
                     stencil=stencil(func, 3), scissor=[i * 20, 0, 20, 120]))
scene("stencil_funcs", objs, draw_order="file")

# ---- depth: the eight functions against a tilted plane, and the test and write switches
objs = [{"builtin": {"type": "plane", "size": 3}, "transform": {"rotate": [70, 0, 25]},
         "material": {"shading": "lambert", "color": [0.5, 0.5, 0.55, 1]}, "cull": "none"}]
for i, func in enumerate(["never", "less", "equal", "less_equal", "greater", "not_equal", "greater_equal", "always"]):
    objs.append(quad([0, 0, 0], size=4, color=[0.9, 0.2 + 0.1 * i, 0.1 * i, 1], depth={"func": func, "write": False},
                     scissor=[i * 20, 0, 20, 120]))
scene("depth_funcs", objs, draw_order="file")
scene("depth_switches", [
    dict(torus, transform={"rotate": [40, 0, 0]}),
    # drawn over everything (test off), writes nothing
    quad([0.3, 0.2, -1.0], size=0.8, color=[0.2, 0.8, 0.3, 1], depth={"test": False}),
    # tested but not written: the next quad, farther, still shows through where this one is
    quad([-0.3, -0.2, 0.6], size=0.9, color=[0.8, 0.2, 0.7, 1], depth={"write": False}),
    quad([-0.5, -0.4, 0.3], size=0.9, color=[0.2, 0.4, 0.9, 1]),
    # blended but writing depth (explicit): hides the cube after it
    quad([0.5, -0.5, 0.8], size=0.7, color=[1, 1, 0.2, 0.5], blend="alpha", depth={"write": True}),
    {"builtin": {"type": "cube", "size": 0.5}, "transform": {"translate": [0.6, -0.6, 0.2]},
     "material": {"color": [0.3, 0.9, 0.9, 1]}},
], camera={"eye": [0, 0.3, 4], "target": [0, 0, 0], "fov_y": 50}, draw_order="file")

# ---- polygon offset: decals coplanar with a tilted plane, pulled forward (and one pushed back)
ground = {"builtin": {"type": "plane", "size": 3, "divisions": 4}, "transform": {"rotate": [35, 20, 0]},
          "material": {"shading": "lambert", "color": [0.6, 0.6, 0.6, 1]}, "cull": "none"}
scene("polygon_offset", [
    ground,
    dict(ground, builtin={"type": "plane", "size": 1.0}, material={"shading": "unlit", "color": [0.9, 0.2, 0.2, 1]},
         depth={"offset": [-1, -4], "func": "less"}),
    dict(ground, builtin={"type": "plane", "size": 0.6}, transform={"translate": [0.6, 0.33, -0.2], "rotate": [35, 20, 0]},
         material={"shading": "unlit", "color": [0.2, 0.9, 0.2, 1]}, depth={"offset": [-2, -2]}),
    # pushed behind the plane: hidden
    dict(ground, builtin={"type": "plane", "size": 0.8}, transform={"translate": [-0.7, -0.3, 0.3], "rotate": [35, 20, 0]},
         material={"shading": "unlit", "color": [0.2, 0.2, 0.9, 1]}, depth={"offset": [2, 8]}),
], camera=SKEW_CAM, draw_order="file")

# ---- blending: the five equations, side by side over colored stripes
stripes = [quad([-1.2 + 0.8 * i, 0, -0.5], size=0.8, color=c) for i, c in
           enumerate([[0.9, 0.2, 0.2, 1], [0.2, 0.8, 0.3, 1], [0.2, 0.3, 0.9, 0.5], [0.9, 0.9, 0.9, 0.2]])]
objs = list(stripes)
for i, eq in enumerate(["add", "subtract", "reverse_subtract", "min", "max"]):
    objs.append(quad([-1.5 + 0.75 * i, 0, 0], size=0.7, color=[0.6, 0.45, 0.3, 0.7], rotate=[90, 0, 0],
                     blend={"equation": eq, "src": "src_alpha", "dst": "one"}, depth={"test": False}))
    objs.append(quad([-1.5 + 0.75 * i, -0.9, 0], size=0.5, color=[0.3, 0.6, 0.8, 0.4],
                     blend={"equation": eq, "src": "one", "dst": "one_minus_src_alpha", "equation_alpha": "add"},
                     depth={"test": False}))
scene("blend_equations", objs, draw_order="file")

# ---- blend factors: a grid of (src, dst) pairs, separate alpha and the constant color
factors = [("one", "zero"), ("src_color", "one_minus_src_color"), ("dst_color", "zero"), ("one_minus_dst_color", "one"),
           ("src_alpha", "one_minus_src_alpha"), ("dst_alpha", "one_minus_dst_alpha"), ("constant_color", "one_minus_constant_color"),
           ("constant_alpha", "one_minus_constant_alpha"), ("src_alpha_saturate", "one"), ("one_minus_dst_alpha", "src_alpha"),
           ("zero", "src_color"), ("one_minus_constant_color", "constant_alpha")]
objs = [quad([0, 0, -0.5], size=4, color=[0.3, 0.5, 0.7, 0.6]),
        quad([0, 0.6, -0.4], size=1.2, color=[0.9, 0.8, 0.1, 0.9])]
for i, (src, dst) in enumerate(factors):
    x, y = -1.35 + 0.9 * (i % 4), 0.9 - 0.9 * (i // 4)
    objs.append(quad([x, y, 0], size=0.7, color=[0.8, 0.3, 0.5, 0.65], depth={"test": False},
                     blend={"src": src, "dst": dst, "src_alpha": "one", "dst_alpha": "one_minus_src_alpha",
                            "constant": [0.25, 0.5, 0.75, 0.4]}))
scene("blend_factors", objs, draw_order="file", background=(0.5, 0.4, 0.3, 0.5))

# ---- color masks: quads writing only some channels
objs = [quad([0, 0, -0.5], size=4, color=[0.5, 0.5, 0.5, 1])]
for i, mask in enumerate([[True, False, False, True], [False, True, False, False], [False, False, True, True],
                          [True, True, False, False], [False, False, False, True]]):
    objs.append(quad([-1.4 + 0.7 * i, 0, 0], size=0.6, color=[1, 0.9, 0.1, 0.3], color_mask=mask))
scene("color_mask", objs)

# ---- alpha cutoff (glTF MASK) and alpha-to-coverage, through a texture whose alpha is a ramp
tex = {"texture": "textures/alpha_ramp.png", "filter": "bilinear"}
scene("alpha_cutoff", [
    dict(torus, transform={"translate": [0, 0, -0.8], "rotate": [60, 0, 0]}),
    quad([-0.8, 0, 0], size=1.4, alpha_cutoff=0.5, **tex),
    quad([0.8, 0, 0], size=1.4, alpha_cutoff=0.25, rotate=[90, 30, 0], **tex),
], draw_order="file")
scene("alpha_to_coverage", [
    dict(torus, transform={"translate": [0, 0, -0.8], "rotate": [60, 0, 0]}),
    quad([-0.8, 0, 0], size=1.4, alpha_to_coverage=True, **tex),
    quad([0.8, 0, 0.2], size=1.4, alpha_to_coverage=True, rotate=[90, 30, 0], shading="unlit", **tex),
], samples=4, draw_order="file")

# ---- scissor rectangles per object
scene("scissor", [
    dict(torus, transform={"rotate": [50, 0, 0]}, scissor=[10, 10, 70, 60]),
    dict(torus, transform={"rotate": [50, 0, 0], "translate": [0.3, 0, 0]}, scissor=[75, 40, 80, 75],
         material={"shading": "normals"}),
    quad([0, 0, -1], size=5, color=[0.3, 0.3, 0.3, 1], scissor=[0, 100, 160, 20]),
], draw_order="file")

# ---- supersampling, alone and with 4x MSAA
spiky = [dict(torus, transform={"rotate": [70, 10, 0]}),
         {"builtin": {"type": "cube", "size": 0.6}, "transform": {"translate": [0.9, 0.5, 0.3], "rotate": [20, 35, 10]},
          "material": {"color": [0.4, 0.8, 0.5, 1]}},
         quad([-0.9, 0.6, 0.3], size=0.6, color=[0.9, 0.9, 0.2, 0.5], blend="alpha")]
scene("supersample2", spiky, supersample=2)
scene("supersample3_msaa4", spiky, supersample=3, samples=4)
scene("msaa4_stencil_blend", [
    dict(torus, transform={"rotate": [70, 10, 0]}, stencil=stencil("always", 1, "replace")),
    quad([0, 0, 0.9], size=1.6, color=[0.2, 0.6, 1, 0.6], depth={"test": False},
         blend={"equation": "add", "src": "src_alpha", "dst": "one_minus_src_alpha", "src_alpha": "zero", "dst_alpha": "one"},
         stencil=stencil("equal", 1)),
], samples=4, draw_order="file")

# ---- affine interpolation: a checkerboard floor in perspective
# (wholly in front of the near plane: see docs/scene-format.md on affine and clipping)
floor = {"builtin": {"type": "plane", "size": 6, "divisions": 1}, "transform": {"translate": [0, -0.5, -4.6]},
         "material": {"shading": "unlit", "texture": "../conformance/textures/checker.png", "filter": "nearest"},
         "cull": "none"}
scene("affine_floor", [dict(floor, material=dict(floor["material"], interpolation="affine"))],
      camera={"eye": [0, 0.6, 0.5], "target": [0, -0.5, -3], "fov_y": 60})

# ---- draw order "file": blended objects in the order written (front one first)
scene("draw_order_file", [
    quad([0, 0, 0.5], size=1.2, color=[0.9, 0.2, 0.2, 0.5], blend="alpha"),
    quad([0.4, 0.3, -0.5], size=1.2, color=[0.2, 0.4, 0.9, 0.5], blend="alpha"),
], draw_order="file")

# ---- lines and points (OBJ `l` and `p` elements, triangle edges, wireframes)
import math
star = ["# A star of segments at generic angles and lengths, polylines, vertex colors."]
lines = []
n = 1
for i in range(28):
    a = 2 * math.pi * i / 28 + 0.037
    r0, r1 = 0.08 + 0.013 * (i % 5), 0.55 + 0.31 * ((i * 7) % 11) / 11
    c0 = (0.5 + 0.5 * math.cos(a), 0.5 + 0.5 * math.sin(a), 0.3)
    star.append("v %.5f %.5f 0 %.3f %.3f %.3f" % (r0 * math.cos(a) - 0.55, r0 * math.sin(a) + 0.05, *c0))
    star.append("v %.5f %.5f 0 %.3f %.3f %.3f" % (r1 * math.cos(a) - 0.55, r1 * math.sin(a) + 0.05, 1, 1 - c0[0], c0[1]))
    lines.append("l %d %d" % (n, n + 1))
    n += 2
# a polyline (a spiral) and an axis-aligned box
first = n
for k in range(40):
    a, r = 0.45 * k, 0.1 + 0.018 * k
    star.append("v %.5f %.5f 0 %.3f 0.9 %.3f" % (0.75 + r * math.cos(a), 0.1 + r * math.sin(a), k / 40, 1 - k / 40))
    n += 1
lines.append("l " + " ".join(str(k) for k in range(first, n)))
for x, y in [(-1.2, -0.8), (1.25, -0.8), (1.25, 0.83), (-1.2, 0.83)]:
    star.append("v %.3f %.3f 0 1 1 1" % (x, y))
lines.append("l %d %d %d %d %d" % (n, n + 1, n + 2, n + 3, n))
write('meshes/lines_star.obj', "\n".join(star + lines) + "\n")
# the same without vertex colors
write('meshes/lines_star_plain.obj', "\n".join([" ".join(l.split()[:4]) if l.startswith("v ") else l for l in star + lines]) + "\n")

pts = ["# Points on a jittered grid, vertex colors."]
for j in range(5):
    for i in range(8):
        pts.append("v %.5f %.5f %.3f %.3f %.3f 0.4" % (-1.1 + 0.31 * i + 0.013 * j, -0.7 + 0.33 * j + 0.007 * i, 0.1 * ((i + j) % 3), i / 7, j / 4))
pts.append("p " + " ".join(str(k + 1) for k in range(40)))
write('meshes/points_grid.obj', "\n".join(pts) + "\n")

ORTHO = {"projection": "orthographic", "eye": [0, 0, 3], "target": [0, 0, 0], "height": 2}
unlit_white = {"shading": "unlit", "color": [1, 1, 1, 1]}
scene("lines_star", [{"mesh": "meshes/lines_star.obj", "primitive": "lines", "material": unlit_white}], camera=ORTHO)
scene("lines_wide", [
    {"builtin": {"type": "uv_sphere", "radius": 0.5}, "transform": {"translate": [0.2, 0, -0.2]}, "material": {"color": [0.3, 0.5, 0.8, 1]}},
    # (inside the picture: at its border llvmpipe's wide lines light fewer pixels than the rule)
    {"mesh": "meshes/lines_star.obj", "primitive": "lines", "line_width": 3, "transform": {"translate": [-0.1, 0, 0], "scale": 0.8},
     "material": unlit_white},
    {"mesh": "meshes/lines_star.obj", "primitive": "lines", "line_width": 2,
     "transform": {"translate": [0.25, -0.2, 0.1], "rotate": [0, 0, 17], "scale": 0.75},
     "material": {"shading": "unlit", "color": [1, 0.4, 0.2, 1]}},
], camera=ORTHO)
scene("lines_msaa4", [
    {"mesh": "meshes/lines_star_plain.obj", "primitive": "lines", "material": unlit_white},
    {"mesh": "meshes/lines_star_plain.obj", "primitive": "lines", "line_width": 2.5,
     "transform": {"translate": [0.3, -0.2, 0.1], "rotate": [0, 0, 23], "scale": 0.75},
     "material": {"shading": "unlit", "color": [1, 0.6, 0.2, 0.7], "blend": "alpha"}},
], camera=ORTHO, samples=4)
points = [{"mesh": "meshes/points_grid.obj", "primitive": "points", "point_size": size, "transform": {"translate": [dx, dy, 0]},
           "material": unlit_white} for size, dx, dy in [(1, 0, 0), (2, 0.06, 0.05), (3.5, 0.12, -0.06), (6, 0.03, 0.13)]]
scene("points_sizes", points, camera=ORTHO)
scene("points_msaa4", points, camera=ORTHO, samples=4)
# triangle edges as lines, in perspective, through the near plane; a sphere's vertices as points
scene("lines_perspective", [
    {"builtin": {"type": "plane", "size": 6, "divisions": 7}, "transform": {"translate": [0.13, -0.5, -1.5], "rotate": [0, 11, 0]},
     "primitive": "lines", "material": {"shading": "unlit", "texture": "../conformance/textures/checker.png"}},
    {"builtin": {"type": "uv_sphere", "radius": 0.6, "rings": 12, "segments": 20}, "transform": {"translate": [0.3, 0.1, -1.2]},
     "primitive": "points", "point_size": 2, "material": {"shading": "unlit", "color": [1, 0.9, 0.3, 1]}},
], camera={"eye": [0, 0.3, 0.6], "target": [0, -0.2, -2], "fov_y": 60})
scene("wireframe", [
    {"builtin": {"type": "torus", "major": 0.75, "minor": 0.3, "rings": 14, "segments": 8}, "transform": {"rotate": [50, 10, 0]},
     "material": torus["material"], "wireframe": {"color": [0.05, 0.05, 0.1]}},
    {"builtin": {"type": "cube", "size": 0.7}, "transform": {"translate": [1.0, 0.5, 0.2], "rotate": [20, 35, 10]},
     "material": {"color": [0.4, 0.8, 0.5, 1]}, "wireframe": {"color": [1, 1, 1], "width": 2}},
    {"builtin": {"type": "uv_sphere", "radius": 0.35, "rings": 8, "segments": 12}, "transform": {"translate": [-1.0, -0.5, 0.3]},
     "material": {"shading": "flat", "color": [0.8, 0.4, 0.4, 1]}, "wireframe": {"color": [1, 0.9, 0.2]}},
], camera=SKEW_CAM)
