#!/usr/bin/env python3
"""Writes the bench scenes that read large textures (1080p):
  bench_textured_model            a textured model (a finely tessellated torus knot of
                                  spheres, ~200k triangles) with a 1024x1024 texture, Blinn-Phong,
                                  bilinear as scene format version 1 samples
  bench_textured_model_trilinear  the same with trilinear filtering (version 2)
  bench_trilinear                 a corridor of four textured walls to the horizon, the texture
                                  repeated 24 times along it: minified at a grazing angle
  bench_trilinear_srgb            the same corridor in sRGB (the texture decoded, the picture
                                  encoded), as a glTF base color texture is read
  bench_pbr                       the textured model with glTF metallic-roughness materials (the
                                  texture also as the metallic-roughness map, a normal map of
                                  bevelled tiles), a directional, a point and a spot light
                                  with a shadow map, in sRGB with the ACES curve
The texture (textures/tiles_1024.png) and the corridor's walls (corridor_*.obj) are written
here too. Run it again after editing; the files it writes are committed."""
import json, math, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
LIGHTS = {"ambient": [0.15, 0.15, 0.17], "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.9, 0.85, 0.8]},
                                                          {"direction": [0.6, -0.2, -0.5], "color": [0.3, 0.3, 0.4]}]}


def write(name, scene):
    with open(os.path.join(HERE, name + '.json'), 'w') as f:
        json.dump(scene, f, indent=1)


def png(path, w, h, rows):
    """RGB PNG; each row filtered with 'Sub' (the difference to the left), which keeps smooth
    gradients small."""
    raw = bytearray()
    for row in rows:
        raw.append(1)
        prev = (0, 0, 0)
        for px in row:
            raw.extend(((px[0] - prev[0]) & 255, (px[1] - prev[1]) & 255, (px[2] - prev[2]) & 255))
            prev = px
    chunk = lambda tag, data: struct.pack('>I', len(data)) + tag + data + struct.pack('>I', zlib.crc32(tag + data) & 0xffffffff)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(bytes(raw), 9)) + chunk(b'IEND', b''))


def tiles(n):
    """Stone tiles: 8x8 tiles of varying hue with dark grout, a soft sheen across each tile and
    fine stripes, so that every mip level differs from the next."""
    for y in range(n):
        row = []
        for x in range(n):
            tx, ty = x * 8 // n, y * 8 // n
            fx, fy = (x * 8 % n) / n, (y * 8 % n) / n
            grout = min(fx, fy, 1 - fx, 1 - fy) < 0.03
            hue = (tx * 5 + ty * 3) % 7 / 7.0
            sheen = 0.75 + 0.25 * round(6 * math.sin(math.pi * fx) * math.sin(math.pi * fy)) / 6  # in steps: small PNG
            stripe = 0.9 if (x + 2 * y) // 6 % 2 else 1.0  # diagonal bands 6 texels wide
            if grout:
                row.append((40, 38, 36))
            else:
                r = 0.55 + 0.4 * math.sin(2 * math.pi * hue)
                g = 0.55 + 0.4 * math.sin(2 * math.pi * (hue + 0.33))
                b = 0.55 + 0.4 * math.sin(2 * math.pi * (hue + 0.67))
                row.append(tuple(int(255 * max(0.0, min(1.0, c * sheen * stripe))) for c in (r, g, b)))
        yield row


def tile_normals(n):
    """The tiles' normal map (tangent space, +y up the picture): each tile's edges bevelled,
    the normal leaning out across the nearest edge, flat on the tile and in the grout."""
    flat = (128, 128, 255)
    lean = [tuple(int(round(255 * (c * 0.5 + 0.5))) for c in (d[0] * 0.6, d[1] * 0.6, 0.8)) for d in ((-1, 0), (1, 0), (0, 1), (0, -1))]
    for y in range(n):
        row = []
        for x in range(n):
            fx, fy = (x * 8 % n) / n, (y * 8 % n) / n
            edges = (fx, 1 - fx, fy, 1 - fy)  # left, right, top (row 0 at the top: +y), bottom
            k = min(range(4), key=lambda i: edges[i])
            row.append(lean[k] if 0.03 <= edges[k] < 0.1 else flat)
        yield row


def quad_obj(name, corners, uv_max):
    """One quad (two triangles, counter-clockwise as seen from the side that faces the
    corridor's inside) with uv from (0, 0) to uv_max, so the texture repeats."""
    with open(os.path.join(HERE, name), 'w') as f:
        f.write('# written by make_bench_textured.py\n')
        for c in corners:
            f.write('v %g %g %g\n' % c)
        for uv in ((0, 0), (uv_max[0], 0), (uv_max[0], uv_max[1]), (0, uv_max[1])):
            f.write('vt %g %g\n' % uv)
        f.write('f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n')


