#!/usr/bin/env python3
"""model_commands_test.py SOFTRASTER CORPUS WORKDIR: `render MODEL` and `thumbnails`.

CORPUS is Debian's assimp-testmodels folder (/usr/share/assimp/models)."""
import json, os, shutil, signal, struct, subprocess, sys, time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from checks import check, failures  # noqa: E402

exe, corpus, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
DUCK = os.path.join(corpus, 'Collada', 'duck.dae')
BOX = os.path.join(corpus, 'glTF2', 'BoxTextured-glTF', 'BoxTextured.gltf')
CAMERAS = os.path.join(corpus, 'glTF2', 'cameras', 'Cameras.gltf')


def run(args, timeout=120):
    return subprocess.run([exe] + args, capture_output=True, text=True, timeout=timeout)


def png_size(path):
    with open(path, 'rb') as f:
        data = f.read(24)
    return struct.unpack('>II', data[16:24]) if data[:8] == b'\x89PNG\r\n\x1a\n' else None



# render MODEL: size, views, flags that only models take.
out = os.path.join(work, 'duck.png')
r = run(['render', DUCK, '-o', out, '--size', '300x200', '--view', 'front', '--samples', '1'])
check('render duck', r.returncode == 0 and png_size(out) == (300, 200), r.stderr)
out = os.path.join(work, 'box.png')
r = run(['render', BOX, '-o', out])
check('render box default size', r.returncode == 0 and png_size(out) == (512, 512), r.stderr)
r = run(['render', DUCK, '-o', os.path.join(work, 'v.png'), '--size', '16', '-v'])
check('render -v says what is not drawn', r.returncode == 0 and "not drawn: the file's lights" in r.stderr, r.stderr)
r = run(['thumbnails', DUCK, '--out', os.path.join(work, 'verbose'), '--size', '16', '-v'])
check('thumbnails -v says what is not drawn', r.returncode == 0 and "not drawn: the file's lights" in r.stderr, r.stderr)
if os.path.exists(CAMERAS):
    r = run(['render', CAMERAS, '-o', os.path.join(work, 'cam.png'), '--camera', '0'])
    check('render --camera 0', r.returncode == 0, r.stderr)
for args, what in [(['--size', '0'], '--size'), (['--size', '20x'], '--size'), (['--background', '1,2,3'], '--background'),
                   (['--background', '#12345'], '--background'), (['--camera', '99'], 'camera')]:
    target = os.path.join(work, 'bad.png')
    r = run(['render', DUCK, '-o', target] + args)
    check('render %s' % args, r.returncode == 2 and what in r.stderr and len(r.stderr.strip().splitlines()) == 1
          and not os.path.exists(target), '%d %r' % (r.returncode, r.stderr))
for args, what in [(['--color-space', 'rec2020'], '--color-space'), (['--tone-mapping', 'filmic'], '--tone-mapping'),
                   (['--exposure', '0'], '--exposure')]:
    target = os.path.join(work, 'bad.png')
    r = run(['render', BOX, '-o', target] + args)
    check('render %s' % args, r.returncode == 2 and what in r.stderr and not os.path.exists(target), '%d %r' % (r.returncode, r.stderr))


def png_pixels(path):
    """The RGBA bytes of an 8-bit RGBA PNG as stb writes it (filter bytes per row)."""
    import zlib
    data = open(path, 'rb').read()
    w, h = struct.unpack('>II', data[16:24])
    idat, at = b'', 8
    while at < len(data):
        n, kind = struct.unpack('>I4s', data[at:at + 8])
        if kind == b'IDAT':
            idat += data[at + 8:at + 8 + n]
        at += 12 + n
    raw, rows, prev = zlib.decompress(idat), [], bytearray(w * 4)
    for y in range(h):
        f, row = raw[y * (w * 4 + 1)], bytearray(raw[y * (w * 4 + 1) + 1:(y + 1) * (w * 4 + 1)])
        for i in range(len(row)):
            a = row[i - 4] if i >= 4 else 0
            b, c = prev[i], prev[i - 4] if i >= 4 else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else (b if abs(p - b) <= abs(p - c) else c)][f]
            row[i] = (row[i] + pred) & 255
        rows.append(row)
        prev = row
    return w, h, rows


