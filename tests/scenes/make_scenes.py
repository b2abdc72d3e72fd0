#!/usr/bin/env python3
"""Writes the project's own conformance scenes (tests/scenes/*.json, with their meshes and
textures), chosen so that every feature of scene format v1 is drawn by at least one scene.
ctest renders each with softraster and with Mesa llvmpipe (tests/reference) and compares.
Run it again after editing; the files it writes are committed."""
import json, math, os, shutil, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
LIGHTS = {"ambient": [0.12, 0.12, 0.14],
          "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.85, 0.82, 0.78]},
                          {"direction": [0.8, -0.2, 0.3], "color": [0.25, 0.3, 0.4]}]}


def write(rel, data):
    path = os.path.join(HERE, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'wb') as f:
        f.write(data.encode() if isinstance(data, str) else data)


def scene(name, width, height, camera, objects, lights=None, background=None, samples=1):
    image = {"width": width, "height": height}
    if background:
        image["background"] = background
    if samples != 1:
        image["samples"] = samples
    s = {"version": 1, "image": image, "camera": camera, "objects": objects}
    if lights:
        s["lights"] = lights
    write(name + '.json', json.dumps(s, indent=1))


# ---------------------------------------------------------------- textures
def png(w, h, pixels, channels=4):
    color_type = {3: 2, 4: 6}[channels]
    raw = b''.join(b'\x00' + bytes(pixels[y * w * channels:(y + 1) * w * channels]) for y in range(h))
    chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, color_type, 0, 0, 0)) +
            chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))


def texture(name, w, h, f):
    """textures/NAME: a w x h RGBA PNG whose pixel (x, y), row 0 at the top, is f(x, y)."""
    px = []
    for y in range(h):
        for x in range(w):
            px += f(x, y)
    write('textures/' + name, png(w, h, px))


def bmp(w, h, rgb):  # 24-bit, bottom-up rows
    row = (w * 3 + 3) & ~3
    data = b''
    for y in reversed(range(h)):
        r = b''.join(bytes((rgb[(y * w + x) * 3 + 2], rgb[(y * w + x) * 3 + 1], rgb[(y * w + x) * 3])) for x in range(w))
        data += r + b'\x00' * (row - w * 3)
    return b'BM' + struct.pack('<IHHI', 54 + len(data), 0, 0, 54) + struct.pack('<IiiHHIIiiII', 40, w, h, 1, 24, 0, len(data), 2835, 2835, 0, 0) + data


def tga(w, h, rgba):  # uncompressed 32-bit, top-left origin
    header = bytes([0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0]) + struct.pack('<HH', w, h) + bytes([32, 0x28])
    return header + b''.join(bytes((rgba[i + 2], rgba[i + 1], rgba[i], rgba[i + 3])) for i in range(0, len(rgba), 4))