os.makedirs(os.path.join(HERE, 'textures'), exist_ok=True)
png(os.path.join(HERE, 'textures', 'tiles_1024.png'), 1024, 1024, tiles(1024))
png(os.path.join(HERE, 'textures', 'tiles_normal_1024.png'), 1024, 1024, tile_normals(1024))

# A model of real size: three tori and a sphere, ~200k triangles, the texture wrapped once
# around each; together they cover about a third of the picture.
model = []
for i, (x, y, rot) in enumerate(((-0.9, 0.35, 20), (0.9, 0.35, -25), (0, -0.55, 70))):
    model.append({"builtin": {"type": "torus", "major": 0.62, "minor": 0.26, "rings": 256, "segments": 128},
                  "transform": {"translate": [x, y, 0], "rotate": [rot, 30 * i, 0]}})
model.append({"builtin": {"type": "uv_sphere", "radius": 0.45, "rings": 128, "segments": 256}, "transform": {"translate": [0, 0.45, -0.3]}})
material = {"shading": "blinn_phong", "color": [1, 1, 1, 1], "specular": [0.3, 0.3, 0.3], "shininess": 32,
            "texture": "textures/tiles_1024.png"}
base = {"image": {"width": 1920, "height": 1080, "background": [0.1, 0.1, 0.12, 1]},
        "camera": {"eye": [0, 0.4, 5.2], "target": [0, 0, 0], "fov_y": 45}, "lights": LIGHTS}
write('bench_textured_model', dict(base, version=1, objects=[dict(o, material=material) for o in model]))
trilinear = dict(material, filter="trilinear")
write('bench_textured_model_trilinear', dict(base, version=2, objects=[dict(o, material=trilinear) for o in model]))

pbr = {"shading": "pbr", "color": [1, 1, 1, 1], "texture": "textures/tiles_1024.png", "metallic": 0.8, "roughness": 0.9,
       "metallic_roughness_texture": "textures/tiles_1024.png", "normal_texture": "textures/tiles_normal_1024.png", "filter": "trilinear"}
# The spot light casts shadows (the default map: 1024², 3 x 3 PCF); sRGB color and the ACES curve.
write('bench_pbr', dict(base, version=2, objects=[dict(o, material=pbr) for o in model],
                        image=dict(base["image"], color_space="srgb", tone_mapping="aces"),
                        lights={"ambient": [0.1, 0.1, 0.12], "directional": LIGHTS["directional"][:1],
                                "point": [{"position": [1.8, 1.2, 2.0], "color": [0.5, 0.7, 1.0], "intensity": 4, "range": 8}],
                                "spot": [{"position": [-1.5, 2.5, 2.5], "direction": [0.5, -0.8, -0.9], "color": [1, 0.9, 0.7],
                                          "intensity": 10, "inner_angle": 15, "outer_angle": 30,
                                          "shadow": {}}]}))

# The corridor: floor, ceiling and two walls, 2 wide, 2 high and 60 long, from z = 2 to -58.
L, W = 60.0, 1.0
quad_obj('corridor_floor.obj', ((-W, -1, 2), (W, -1, 2), (W, -1, 2 - L), (-W, -1, 2 - L)), (2, 24 * 2))
quad_obj('corridor_ceiling.obj', ((-W, 1, 2 - L), (W, 1, 2 - L), (W, 1, 2), (-W, 1, 2)), (2, 24 * 2))
quad_obj('corridor_left.obj', ((-W, -1, 2), (-W, -1, 2 - L), (-W, 1, 2 - L), (-W, 1, 2)), (24 * 2, 2))
quad_obj('corridor_right.obj', ((W, -1, 2 - L), (W, -1, 2), (W, 1, 2), (W, 1, 2 - L)), (24 * 2, 2))
walls = [{"mesh": "corridor_%s.obj" % side, "material": {"shading": "unlit", "texture": "textures/tiles_1024.png", "filter": "trilinear"}}
         for side in ("floor", "ceiling", "left", "right")]
corridor_camera = {"eye": [0.2, 0.1, 1.5], "target": [0, 0, -20], "fov_y": 70, "near": 0.1, "far": 100}
write('bench_trilinear', {"version": 2, "image": {"width": 1920, "height": 1080, "background": [0, 0, 0, 1]},
                          "camera": corridor_camera, "objects": walls})
write('bench_trilinear_srgb', {"version": 2, "image": {"width": 1920, "height": 1080, "background": [0, 0, 0, 1], "color_space": "srgb"},
                               "camera": corridor_camera, "objects": walls})