# The color space: sRGB (the default for models) encodes the light, so the lit box is
# lighter than with --color-space linear; the background keeps the values asked for either way.
lit = {}
for space in ('srgb', 'linear'):
    target = os.path.join(work, 'box_%s.png' % space)
    r = run(['render', BOX, '-o', target, '--size', '64', '--color-space', space, '--background', '#204060'])
    check('render --color-space %s' % space, r.returncode == 0, r.stderr)
    w, h, rows = png_pixels(target)
    check('background as asked (%s)' % space, tuple(rows[0][0:4]) == (0x20, 0x40, 0x60, 255), tuple(rows[0][0:4]))
    lit[space] = sum(rows[32][4 * 32:4 * 32 + 3])
check('sRGB is lighter than linear', lit['srgb'] > lit['linear'] + 30, lit)
r = run(['render', BOX, '-o', os.path.join(work, 'box_aces.png'), '--size', '64', '--tone-mapping', 'aces', '--exposure', '2'])
check('render --tone-mapping aces', r.returncode == 0 and png_pixels(os.path.join(work, 'box_aces.png'))[2][32] !=
      png_pixels(os.path.join(work, 'box_srgb.png'))[2][32], r.stderr)

# --shadows and --ssao each darken the floor beside the cube, and brighten nothing.
CUBE_ON_FLOOR = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scenes', 'models', 'normal_mapped.gltf')


def darkens(flag, at_least):
    rows_of = {}
    for args in ([], [flag]):
        target = os.path.join(work, 'floor%s.png' % ''.join(args))
        r = run(['render', CUBE_ON_FLOOR, '-o', target, '--size', '96'] + args)
        check('render %s' % args, r.returncode == 0, r.stderr)
        rows_of[bool(args)] = png_pixels(target)[2]
    darker = sum(a < b for ra, rb in zip(rows_of[True], rows_of[False]) for a, b in zip(ra, rb))
    brighter = sum(a > b for ra, rb in zip(rows_of[True], rows_of[False]) for a, b in zip(ra, rb))
    check('%s darkens' % flag, darker > at_least and brighter == 0, (darker, brighter))


darkens('--shadows', 100)
darkens('--ssao', 50)

# --anisotropy: more lookups where the duck's texture is minified and stretched; 17 is refused.
pics = {}
for n in ('1', '16'):
    target = os.path.join(work, 'duck_aniso%s.png' % n)
    r = run(['render', DUCK, '-o', target, '--size', '48', '--samples', '1', '--anisotropy', n])
    check('render --anisotropy %s' % n, r.returncode == 0, r.stderr)
    pics[n] = png_pixels(target)[2]
changed = sum(a != b for ra, rb in zip(pics['1'], pics['16']) for a, b in zip(ra, rb))
check('--anisotropy changes minified texels', changed > 20, changed)
r = run(['render', DUCK, '-o', os.path.join(work, 'a17.png'), '--anisotropy', '17'])
check('render --anisotropy 17', r.returncode == 2 and '--anisotropy' in r.stderr and not os.path.exists(os.path.join(work, 'a17.png')), r.stderr)

# --env: a uniform environment lights a pbr model's materials; a cut file is one line, exit 2.
hdr = b'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n' + b'\x80\x80\x80\x81' * 8
open(os.path.join(work, 'white.hdr'), 'wb').write(hdr)
open(os.path.join(work, 'cut.hdr'), 'wb').write(hdr[:-4])
target = os.path.join(work, 'box_env.png')
r = run(['render', BOX, '-o', target, '--size', '64', '--shading', 'pbr', '--env', os.path.join(work, 'white.hdr')])
check('render --env', r.returncode == 0, r.stderr)
r2 = run(['render', BOX, '-o', os.path.join(work, 'box_pbr.png'), '--size', '64', '--shading', 'pbr'])
check('--env lights the model', r.returncode == 0 and r2.returncode == 0 and
      sum(png_pixels(target)[2][32]) > sum(png_pixels(os.path.join(work, 'box_pbr.png'))[2][32]) + 100)
