#!/usr/bin/env python3
"""commands_test.py SOFTRASTER EXAMPLE WORKDIR: --help texts, the showcase, the example."""
import json, os, re, shutil, subprocess, sys, zlib, struct

exe, example, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def run(args):
    return subprocess.run(args, capture_output=True, text=True, timeout=120)


def png_size(path):
    with open(path, 'rb') as f:
        data = f.read(24)
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path
    return struct.unpack('>II', data[16:24])


r = run([exe, '--help'])
if r.returncode != 0 or 'render' not in r.stdout or 'showcase' not in r.stdout:
    failures.append('softraster --help: %d %s' % (r.returncode, r.stdout[:200]))
r = run([exe, 'render', '--help'])
if r.returncode != 0 or '--output' not in r.stdout:
    failures.append('softraster render --help: %d' % r.returncode)
# --version: the version and the commit built (the source tree's, when it is a git checkout).
r = run([exe, '--version'])
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
head = subprocess.run(['git', '-C', src, 'rev-parse', '--short=12', 'HEAD'], capture_output=True, text=True)
expected = head.stdout.strip() if head.returncode == 0 else 'unknown'
if r.returncode != 0 or not re.fullmatch(r'softraster \d+\.\d+(\.\d+)? \(commit %s(-dirty)?\)\n' % re.escape(expected), r.stdout):
    failures.append('softraster --version should name the version and commit %s: %d %r' % (expected, r.returncode, r.stdout))
r = run([exe])
if r.returncode != 2 or len(r.stderr.strip().split('\n')) != 1:
    failures.append('no subcommand should exit 2 with one line: %d %r' % (r.returncode, r.stderr))

# The showcase's picture against the one it drew when this test was written
# (tests/cli/showcase_reference.png; the same pixels in Release, within the conformance bar
# under the sanitizers' -O0): a blank or broken picture fails, not only a missing file.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
import imgdiff  # noqa: E402
out = os.path.join(work, 'showcase.png')
r = run([exe, 'showcase', '-o', out])
if r.returncode != 0 or png_size(out) != (960, 540):
    failures.append('showcase: %d %s' % (r.returncode, r.stderr))
else:
    stats = json.loads(imgdiff.compare(out, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'showcase_reference.png'))[0])
    if stats['frac_over_2'] > 0.001 or stats['psnr_db'] < 38:
        failures.append('showcase differs from tests/cli/showcase_reference.png: %s' % stats)
r = run([exe, 'showcase', '-o', os.path.join(work, 'no_such_dir', 'x.png')])
if r.returncode != 2:
    failures.append('showcase into a missing folder should exit 2, got %d' % r.returncode)

out = os.path.join(work, 'triangle.png')
r = run([example, out])
if r.returncode != 0 or png_size(out) != (480, 360):
    failures.append('example: %d %s' % (r.returncode, r.stderr))

# --- output formats and the pictures of the depth and stencil buffers
mirror = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scenes', 'v2_stencil_mirror.json')
P = lambda name: os.path.join(work, name)
r = run([exe, 'render', mirror, '-o', P('m.png')])
w, h, ch, rgba = imgdiff.read_png(P('m.png'))
r = run([exe, 'render', mirror, '-o', P('m.ppm'), '--depth-out', P('d.png'), '--stencil-out', P('s.png')])
if r.returncode != 0:
    failures.append('render with --depth-out/--stencil-out: %d %s' % (r.returncode, r.stderr))
else:
    ppm = open(P('m.ppm'), 'rb').read()
    header = b'P6\n%d %d\n255\n' % (w, h)
    rgb = bytes(b for i, b in enumerate(rgba) if i % 4 != 3)
    if not ppm.startswith(header) or ppm[len(header):] != rgb:
        failures.append('PPM output differs from the PNG output')
    sw, sh, sc, stencil = imgdiff.read_png(P('s.png'))
    if (sw, sh, sc) != (w, h, 1) or set(stencil) != {0, 1} or stencil.count(1) < 2000:
        failures.append('stencil picture: %dx%d, %d channels, values %s' % (sw, sh, sc, sorted(set(stencil))[:8]))
    d = open(P('d.png'), 'rb').read()
    width, height, depth, color = struct.unpack('>IIBB', d[16:26])
    idat, pos = b'', 8
    while pos < len(d):
        n, t = struct.unpack('>I4s', d[pos:pos + 8])
        if t == b'IDAT':
            idat += d[pos + 8:pos + 8 + n]
        pos += 12 + n
    raw = imgdiff._unfilter(zlib.decompress(idat), width, height, 2)
    z = struct.unpack('>%dH' % (width * height), bytes(raw))
    if (width, height, depth, color) != (w, h, 16, 0) or min(z) != 0 or max(z) != 65535 or z[0] != 65535:
        failures.append('depth picture: %dx%d, %d bits, color type %d, range %d..%d, corner %d' %
                        (width, height, depth, color, min(z), max(z), z[0]))