def pattern(w, h, alpha=False):
    """Distinct colors per texel: a gradient with a checker, so orientation and filtering show."""
    px = []
    for y in range(h):
        for x in range(w):
            c = 60 if (x + y) % 2 else 0
            px += [min(255, 40 + 200 * x // max(1, w - 1) + c), min(255, 40 + 200 * y // max(1, h - 1)), 120 + c]
            if alpha:
                px.append(255 if (x // 2 + y // 2) % 2 else 96)
    return px


def make_textures():
    write('textures/tiny4.png', png(4, 4, pattern(4, 4, True), 4))
    write('textures/grid64.png', png(64, 64, pattern(64, 64), 3))
    write('textures/ramp8.bmp', bmp(8, 8, pattern(8, 8)))
    write('textures/ramp8.tga', tga(8, 8, pattern(8, 8, True)))
    shutil.copy(os.path.join(HERE, '..', 'conformance', 'textures', 'SpiderTex.jpg'), os.path.join(HERE, 'textures', 'spider.jpg'))


# ---------------------------------------------------------------- meshes
def quad_obj(normals, uvs, colors):
    lines = ['# quad: %s normals, %s uvs, %s colors' % (normals, uvs, colors)]
    corners = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    cols = [(1, 0.2, 0.2), (0.2, 1, 0.2), (0.2, 0.2, 1), (1, 1, 0.2)]
    for (p, c) in zip(corners, cols):
        lines.append('v %g %g %g' % p + (' %g %g %g' % c if colors else ''))
    if uvs:
        lines += ['vt 0 0', 'vt 1 0', 'vt 1 1', 'vt 0 1']
    if normals:
        lines += ['vn 0.3 0.2 1', 'vn -0.3 0.2 1', 'vn -0.3 -0.2 1', 'vn 0.3 -0.2 1']
    form = lambda i: str(i) + ('/%d' % i if uvs else ('/' if normals else '')) + ('/%d' % i if normals else '')
    lines.append('f ' + ' '.join(form(i) for i in (1, 2, 3, 4)))
    return '\n'.join(lines) + '\n'


def make_meshes():
    write('meshes/quad_plain.obj', quad_obj(False, False, False))
    write('meshes/quad_full.obj', quad_obj(True, True, True))
    write('meshes/quad_uv.obj', quad_obj(False, True, False))
    write('meshes/quad_colors.obj', quad_obj(True, False, True))
    # negative (relative) indices, a pentagon fan, mixed corners with and without normals
    write('meshes/relative.obj', '\n'.join([
        'o pentagon', 'mtllib none.mtl', 'usemtl none', 's off',
        *['v %.6f %.6f 0' % (math.cos(2 * math.pi * k / 5 + 0.3), math.sin(2 * math.pi * k / 5 + 0.3)) for k in range(5)],
        'vn 0 0 1', 'vt 0.5',
        'f -5/-1/-1 -4/-1/-1 -3/-1/-1 -2//-1 -1',
        'l 1 2', 'p 3', 'g rest']) + '\n')
    # PLY: ascii with float colors + alpha and s/t; binary LE with uchar colors; binary BE with normals
    verts = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    uv = [(0, 0), (1, 0), (1, 1), (0, 1)]
    fc = [(1, 0.5, 0.2, 1), (0.2, 1, 0.5, 0.5), (0.5, 0.2, 1, 1), (1, 1, 1, 0.25)]
    head = 'ply\nformat %s 1.0\ncomment softraster test mesh\nobj_info quad\nelement vertex 4\n'
    write('meshes/quad_ascii.ply', head % 'ascii' +
          'property float x\nproperty float y\nproperty float z\nproperty float s\nproperty float t\n'
          'property float red\nproperty float green\nproperty float blue\nproperty float alpha\n'
          'element face 1\nproperty list uchar int vertex_indices\nend_header\n' +
          ''.join('%g %g %g %g %g %g %g %g %g\n' % (p + t + c) for p, t, c in zip(verts, uv, fc)) + '4 0 1 2 3\n')
    body = b''.join(struct.pack('<fffBBBffi', *p, int(c[0] * 255), int(c[1] * 255), int(c[2] * 255), *t, 7) for p, t, c in zip(verts, uv, fc))
    body += struct.pack('<Biiii', 4, 0, 1, 2, 3)
    write('meshes/quad_le.ply', (head % 'binary_little_endian' +
          'property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n'
          'property float texture_u\nproperty float texture_v\nproperty int extra\n'
          'element face 1\nproperty list uchar uint vertex_index\nend_header\n').encode() + body)
    n = [(0.3, 0.3, 1), (-0.3, 0.3, 1), (-0.3, -0.3, 1), (0.3, -0.3, 1)]
    body = b''.join(struct.pack('>dddfffff', *p, *nn, *t) for p, nn, t in zip(verts, n, uv))
    body += struct.pack('>Hhhh', 3, 0, 1, 2) + struct.pack('>Hhhh', 3, 0, 2, 3)
    write('meshes/quad_be.ply', (head % 'binary_big_endian' +
          'property double x\nproperty double y\nproperty double z\nproperty float nx\nproperty float ny\nproperty float nz\n'
          'property float u\nproperty float v\nelement face 2\nproperty list ushort short vertex_indices\nend_header\n').encode() + body)
    # slivers: a fan of very thin triangles, and tiny triangles
    pts, idx = [(0.0, 0.0, 0.0)], []
    for k in range(41):
        a = math.radians(-30 + 1.5 * k)
        pts.append((3 * math.cos(a), 3 * math.sin(a), 0.0))
        if k:
            idx.append((0, k, k + 1))
    write('meshes/sliver_fan.obj', ''.join('v %.7f %.7f %.7f\n' % p for p in pts) + ''.join('f %d %d %d\n' % (a + 1, b + 1, c + 1) for a, b, c in idx))
    tiny = []
    for j in range(30):
        for i in range(40):
            x, y, s = -1 + i * 0.05 + 0.013 * (j % 3), -0.75 + j * 0.05, 0.004 + 0.0011 * ((i * 7 + j) % 5)
            tiny.append([(x, y, 0), (x + s, y + 0.3 * s, 0), (x + 0.2 * s, y + s, 0)])
    write('meshes/tiny.obj', ''.join('v %.7f %.7f %.7f\n' % p for t in tiny for p in t) +
          ''.join('f %d %d %d\n' % (3 * k + 1, 3 * k + 2, 3 * k + 3) for k in range(len(tiny))))
    # huge triangles reaching far beyond the screen, and vertices exactly on near/far
    write('meshes/huge.obj', 'v -5000 -3000 0\nv 5000 -3000 0\nv 0 4000 0\nv -0.2 -0.2 0.5\nv 9000 -0.1 0.5\nv -0.1 9000 0.5\n'
          'vn 0 0 1\nf 1//1 2//1 3//1\nf 4//1 5//1 6//1\n')


def obj(mesh, shading='lambert', **kw):
    o = {"mesh": mesh, "material": dict({"shading": shading}, **kw.pop('material', {}))}
    o.update(kw)
    return o


def builtin(kind, transform=None, material=None, **kw):
    o = {"builtin": {"type": kind}}
    o["builtin"].update(kw.pop('params', {}))
    if transform:
        o["transform"] = transform
    if material:
        o["material"] = material
    o.update(kw)
    return o


def make_scenes():
    persp = lambda eye, target, **kw: dict({"eye": eye, "target": target}, **kw)
    # each shading model at grazing light: lights almost parallel to the surfaces
    grazing = {"ambient": [0.05, 0.05, 0.06], "directional": [
        {"direction": [-1, -0.02, 0], "color": [0.9, 0.8, 0.7]}, {"direction": [0.05, -1, 0.999], "color": [0.3, 0.4, 0.5]}]}
    models = ['unlit', 'flat', 'gouraud', 'lambert', 'blinn_phong', 'normals', 'depth']
    objs = []
    for i, m in enumerate(models):
        x = -3 + i
        objs.append(builtin('uv_sphere', {"translate": [x, 0.6, 0]}, {"shading": m, "color": [0.9, 0.7, 0.5, 1], "specular": [0.6, 0.6, 0.6], "shininess": 12}, params={"radius": 0.45, "rings": 12, "segments": 24}))
        objs.append(builtin('plane', {"translate": [x, -0.6, 0], "rotate": [70, 0, 0]}, {"shading": m, "color": [0.6, 0.8, 0.9, 1], "specular": [1, 1, 1], "shininess": 0}, params={"size": 0.9, "divisions": 3}, cull="none"))
    scene('shading_grazing', 560, 200, persp([0, 0, 6], [0, 0, 0], fov_y=40), objs, grazing, [0.1, 0.1, 0.1, 1])

    # filters and wraps, magnified (close, small texture) and minified (far, big texture, uv x8)
    objs = []
    for i, (f, w) in enumerate([(f, w) for f in ('nearest', 'bilinear') for w in ('repeat', 'clamp')]):
        objs.append(obj('meshes/quad_uv.obj', 'unlit', transform={"translate": [-2.25 + 1.5 * i, 0.8, 0], "scale": 0.6},
                        material={"texture": "textures/tiny4.png", "filter": f, "wrap": w}))
    scene('texture_magnified', 480, 240, persp([0, 0.8, 3], [0, 0.8, 0], fov_y=40), objs)
    objs = []
    for i, (f, w) in enumerate([(f, w) for f in ('nearest', 'bilinear') for w in ('repeat', 'clamp')]):
        objs.append(builtin('plane', {"translate": [-3 + 2 * i, 0, -6], "rotate": [60, 0, 0]},
                            {"shading": "unlit", "texture": "textures/grid64.png", "filter": f, "wrap": w}, params={"size": 1.8}))
    scene('texture_minified', 400, 160, persp([0, 1.5, 4], [0, 0, -6], fov_y=30), objs)
    # uv outside [0, 1] (repeat vs clamp) with the other file formats
    objs = [obj('meshes/quad_full.obj', 'lambert', transform={"translate": [-1.1, 0, 0]}, material={"texture": "textures/ramp8.bmp", "wrap": "clamp", "filter": "nearest"}),
            obj('meshes/quad_le.ply', 'unlit', transform={"translate": [1.1, 0, 0]}, material={"texture": "textures/ramp8.tga"}),
            builtin('cube', {"translate": [0, 0, -2], "rotate": [20, 30, 0]}, {"shading": "lambert", "texture": "textures/spider.jpg"})]
    scene('texture_formats', 400, 200, persp([0, 0, 4.5], [0, 0, 0], fov_y=40), objs, LIGHTS)

    # blending in several orders: interleaved depths, ties at equal depth, alpha over additive
    objs = [builtin('plane', {"translate": [0, 0, -3], "rotate": [90, 0, 0]}, {"shading": "unlit", "texture": "textures/grid64.png", "filter": "nearest"}, params={"size": 8})]
    specs = [(-0.6, 0.3, 0.0, 'alpha', [1, 0.2, 0.2, 0.5]), (0.3, 0.1, -1.0, 'additive', [0.2, 0.9, 0.3, 0.6]),
             (0.0, -0.4, 0.5, 'alpha', [0.2, 0.3, 1, 0.4]), (0.5, -0.2, 0.5, 'alpha', [1, 1, 0.2, 0.7]),
             (-0.3, -0.5, -0.5, 'additive', [0.9, 0.5, 0.1, 0.8]), (0.2, 0.4, 1.2, 'alpha', [0.8, 0.2, 0.9, 0.3])]
    for (x, y, z, mode, color) in specs:
        objs.append(builtin('uv_sphere', {"translate": [x, y, z]}, {"shading": "blinn_phong", "blend": mode, "color": color, "specular": [0.4, 0.4, 0.4]}, params={"radius": 0.5, "rings": 16, "segments": 32}, cull="none"))
    objs.insert(2, builtin('cube', {"translate": [0.9, 0.6, -0.5], "rotate": [10, 40, 0]}, {"shading": "lambert", "color": [0.7, 0.7, 0.7, 1]}, params={"size": 0.6}))
    scene('blend_orders', 480, 360, persp([0, 0, 4], [0, 0, 0]), objs, LIGHTS, [0.1, 0.1, 0.12, 1])
    scene('blend_orders_reversed', 480, 360, persp([0.5, 0.3, -3.5], [0, 0, 0]), objs, LIGHTS, [0.1, 0.1, 0.12, 1])

    # MSAA on slivers, tiny triangles and blended objects
    objs = [obj('meshes/sliver_fan.obj', 'unlit', cull="none", transform={"translate": [-1.5, -0.5, 0]}, material={"color": [1, 0.9, 0.6, 1]}),
            obj('meshes/tiny.obj', 'unlit', cull="none", transform={"translate": [0.6, 0.3, 0], "scale": 0.8}),
            builtin('torus', {"translate": [0.6, -0.6, 0.3], "rotate": [70, 10, 0]}, {"shading": "blinn_phong", "blend": "alpha", "color": [0.3, 0.6, 1, 0.5], "specular": [0.5, 0.5, 0.5]}, params={"major": 0.5, "minor": 0.15}),
            builtin('uv_sphere', {"translate": [-0.4, 0.6, 0.2]}, {"shading": "gouraud", "blend": "additive", "color": [1, 0.5, 0.2, 0.5]}, params={"radius": 0.4, "rings": 8, "segments": 12})]
    scene('msaa_slivers_blended', 400, 300, persp([0, 0, 4], [0, 0, 0]), objs, LIGHTS, [0.05, 0.05, 0.08, 1], samples=4)

    # clipping at each of the six planes (perspective, near 1, far 8)
    objs = [builtin('cube', {"translate": [-2.6, 0, 0], "rotate": [0, 30, 0]}, {"shading": "normals"}, params={"size": 1.2}),  # left
            builtin('cube', {"translate": [2.6, 0.3, 0], "rotate": [20, 0, 0]}, {"shading": "normals"}, params={"size": 1.2}),  # right
            builtin('torus', {"translate": [0, 1.9, 0], "rotate": [90, 0, 0]}, {"shading": "lambert"}, params={"major": 0.6, "minor": 0.3}),  # top
            builtin('torus', {"translate": [0.3, -1.9, 0], "rotate": [60, 0, 0]}, {"shading": "lambert"}, params={"major": 0.6, "minor": 0.3}),  # bottom
            builtin('uv_sphere', {"translate": [-0.6, 0, 3.4]}, {"shading": "gouraud", "color": [1, 0.6, 0.3, 1]}, params={"radius": 0.8}, cull="none"),  # near
            builtin('plane', {"translate": [0.5, 0, -3.5], "rotate": [80, 0, 0]}, {"shading": "depth"}, params={"size": 6}, cull="none")]  # far
    scene('clip_six_planes', 480, 320, persp([0, 0, 5], [0, 0, 0], near=1, far=8), objs, LIGHTS, [0.2, 0.2, 0.25, 1])

    # orthographic camera; vertices exactly on the near and far planes (eye z = 10, near 2, far 12)
    objs = [obj('meshes/quad_colors.obj', 'unlit', transform={"translate": [-1, 0, 8], "scale": 0.7}),   # on the near plane
            obj('meshes/quad_plain.obj', 'depth', transform={"translate": [1, 0, -2], "scale": 0.7}),    # on the far plane
            builtin('plane', {"translate": [0, -0.9, 3], "rotate": [90, 0, 0]}, {"shading": "depth"}, params={"size": 20}, cull="none"),
            builtin('torus', {"translate": [0, 0.9, 0], "rotate": [40, 30, 0]}, {"shading": "flat", "color": [0.5, 0.8, 0.6, 1]}, front_face="cw", cull="front")]
    scene('ortho_near_far_exact', 360, 240, {"projection": "orthographic", "eye": [0, 0, 10], "target": [0, 0, 0], "height": 3, "near": 2, "far": 12}, objs, LIGHTS)

    # huge and tiny triangles
    objs = [obj('meshes/huge.obj', 'lambert', cull="none", material={"color": [0.4, 0.6, 0.8, 1]}),
            obj('meshes/tiny.obj', 'unlit', cull="none", transform={"translate": [0, 0, 0.6]}, material={"color": [1, 0.8, 0.2, 1]})]
    scene('huge_and_tiny', 320, 240, persp([0, 0, 3], [0, 0, 0]), objs, LIGHTS)

    # meshes with and without normals, uvs and vertex colors; OBJ and PLY variants
    files = ['meshes/quad_plain.obj', 'meshes/quad_full.obj', 'meshes/quad_uv.obj', 'meshes/quad_colors.obj',
             'meshes/relative.obj', 'meshes/quad_ascii.ply', 'meshes/quad_le.ply', 'meshes/quad_be.ply']
    objs = []
    for i, f in enumerate(files):
        shading = ['lambert', 'blinn_phong', 'gouraud', 'lambert'][i % 4]
        objs.append(obj(f, shading, cull="none", transform={"translate": [-2.7 + 1.8 * (i % 4), 0.95 - 1.9 * (i // 4), 0], "rotate": [0, 25, 0], "scale": 0.75},
                        material={"texture": "textures/tiny4.png", "specular": [0.5, 0.5, 0.5], "blend": "alpha" if f.endswith('ascii.ply') else "opaque"}))
    scene('mesh_variants', 480, 240, persp([0, 0, 5], [0, 0, 0], fov_y=50), objs, LIGHTS, [0.2, 0.2, 0.2, 1])

    # a size that is not a multiple of eight or of the 64-pixel tile: the last group of eight
    # pixels in each row is partly outside the image. Stacked opaque layers (hidden-surface
    # removal), then blended and opaque objects across the right and bottom edges.
    objs = [builtin('plane', {"translate": [0.1 * k, 0, -4 + k], "rotate": [90, 0, 0]},
                    {"shading": "lambert", "texture": "textures/grid64.png", "filter": "bilinear", "color": [0.5 + 0.1 * k, 0.8, 0.7, 1]}, params={"size": 9})
            for k in range(4)]
    objs += [builtin('uv_sphere', {"translate": [1.5, -0.3, 0.5]}, {"shading": "blinn_phong", "blend": "alpha", "color": [1, 0.4, 0.2, 0.6], "specular": [0.5, 0.5, 0.5]}, params={"radius": 0.7}),
             builtin('torus', {"translate": [0.6, -1.1, 0.8], "rotate": [60, 20, 0]}, {"shading": "gouraud", "color": [0.3, 0.7, 1, 1]}, params={"major": 0.5, "minor": 0.2}),
             builtin('cube', {"translate": [-1.2, 0.4, 0.6], "rotate": [30, 40, 0]}, {"shading": "lambert", "blend": "additive", "color": [0.2, 0.6, 0.3, 0.7]}, params={"size": 0.7}, cull="none")]
    scene('odd_size_edges', 301, 203, persp([0, 0, 4], [0, 0, 0]), objs, LIGHTS, [0.1, 0.1, 0.1, 1])


if __name__ == '__main__':
    make_textures()
    make_meshes()
    make_scenes()
    print('scenes written to', HERE)