r = run(['render', BOX, '-o', os.path.join(work, 'no.png'), '--env', os.path.join(work, 'cut.hdr')])
check('--env cut file', r.returncode == 2 and 'cut.hdr: corrupt Radiance HDR' in r.stderr and len(r.stderr.strip().splitlines()) == 1
      and not os.path.exists(os.path.join(work, 'no.png')), r.stderr)

scene = os.path.join(work, 'scene.json')
json.dump({'version': 1, 'image': {'width': 8, 'height': 8}, 'camera': {'eye': [0, 0, 3], 'target': [0, 0, 0]},
           'objects': []}, open(scene, 'w'))
r = run(['render', scene, '-o', os.path.join(work, 's.png'), '--size', '64'])
check('model options on a scene', r.returncode == 2 and 'model files' in r.stderr, r.stderr)
r = run(['render', os.path.join(work, 'nothing.glb'), '-o', os.path.join(work, 'n.png')])
check('render missing model', r.returncode == 2 and 'nothing.glb' in r.stderr, r.stderr)

# thumbnails: a folder with a good model, a broken one and a subfolder; names mirror the tree.
models = os.path.join(work, 'models')
os.makedirs(os.path.join(models, 'sub'))
shutil.copy(DUCK, os.path.join(models, 'duck.dae'))
shutil.copy(os.path.join(corpus, 'STL', 'Spider_ascii.stl'), os.path.join(models, 'sub', 'spider.stl'))
open(os.path.join(models, 'broken.obj'), 'w').write('v 0 0 0\nf 1 2 3\n')
open(os.path.join(models, 'notes.txt'), 'w').write('not a model\n')
thumbs = os.path.join(work, 'thumbs')
r = run(['thumbnails', models, '--out', thumbs, '--size', '32'])
report = json.load(open(os.path.join(thumbs, 'thumbnails.json')))
status = {os.path.relpath(e['input'], models): e['status'] for e in report['inputs']}
check('thumbnails exit 1 with a failure', r.returncode == 1, '%d %s' % (r.returncode, r.stderr))
check('thumbnails statuses', status == {'broken.obj': 'failed', 'duck.dae': 'ok', 'sub/spider.stl': 'ok'}, status)
check('thumbnails mirrors the tree', png_size(os.path.join(thumbs, 'sub', 'spider.stl.png')) == (32, 32))
check('thumbnails failure line', any(l.startswith('failed') and 'broken.obj' in l for l in r.stderr.splitlines()), r.stderr)
check('thumbnails summary', report['summary']['ok'] == 2 and report['summary']['failed'] == 1, report['summary'])

# --skip-existing: a re-run draws only what has no picture yet.
os.remove(os.path.join(thumbs, 'duck.dae.png'))
r = run(['thumbnails', models, '--out', thumbs, '--size', '32', '--skip-existing'])
report = json.load(open(os.path.join(thumbs, 'thumbnails.json')))
status = {os.path.relpath(e['input'], models): e['status'] for e in report['inputs']}
check('skip-existing', status == {'broken.obj': 'failed', 'duck.dae': 'ok', 'sub/spider.stl': 'skipped'}, status)

# Globs: the matches, named relative to the pattern's folders without wildcards.
r = run(['thumbnails', os.path.join(models, '*', '*.stl'), os.path.join(models, '*.dae'), '--out', os.path.join(work, 'glob'),
         '--size', '16'])
check('thumbnails globs', r.returncode == 0 and png_size(os.path.join(work, 'glob', 'sub', 'spider.stl.png')) == (16, 16)
      and png_size(os.path.join(work, 'glob', 'duck.dae.png')) == (16, 16), r.stderr)