r = run([exe, 'render', mirror, '-o', P('m.exr'), '--depth-out', P('d.exr')])
if r.returncode != 0 or any(open(P(f), 'rb').read(4) != b'\x76\x2f\x31\x01' for f in ('m.exr', 'd.exr')):
    failures.append('EXR output: %d %s' % (r.returncode, r.stderr))
r = run([exe, 'render', mirror, '-o', P('m.tga')])
tga = open(P('m.tga'), 'rb').read(18) if r.returncode == 0 else b''
if len(tga) < 18 or tga[2] not in (2, 10) or struct.unpack('<HH', tga[12:16]) != (w, h) or tga[16] != 32:
    failures.append('TGA output: %d %s' % (r.returncode, r.stderr))
for args, what in (([P('x.jpg')], 'a .jpg output'), ([P('y.png'), '--stencil-out', P('s.exr')], 'a float stencil'),
                   ([P('y.png'), '--depth-out', P('d.tga')], 'a TGA depth picture')):
    r = run([exe, 'render', mirror, '-o'] + args)
    if r.returncode != 2 or len(r.stderr.strip().split('\n')) != 1 or os.path.exists(P('y.png')):
        failures.append('%s should be refused (exit 2, one line, no output): %d %r' % (what, r.returncode, r.stderr))

# bench: the JSON report's counts. Two spheres of 6 x 12 quads (144 triangles each), a frame
# count of our choosing, and times in order.
spheres = P('bench_spheres.json')
with open(spheres, 'w') as f:
    json.dump({"version": 1, "image": {"width": 96, "height": 64},
               "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y": 45},
               "objects": [{"builtin": {"type": "uv_sphere", "rings": 6, "segments": 12}, "transform": {"translate": [x, 0, 0]},
                            "material": {"shading": "unlit", "color": [1, 0.5, 0.2, 1]}} for x in (-0.8, 0.8)]}, f)
r = run([exe, 'bench', spheres, '--frames', '3', '--warmup', '1', '--threads', '2', '--json'])
try:
    b = json.loads(r.stdout) if r.returncode == 0 else {}
except ValueError:
    b = {}
if not (b.get('frames') == 3 and b.get('threads') == 2 and b.get('triangles') == 288 and b.get('fragments_shaded', 0) > 0
        and 0 < b.get('min_ms', 0) <= b.get('median_ms', 0) <= b.get('max_ms', 0)):
    failures.append('bench --json should report 3 frames of 288 triangles: %d %r %s' % (r.returncode, b, r.stderr))
# --scaling: both thread counts' frames, and how much faster the second; refused for one
# thread (nothing to compare) and beside --orbit.
def speedup_matches(b):
    """The speed-up is the 1-thread median over the N-thread one, both printed to 0.001 ms. A
    frame of the small test scene takes some 0.02 ms, so the check allows for that rounding."""
    one, many, half = b['one_thread_median_ms'], b['median_ms'], 0.0005
    return (one - half) / (many + half) - 0.001 <= b.get('speedup', 0) <= (one + half) / (many - half) + 0.001


r = run([exe, 'bench', spheres, '--scaling', '--frames', '3', '--warmup', '1', '--threads', '2', '--json'])
try:
    b = json.loads(r.stdout) if r.returncode == 0 else {}
except ValueError:
    b = {}
if not (b.get('frames') == 3 and b.get('threads') == 2 and 0 < b.get('min_ms', 0) <= b.get('median_ms', 0)
        and 0 < b.get('one_thread_min_ms', 0) <= b.get('one_thread_median_ms', 0)
        and speedup_matches(b)):
    failures.append('bench --scaling --json should report both thread counts and the speedup: %d %r %s' % (r.returncode, b, r.stderr))
for args in (['--threads', '1'], ['--orbit', '--threads', '2']):
    r = run([exe, 'bench', spheres, '--scaling', '--frames', '1'] + args)
    if r.returncode != 2 or len(r.stderr.strip().split('\n')) != 1 or r.stdout:
        failures.append('bench --scaling %s should be refused (exit 2, one line): %d %r' % (' '.join(args), r.returncode, r.stderr))
# ... and the CPU copies it ran on: the generic one when forced, never AVX-512 when that is off.
for env, allowed in (({}, ('avx512', 'avx2', 'generic')), ({'SOFTRASTER_GENERIC': '1'}, ('generic',)),
                     ({'SOFTRASTER_NO_AVX512': '1'}, ('avx2', 'generic'))):
    r = subprocess.run([exe, 'bench', spheres, '--frames', '1', '--warmup', '0', '--json'], capture_output=True, text=True,
                       env=dict(os.environ, **env))
    try:
        path = json.loads(r.stdout).get('cpu_path') if r.returncode == 0 else None
    except ValueError:
        path = None
    if path not in allowed:
        failures.append('bench --json with %r should name its CPU path, one of %r: %r %s' % (env, allowed, path, r.stderr))

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('commands behave')
