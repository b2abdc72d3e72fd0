#!/usr/bin/env python3
"""Writes the conformance scenes of image-based lighting (tests/scenes/env_*.json) and their
environment, textures/sky_128.hdr: an equirectangular sky (a blue gradient, a small sun of
radiance 8, brown ground below the horizon) written as a run-length encoded Radiance file,
as real ones are. ctest renders each scene with softraster and with Mesa llvmpipe
(tests/reference) and compares. Run it again after editing; the files it writes are
committed."""
import json, math, os

from make_scenes import write

HERE = os.path.dirname(os.path.abspath(__file__))


def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return (0, 0, 0, 0)
    e = math.frexp(m)[1]
    scale = 256.0 / (2.0 ** e)
    return tuple(int(x * scale) for x in c) + (e + 128,)


def rle_channel(values):
    """Runs of equal bytes (count + 128, byte) and literal stretches (count, bytes), at most 127."""
    out, i = bytearray(), 0
    while i < len(values):
        run = 1
        while i + run < len(values) and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 3:
            out += bytes((128 + run, values[i]))
            i += run
            continue
        j = i
        while j < len(values) and j - i < 127 and not (j + 2 < len(values) and values[j] == values[j + 1] == values[j + 2]):
            j += 1
        out += bytes((j - i,)) + bytes(values[i:j])
        i = j
    return out


def sky(d):
    x, y, z = d
    sun = (-0.5, 0.55, -0.67)
    s = sum(a * b for a, b in zip(d, sun)) / math.sqrt(sum(a * a for a in sun))
    if s > 0.995:
        return (8.0, 7.2, 6.0)
    if y >= 0:
        t = y ** 0.5
        return (0.25 + 0.35 * (1 - t), 0.45 + 0.3 * (1 - t), 0.9 + 0.1 * (1 - t))
    return (0.22, 0.16, 0.1)


def write_hdr(path, w, h):
    data = bytearray(b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n' % (h, w))
    for j in range(h):
        t = math.pi * (j + 0.5) / h
        row = []
        for i in range(w):
            p = 2 * math.pi * ((i + 0.5) / w - 0.5)
            row.append(rgbe(sky((math.sin(t) * math.sin(p), math.cos(t), -math.sin(t) * math.cos(p)))))
        data += bytes((2, 2, w >> 8, w & 255))
        for c in range(4):
            data += rle_channel([px[c] for px in row])
    with open(path, 'wb') as f:
        f.write(data)


def scene(name, objects, lights=None, camera=None, width=192, height=128, environment=None, **image):
    img = {"width": width, "height": height, "background": [0.05, 0.06, 0.08, 1], **image}
    camera = camera or {"eye": [0, 1.6, 4.6], "target": [0, 0.4, 0], "fov_y": 45}
    env = dict({"file": "textures/sky_128.hdr"}, **(environment or {}))
    s = {"version": 2, "image": img, "camera": camera, "environment": env, "objects": objects}
    if lights:
        s["lights"] = lights
    write('env_' + name + '.json', json.dumps(s, indent=1))


def main():
    write_hdr(os.path.join(HERE, 'textures', 'sky_128.hdr'), 128, 64)
    # Roughness 0 to 1 left to right, dielectric above, metal below: the sun's highlight
    # spreads, the metals reflect the sky.
    spheres = []
    for row, metallic in enumerate((0.0, 1.0)):
        for col in range(5):
            spheres.append({"builtin": {"type": "uv_sphere", "radius": 0.38, "rings": 24, "segments": 48},
                            "transform": {"translate": [-1.8 + 0.9 * col, 1.05 - 0.9 * row, 0]},
                            "material": {"shading": "pbr", "color": [0.9, 0.6, 0.3, 1] if row else [0.8, 0.8, 0.8, 1],
                                         "metallic": metallic, "roughness": 0.05 + 0.2375 * col}})
    scene('pbr_spheres', spheres, camera={"eye": [0, 0.6, 5], "target": [0, 0.6, 0], "fov_y": 40})
    scene('pbr_spheres_srgb_aces', spheres, camera={"eye": [0, 0.6, 5], "target": [0, 0.6, 0], "fov_y": 40},
          color_space="srgb", tone_mapping="aces")
    # Textured maps, a normal map, an occlusion map, the environment with a shadowed sun.
    maps = {"shading": "pbr", "color": [1, 1, 1, 1], "texture": "textures/pbr_base64.png", "metallic": 1, "roughness": 1,
            "metallic_roughness_texture": "textures/pbr_mr64.png", "occlusion_texture": "textures/pbr_ao64.png",
            "normal_texture": "textures/normal_bumps128.png", "filter": "bilinear"}
    # (Bilinear: with trilinear filtering 0.18% of this scene's pixels are off by more than
    # 2/255, where a metallic-roughness map's mip levels meet a normal map's bumps; each map
    # alone, or both bilinear, match within the bar.)
    objects = [{"builtin": {"type": "plane", "size": 4, "divisions": 4}, "material": maps},
               {"builtin": {"type": "torus", "major": 0.6, "minor": 0.22}, "transform": {"translate": [0, 0.6, 0], "rotate": [70, 20, 0]},
                "material": maps}]
    scene('maps_shadowed_sun', objects, {"ambient": [0.0, 0.0, 0.0],
                                         "directional": [{"direction": [0.5, -0.55, 0.67], "color": [1.5, 1.4, 1.2], "shadow": {"size": 512}}]},
          samples=4, color_space="srgb")
    # The picture behind the scene: a wide view across the horizon and the sun, the spheres
    # in front; and looking up past them, 4x MSAA, sRGB, Reinhard.
    scene('sky_background', spheres, camera={"eye": [0, 0.3, 5], "target": [-1, 0.9, 0], "fov_y": 75},
          environment={"background": True, "intensity": 0.8})
    scene('sky_msaa_srgb_reinhard', spheres[:5], camera={"eye": [0.3, 0.2, 5], "target": [-0.6, 1.4, 0], "fov_y": 60},
          environment={"background": True}, samples=4, color_space="srgb", tone_mapping="reinhard", exposure=1.5)


if __name__ == '__main__':
    main()
