#!/usr/bin/env python3
"""Writes the conformance scenes of normal mapping (tests/scenes/normal_map_*.json and their
textures): a bumpy floor seen at a grazing angle, and a sphere, a torus and a mirrored cube
with ridges, under pbr shading. The tangents are softraster's own (generated from the
meshes); ctest renders each with softraster and with Mesa llvmpipe (tests/reference), which
reads the same tangents, and compares. Run it again after editing; the files it writes are
committed."""
import json, math

from make_scenes import texture, write


def encode(n):
    """A unit normal as the map's 8-bit texel: 255 (n + 1) / 2, rounded."""
    return [int(round(255 * (c * 0.5 + 0.5))) for c in n] + [255]


def bump(x, y, cell=32):
    """A smooth bump in each cell, height cos²(π r / 2) over r < 1: its normal
    normalize(−∂h/∂x, −∂h/∂y, 1), flat (0, 0, 1) elsewhere (the slope is continuous)."""
    dx, dy = (x % cell + 0.5 - cell / 2) / (cell * 0.45), -(y % cell + 0.5 - cell / 2) / (cell * 0.45)
    r = math.hypot(dx, dy)
    if r >= 1 or r == 0:
        return encode((0, 0, 1))
    slope = -0.6 * math.pi / 2 * math.sin(math.pi * r)  # dh/dr, h = 0.6 cos²(π r / 2)
    gx, gy = slope * dx / r, slope * dy / r
    n = math.sqrt(gx * gx + gy * gy + 1)
    return encode((-gx / n, -gy / n, 1 / n))


def ridge(x, y):
    """Ridges along v: the normal tilts back and forth in x."""
    a = 0.8 * math.sin(2 * math.pi * (x + 0.5) / 8)
    return encode((a / math.sqrt(1 + a * a), 0, 1 / math.sqrt(1 + a * a)))


def scene(name, lights, objects, camera, width=192, height=128, **image):
    img = {"width": width, "height": height, "background": [0.04, 0.04, 0.06, 1], **image}
    s = {"version": 2, "image": img, "camera": camera, "lights": lights, "objects": objects}
    write('normal_map_' + name + '.json', json.dumps(s, indent=1))


def main():
    texture('normal_bumps128.png', 128, 128, bump)
    texture('normal_ridges128.png', 128, 128, ridge)
    base = {"shading": "pbr", "color": [0.85, 0.8, 0.75, 1], "metallic": 0, "roughness": 0.5, "filter": "trilinear"}
    lights = {"ambient": [0.05, 0.05, 0.06], "directional": [{"direction": [-0.7, -0.35, -0.4], "color": [0.9, 0.85, 0.8]}],
              "point": [{"position": [1.2, 0.6, 1.0], "color": [0.5, 0.7, 1.0], "intensity": 2, "range": 6}]}
    # A floor to the horizon: the bumps shrink and the mipmaps blend them out.
    scene('grazing', lights,
          [{"builtin": {"type": "plane", "size": 12, "divisions": 6},
            "material": {**base, "normal_texture": "textures/normal_bumps128.png", "wrap": "repeat"}}],
          {"eye": [0, 0.45, 3.5], "target": [0, 0, -2], "fov_y": 50})
    # Mirrored texture coordinates, as on symmetric characters: a panel whose right half reads
    # the map backwards (u from 1 to 0), so its tangents point the other way and w is -1.
    obj = ['# two quads in z = 0 facing +z; the right one with u mirrored']
    verts = [(-1, -1, 0), (0, -1, 0), (0, 1, 0), (-1, 1, 0), (0, -1, 0), (1, -1, 0), (1, 1, 0), (0, 1, 0)]
    uvs = [(0, 0), (1, 0), (1, 1), (0, 1), (1, 0), (0, 0), (0, 1), (1, 1)]
    obj += ['v %g %g %g' % v for v in verts] + ['vt %g %g' % t for t in uvs] + ['vn 0 0 1']
    obj += ['f 1/1/1 2/2/1 3/3/1 4/4/1', 'f 5/5/1 6/6/1 7/7/1 8/8/1']
    write('meshes/mirrored_panel.obj', '\n'.join(obj) + '\n')
    scene('mirrored', lights,
          [{"mesh": "meshes/mirrored_panel.obj", "transform": {"rotate": [-25, 20, 0], "scale": 1.3},
            "material": {**base, "color": [0.8, 0.75, 0.9, 1], "normal_texture": "textures/normal_bumps128.png"}}],
          {"eye": [0, 0, 3.2], "target": [0, 0, 0], "fov_y": 50})
    # Curved surfaces, a scaled map and a mirrored object (its tangent frame flips with it).
    scene('shapes', lights,
          [{"builtin": {"type": "uv_sphere", "radius": 0.7, "rings": 24, "segments": 48}, "transform": {"translate": [-1.1, 0, 0]},
            "material": {**base, "normal_texture": "textures/normal_ridges128.png"}},
           {"builtin": {"type": "torus", "major": 0.45, "minor": 0.2, "rings": 48, "segments": 24},
            "transform": {"translate": [0.35, 0.05, 0], "rotate": [70, 0, 0]},
            "material": {**base, "color": [0.9, 0.6, 0.3, 1], "metallic": 1, "roughness": 0.7,
                         "normal_texture": "textures/normal_bumps128.png", "normal_scale": 0.6}},
           {"builtin": {"type": "cube", "size": 0.8}, "transform": {"translate": [1.45, 0, -0.2], "rotate": [20, 35, 0], "scale": [-1, 1, 1]},
            "cull": "none",
            "material": {**base, "color": [0.5, 0.75, 0.55, 1], "normal_texture": "textures/normal_bumps128.png"}}],
          {"eye": [0, 0.8, 3.4], "target": [0.1, 0, 0], "fov_y": 45})


if __name__ == '__main__':
    main()
