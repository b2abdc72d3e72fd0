#!/usr/bin/env python3
"""Writes the conformance scenes of texture sampling (tests/scenes/tex_*.json, their
textures and meshes): a checkerboard floor running to the horizon under every min filter
(nearest and linear, without mipmaps, with the nearest mipmap and between two), the
magnification filter apart, the four wrap modes (and one per axis) on a floor whose texture
coordinates repeat, a texture whose sides are not powers of two, trilinear filtering with
4x MSAA and on lit, textured boxes (and, apart in anisotropic/, anisotropic filtering). ctest renders each with softraster and with Mesa
llvmpipe (tests/reference) and compares. Run it again after editing; the files it writes
are committed."""
import json, os

from make_scenes import texture, write

LIGHTS = {"ambient": [0.2, 0.2, 0.22],
          "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.85, 0.82, 0.78]}]}
FLOOR_CAM = {"eye": [0, 0.55, 3.2], "target": [0, 0.1, -4], "fov_y": 55}


def scene(name, objects, camera=FLOOR_CAM, width=160, height=120, **image):
    img = {"width": width, "height": height, "background": [0.55, 0.7, 0.9, 1], **image}
    s = {"version": 2, "image": img, "camera": camera, "lights": LIGHTS, "objects": objects}
    write('tex_' + name + '.json', json.dumps(s, indent=1))


def main():
    # A 128 x 128 checkerboard of 4-texel cells with colored stripes, so that each mipmap level
    # averages to something different from its neighbors and the horizon shows the filter.
    texture('checker128.png', 128, 128, lambda x, y: [230, 40, 40, 255] if (x // 16 + y // 16) % 4 == 0 else
            ([250, 250, 240, 255] if (x // 4 + y // 4) % 2 else [20, 30, 60, 255]))
    # 100 x 60: neither side a power of two (the chain is 50x30, 25x15, 12x7, 6x3, 3x1, 1x1).
    texture('npot100x60.png', 100, 60, lambda x, y: [(x * 5) % 256, 255 if (x // 3 + y // 3) % 2 else 30, (y * 9) % 256, 255])
    # 16 x 16 with a distinct corner, to tell mirrored from repeated copies.
    texture('corner16.png', 16, 16, lambda x, y: [255, 210, 40, 255] if x < 5 and y < 5 else
            ([40, 90, 200, 255] if (x + y) % 2 else [235, 235, 235, 255]))

    # A floor 12 long whose texture coordinates run from -3 to 3: the texture repeats 6 times.
    write('meshes/floor_uv6.obj', "\n".join([
        "# a floor quad, y = 0, texture coordinates -3..3",
        "v -3 0 1", "v 3 0 1", "v 3 0 -11", "v -3 0 -11",
        "vt -3 -3", "vt 3 -3", "vt 3 3", "vt -3 3",
        "vn 0 1 0",
        "f 1/1/1 2/2/1 3/3/1", "f 1/1/1 3/3/1 4/4/1"]) + "\n")


    def floor(material, mesh=None):
        if mesh:
            return {"mesh": mesh, "material": material, "cull": "none"}
        return {"builtin": {"type": "plane", "size": 12}, "transform": {"translate": [0, 0, -5]},
                "material": material, "cull": "none"}


    def checker(**sampler):
        return {"shading": "unlit", "texture": "textures/checker128.png", **sampler}


    for min_filter in ("nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest",
                       "nearest_mipmap_linear", "linear_mipmap_linear"):
        scene("floor_" + min_filter, [floor(checker(min_filter=min_filter, mag_filter="linear"))])
    scene("floor_trilinear_mag_nearest", [floor(checker(filter="trilinear", mag_filter="nearest"))])
    scene("floor_trilinear_wide", [floor(checker(filter="trilinear"))], width=240, height=90)

    corner = {"shading": "unlit", "texture": "textures/corner16.png", "filter": "trilinear"}
    scene("wrap_repeat", [floor(dict(corner, wrap="repeat"), "meshes/floor_uv6.obj")])
    scene("wrap_mirror", [floor(dict(corner, wrap="mirror"), "meshes/floor_uv6.obj")])
    scene("wrap_clamp", [floor(dict(corner, wrap="clamp"), "meshes/floor_uv6.obj")])
    scene("wrap_border", [floor(dict(corner, wrap="border", border_color=[0.1, 0.6, 0.3, 1]), "meshes/floor_uv6.obj")])
    scene("wrap_per_axis", [floor(dict(corner, wrap=["mirror", "repeat"]), "meshes/floor_uv6.obj")])

    scene("npot_trilinear", [floor({"shading": "unlit", "texture": "textures/npot100x60.png", "filter": "trilinear"})])
    scene("floor_trilinear_msaa4", [floor(checker(filter="trilinear"))], samples=4)

    BOX_CAM = {"eye": [2.4, 1.9, 3.3], "target": [0, 0, 0], "fov_y": 45}
    boxes = []
    for i, (shading, x, scale) in enumerate((("lambert", -1.1, 1.0), ("blinn_phong", 0.3, 0.55), ("gouraud", 1.2, 0.3))):
        m = {"shading": shading, "texture": "textures/checker128.png", "filter": "trilinear"}
        if shading == "blinn_phong":
            m.update(specular=[0.4, 0.4, 0.4], shininess=20)
        boxes.append({"builtin": {"type": "cube", "size": 1}, "material": m,
                      "transform": {"translate": [x, 0, -0.4 * i], "rotate": [15, 30 + 20 * i, 0], "scale": scale}})
    scene("boxes_lit_trilinear", boxes, camera=BOX_CAM)

    # Anisotropic filtering: llvmpipe's filter is another one (elliptical, EWA), so these are
    # not conformance scenes; docs/materials.md shows them beside llvmpipe's with the
    # measured difference (scripts/side-by-side.py), and texture_test.cpp checks ours.
    for n in (4, 16):
        s = {"version": 2, "image": {"width": 240, "height": 90, "background": [0.55, 0.7, 0.9, 1]}, "camera": FLOOR_CAM,
             "lights": LIGHTS, "objects": [floor(dict(checker(filter="trilinear", anisotropy=n), texture="../textures/checker128.png"))]}
        write('anisotropic/aniso_floor_%dx.json' % n, json.dumps(s, indent=1))


if __name__ == '__main__':
    main()
