#!/usr/bin/env python3
"""views_test.py SOFTRASTER CORPUS WORKDIR: `softraster views`, one model from many cameras:
pictures, depth, masks and cameras.json (intrinsics and poses that agree with the pictures)."""
import json, math, os, shutil, struct, subprocess, sys, zlib

exe, corpus, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from checks import check, failures, finish  # noqa: E402
from imgdiff import read_png  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
DUCK = os.path.join(corpus, 'Collada', 'duck.dae')



def read_png16(path):
    """(width, height, channels, values) of a 16-bit gray or RGB PNG (what libpng writes)."""
    data = open(path, 'rb').read()
    pos, idat = 8, b''
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            w, h, bits, color = struct.unpack('>IIBB', body[:10])
            assert bits == 16 and color in (0, 2), (bits, color)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + length
    ch = 1 if color == 0 else 3
    bpp, stride, raw = 2 * ch, 2 * ch * w, zlib.decompress(idat)
    rows, prev = [], bytearray(stride)
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c][kind]
            line[i] = (line[i] + pred) & 0xff
        rows.append(bytes(line))
        prev = line
    return w, h, ch, struct.unpack('>%dH' % (w * h * ch), b''.join(rows))


def views(out, *args):
    r = subprocess.run([exe, 'views', DUCK, '--out', out, '--size', '64', *args], capture_output=True, text=True)
    check('views %s' % ' '.join(args), r.returncode == 0, r.stderr)
    return json.load(open(os.path.join(out, 'cameras.json')))