# A texture that cannot be read: the model is drawn without it, with a warning line.
notex = os.path.join(work, 'notex')
os.makedirs(notex)
scenes_models = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scenes', 'models')
for f in ('materials.obj', 'materials.mtl'):
    shutil.copy(os.path.join(scenes_models, f), notex)
r = run(['render', os.path.join(notex, 'materials.obj'), '-o', os.path.join(work, 'notex.png'), '--size', '32'])
check('render with a missing texture warns', r.returncode == 0 and 'warning' in r.stderr and 'obj_texture.png' in r.stderr
      and png_size(os.path.join(work, 'notex.png')) == (32, 32), r.stderr)
r = run(['thumbnails', notex, '--out', os.path.join(work, 'notex_out'), '--size', '16'])
check('thumbnails with a missing texture warns', r.returncode == 0 and 'obj_texture.png' in r.stderr, r.stderr)

# All good: exit 0. Bad usage: exit 2.
r = run(['thumbnails', DUCK, '--out', os.path.join(work, 'one')])
check('thumbnails all good exits 0', r.returncode == 0 and png_size(os.path.join(work, 'one', 'duck.dae.png')) == (256, 256),
      r.stderr)
r = run(['thumbnails', os.path.join(work, 'empty_dir_missing'), '--out', os.path.join(work, 'none')])
check('thumbnails missing input is a failed entry', r.returncode == 1, '%d %s' % (r.returncode, r.stderr))
r = run(['thumbnails', DUCK, '--out', os.path.join(work, 'x'), '--jobs', '-1'])
check('thumbnails bad flag exits 2', r.returncode == 2, '%d %s' % (r.returncode, r.stderr))

# A model that hangs (a FIFO nobody writes) is given up after --timeout; one whose process
# dies (killed here with SIGSEGV, as a crashing importer would) is reported as crashed. The
# other files are drawn either way.
hang = os.path.join(work, 'hang')
os.makedirs(hang)
os.mkfifo(os.path.join(hang, 'stuck.obj'))
shutil.copy(DUCK, os.path.join(hang, 'duck.dae'))
# (Named one by one: a folder walk takes regular files only.)
r = run(['thumbnails', os.path.join(hang, 'stuck.obj'), os.path.join(hang, 'duck.dae'), '--out', os.path.join(work, 'hang_out'),
         '--timeout', '1', '--jobs', '2'], timeout=60)
report = json.load(open(os.path.join(work, 'hang_out', 'thumbnails.json')))
reasons = {os.path.basename(e['input']): (e['status'], e.get('reason', '')) for e in report['inputs']}
check('timeout', r.returncode == 1 and reasons.get('stuck.obj', ('', ''))[1].startswith('timed out')
      and reasons.get('duck.dae', ('',))[0] == 'ok', reasons)
stuck_only = os.path.join(work, 'stuck_only')
os.makedirs(stuck_only)
os.mkfifo(os.path.join(stuck_only, 'stuck.obj'))
# (One at a time, the stuck file first: the only child seen while it runs is its own.)
p = subprocess.Popen([exe, 'thumbnails', os.path.join(stuck_only, 'stuck.obj'), DUCK, '--out', os.path.join(work, 'crash_out'), '--jobs', '1',
                      '--timeout', '60'],
                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
children = []
for _ in range(200):
    time.sleep(0.05)
    try:
        children = open('/proc/%d/task/%d/children' % (p.pid, p.pid)).read().split()
    except OSError:
        children = []
    if children:
        break
for c in children:
    os.kill(int(c), signal.SIGSEGV)
p.communicate(timeout=60)
report = json.load(open(os.path.join(work, 'crash_out', 'thumbnails.json')))
reasons = {os.path.basename(e['input']): (e['status'], e.get('reason', '')) for e in report['inputs']}
# (Under AddressSanitizer the child's SIGSEGV handler aborts: signal 6.)
check('crash', p.returncode == 1 and 'crashed (signal ' in reasons.get('stuck.obj', ('', ''))[1]
      and reasons.get('duck.dae', ('',))[0] == 'ok', reasons)

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('ok')