out = os.path.join(work, 'sphere')
cams = views(out, '--count', '6', '--depth', '--mask', '--samples', '1')
check('six views', len(cams['views']) == 6 and cams['width'] == 64 and cams['layout'] == 'sphere')
r = cams['normalization']['radius']
check('normalization', r > 0 and len(cams['normalization']['center']) == 3)
for v in cams['views']:
    w, h, ch, pixels = read_png(os.path.join(out, v['color']))
    mw, mh, mch, mask = read_png(os.path.join(out, v['mask']))
    check('picture %s' % v['color'], (w, h, ch) == (64, 64, 4) and pixels[3::4].count(255) > 64 * 64 // 20)
    check('mask %s' % v['mask'], (mw, mh, mch) == (64, 64, 1) and all((m == 255) == (a >= 128) for m, a in zip(mask, pixels[3::4])))
    check('depth %s' % v['color'], os.path.getsize(os.path.join(out, v['depth'])) > 1000)
    K = v['K']
    f = 32 / math.tan(math.radians(15))
    check('K', abs(K[0][0] - f) < 1e-6 * f and K[0][2] == 32 and K[1][2] == 32 and K[2][2] == 1, K)
    # The pose: a rotation (orthonormal rows) whose camera center -R^T t is the eye, looking
    # (+z in OpenCV's convention) at the model's center from `to_eye`.
    M = v['world_to_camera']
    R = [row[:3] for row in M[:3]]
    t = [row[3] for row in M[:3]]
    ortho = all(abs(sum(R[i][k] * R[j][k] for k in range(3)) - (i == j)) < 1e-5 for i in range(3) for j in range(3))
    center = [-sum(R[k][i] * t[k] for k in range(3)) for i in range(3)]
    check('pose', ortho and all(abs(c - e) < 1e-3 * r for c, e in zip(center, v['eye'])), (center, v['eye']))
    forward = R[2]
    check('looks at the center', all(abs(forward[i] + v['to_eye'][i]) < 1e-4 for i in range(3)), (forward, v['to_eye']))
    gl = v['world_to_camera_gl']
    check('OpenGL pose', all(abs(gl[i][j] - (-1 if i in (1, 2) else 1) * M[i][j]) < 1e-9 for i in range(4) for j in range(4)))
dirs = [v['to_eye'] for v in cams['views']]
check('sphere: unit directions from pole to pole', all(abs(math.hypot(*d) - 1) < 1e-5 for d in dirs)
      and dirs[0][1] > 0.8 and dirs[-1][1] < -0.8)

# Depth and normals as 16-bit PNGs, normals in world and camera space: unit normals where the
# model is (the pixels the depth has), zero elsewhere; the camera's are the world's rotated
# by R, and face the camera; depth steps times depth_scale lie within the model's sphere.
world = views(os.path.join(work, 'nw'), '--count', '2', '--depth', '--normals', '--format', 'png16', '--samples', '1')
camera = views(os.path.join(work, 'nc'), '--count', '2', '--normals', '--normals-space', 'camera', '--format', 'png16', '--samples', '1')
for vw, vc in zip(world['views'], camera['views']):
    _, _, dch, depth = read_png16(os.path.join(work, 'nw', vw['depth']))
    _, _, nch, nw = read_png16(os.path.join(work, 'nw', vw['normals']))
    _, _, _, nc = read_png16(os.path.join(work, 'nc', vc['normals']))
    decode = lambda n, p: [n[3 * p + k] / 65535 * 2 - 1 for k in range(3)]  # noqa: E731
    drawn = [p for p in range(64 * 64) if depth[p] > 0]
    check('png16 channels', dch == 1 and nch == 3 and len(drawn) > 200, len(drawn))
    check('normals zero where empty', all(nw[3 * p + k] == 0 for p in range(64 * 64) if depth[p] == 0 for k in range(3)))
    R = [row[:3] for row in vw['world_to_camera'][:3]]
    worst, facing = 0.0, 0.0
    for p in drawn:
        n, m = decode(nw, p), decode(nc, p)
        worst = max(worst, abs(math.hypot(*n) - 1), max(abs(sum(R[i][k] * n[k] for k in range(3)) - m[i]) for i in range(3)))
        facing += m[2] / len(drawn)
    check('normals unit, camera = R world', worst < 1e-3, worst)
    check('camera normals face the camera', facing < -0.3, facing)
    eye_to_center = math.dist(vw['eye'], world['normalization']['center'])
    radius = world['normalization']['radius']
    d = [depth[p] * vw['depth_scale'] for p in drawn]
    check('png16 depth within the sphere', eye_to_center - radius * 1.001 <= min(d) and max(d) <= eye_to_center + radius * 1.001,
          (min(d), max(d), eye_to_center, radius))

# random: the same views for the same seed, others for another; ring: one height.
a = views(os.path.join(work, 'r1'), '--count', '3', '--layout', 'random', '--seed', '7')
b = views(os.path.join(work, 'r2'), '--count', '3', '--layout', 'random', '--seed', '7')
c = views(os.path.join(work, 'r3'), '--count', '3', '--layout', 'random', '--seed', '8')
check('random seed', [v['to_eye'] for v in a['views']] == [v['to_eye'] for v in b['views']]
      and [v['to_eye'] for v in a['views']] != [v['to_eye'] for v in c['views']])
check('random pictures repeat', open(os.path.join(work, 'r1', '000.png'), 'rb').read() == open(os.path.join(work, 'r2', '000.png'), 'rb').read())
ring = views(os.path.join(work, 'ring'), '--count', '4', '--layout', 'ring')
check('ring', len({round(v['to_eye'][1], 6) for v in ring['views']}) == 1)

# Bad input: one line, exit 2.
r = subprocess.run([exe, 'views', os.path.join(work, 'missing.glb'), '--out', os.path.join(work, 'x')], capture_output=True, text=True)
check('missing model', r.returncode == 2 and 'missing.glb' in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr)
r = subprocess.run([exe, 'views', os.path.join(corpus, 'invalid', 'empty.obj'), '--out', os.path.join(work, 'bad', 'x')], capture_output=True, text=True)
check('bad model: exit 2, no folder', r.returncode == 2 and 'empty.obj' in r.stderr and not os.path.exists(os.path.join(work, 'bad')), r.stderr)

finish()
