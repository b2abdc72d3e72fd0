#!/usr/bin/env python3
"""bad_input_test.py SOFTRASTER CONFORMANCE_DIR WORKDIR

Every kind of bad input to `softraster render` must give exactly one line on stderr that
names the file and what is wrong, exit code 2, and no output file. Also: NaN positions
render the rest, and a mesh with no faces draws nothing."""
import json, os, shutil, struct, subprocess, sys

exe, conf, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, 'meshes'))
os.makedirs(os.path.join(work, 'textures'))
failures = []

BASE = {"version": 1, "image": {"width": 32, "height": 24},
        "camera": {"eye": [0, 0, 3], "target": [0, 0, 0]},
        "objects": [{"builtin": {"type": "cube"}}]}


def write(name, data):
    path = os.path.join(work, name)
    with open(path, 'wb') as f:
        f.write(data if isinstance(data, bytes) else data.encode())
    return path


def scene_with(name, **changes):
    s = json.loads(json.dumps(BASE))
    for key, value in changes.items():
        if key == 'object':
            s['objects'] = [value]
        else:
            section, field = key.split('__')
            s[section][field] = value
    return write(name, json.dumps(s))


def expect_bad(label, scene_path, must_mention, args=()):
    out = os.path.join(work, 'out.png')
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([exe, 'render', scene_path, '-o', out, *args], capture_output=True, text=True, timeout=60)
    lines = r.stderr.strip().split('\n')
    problems = []
    if r.returncode != 2:
        problems.append('exit %d' % r.returncode)
    if len(lines) != 1 or not lines[0]:
        problems.append('%d stderr lines' % len(lines))
    for m in must_mention:
        if m not in r.stderr:
            problems.append('stderr lacks %r' % m)
    if os.path.exists(out) or os.path.exists(out + '.tmp'):
        problems.append('output file written')
    status = 'ok  ' if not problems else 'FAIL'
    print('%s %-34s %s' % (status, label, r.stderr.strip()))
    if problems:
        failures.append('%s: %s' % (label, ', '.join(problems)))


def obj_scene(name, obj_text):
    mesh = write('meshes/%s.obj' % name, obj_text)
    return scene_with(name + '.json', object={"mesh": "meshes/%s.obj" % name}), mesh


def ply_scene(name, ply_data):
    mesh = write('meshes/%s.ply' % name, ply_data)
    return scene_with(name + '.json', object={"mesh": "meshes/%s.ply" % name}), mesh


def tex_scene(name, filename, data):
    path = write('textures/' + filename, data) if data is not None else os.path.join(work, 'textures', filename)
    return scene_with(name + '.json', object={"builtin": {"type": "cube"},
                                              "material": {"texture": "textures/" + filename}}), path


# --- scene files
expect_bad('missing scene', os.path.join(work, 'nope.json'), ['nope.json', 'not found'])
expect_bad('malformed JSON', write('malformed.json', '{"version": 1, "image": }'), ['malformed.json', 'line 1'])
expect_bad('truncated JSON', write('trunc.json', json.dumps(BASE)[:40]), ['trunc.json', 'malformed'])
expect_bad('empty file', write('empty.json', ''), ['empty.json'])
expect_bad('unknown key', scene_with('unk.json', image__widht=3), ['unk.json', 'image.widht', 'unknown key'])
expect_bad('wrong type', scene_with('type.json', image__width="640"), ['type.json', 'image.width'])
expect_bad('width 0', scene_with('w0.json', image__width=0), ['image.width', 'out of range'])
expect_bad('width 20000', scene_with('w2.json', image__width=20000), ['image.width', 'out of range'])
expect_bad('samples 3', scene_with('s3.json', image__samples=3), ['image.samples'])
expect_bad('near >= far', scene_with('nf.json', camera__near=10, camera__far=10), ['camera', 'near'])
expect_bad('fov_y 0', scene_with('fov0.json', camera__fov_y=0), ['camera.fov_y'])
expect_bad('fov_y 180', scene_with('fov180.json', camera__fov_y=180), ['camera.fov_y'])
expect_bad('eye == target', scene_with('eye.json', camera__eye=[0, 0, 0]), ['eye and target'])
expect_bad('too many lights', write('lights.json', json.dumps(dict(BASE, lights={"directional": [{"direction": [0, -1, 0]}] * 9}))), ['lights.directional'])
expect_bad('zero light direction', write('ldir.json', json.dumps(dict(BASE, lights={"directional": [{"direction": [0, 0, 0]}]}))), ['direction'])
expect_bad('bad shading', scene_with('shade.json', object={"builtin": {"type": "cube"}, "material": {"shading": "toon"}}), ['objects[0].material.shading'])
expect_bad('negative shininess', scene_with('shin.json', object={"builtin": {"type": "cube"}, "material": {"shininess": -1}}), ['shininess'])
expect_bad('bad flag', scene_with('flag.json'), ['--frobnicate'], args=['--frobnicate'])

# --- meshes
s, m = obj_scene('missing_ref', 'v 0 0 0\n'); os.remove(m)
expect_bad('missing mesh', s, ['missing_ref.obj', 'not found'])
expect_bad('obj index out of range', obj_scene('oor', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n')[0], ['oor.obj', 'out of range'])
expect_bad('obj index 0', obj_scene('zero', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n')[0], ['zero.obj:4', 'index 0'])
expect_bad('obj non-numeric index', obj_scene('nonnum', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 c\n')[0], ['nonnum.obj:4'])
expect_bad('obj non-numeric coordinate', obj_scene('coord', 'v 0 0 0\nv 1 x 0\n')[0], ['coord.obj:2', 'not a number'])
expect_bad('obj truncated face', obj_scene('truncface', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2')[0], ['truncface.obj:4'])
expect_bad('obj is binary', obj_scene('binary', '\x00\x01\x02garbage')[0], ['binary.obj'])
expect_bad('obj is a PNG', obj_scene('png', open(os.path.join(conf, 'textures', 'checker.png'), 'rb').read().decode('latin-1'))[0], ['png.obj'])
expect_bad('ply truncated', ply_scene('trunc', open(os.path.join(conf, 'meshes', 'fill_rule.ply'), 'rb').read()[:3000])[0], ['trunc.ply', 'truncated'])
expect_bad('ply index out of range', ply_scene('plyoor', 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n')[0], ['plyoor.ply', 'out of range'])
expect_bad('ply is an OBJ', ply_scene('isobj', 'v 0 0 0\n')[0], ['isobj.ply', 'not a PLY'])
expect_bad('unknown mesh type', write('stl.json', json.dumps(dict(BASE, objects=[{"mesh": "meshes/x.stl"}]))), ['x.stl'])

# --- textures
png = open(os.path.join(conf, 'textures', 'checker.png'), 'rb').read()
jpg = open(os.path.join(conf, 'textures', 'SpiderTex.jpg'), 'rb').read()
expect_bad('missing texture', tex_scene('texmissing', 'none.png', None)[0], ['none.png', 'not found'])
expect_bad('truncated PNG', tex_scene('texpng', 'trunc.png', png[:len(png) // 2])[0], ['trunc.png'])
expect_bad('truncated JPEG', tex_scene('texjpg', 'trunc.jpg', jpg[:len(jpg) // 2])[0], ['trunc.jpg'])
expect_bad('corrupt PNG', tex_scene('texcorrupt', 'corrupt.png', png[:40] + b'\x00' * 60 + png[100:])[0], ['corrupt.png'])
expect_bad('JPEG named .png', tex_scene('texwrong', 'wrong.png', jpg)[0], ['wrong.png', 'not a PNG'])
expect_bad('text named .bmp', tex_scene('texbmp', 'text.bmp', b'hello world, not a bitmap')[0], ['text.bmp'])
bmp_header = b'BM' + struct.pack('<IHHI', 54 + 16 * 16 * 3, 0, 0, 54) + struct.pack('<IiiHHIIiiII', 40, 16, 16, 1, 24, 0, 0, 0, 0, 0, 0)
expect_bad('truncated BMP', tex_scene('texbmptrunc', 'short.bmp', bmp_header + b'\x80' * 100)[0], ['short.bmp', 'truncated'])
tga = bytes([0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 16, 0, 16, 0, 24, 0]) + b'\x40' * 50
expect_bad('truncated TGA', tex_scene('textga', 'short.tga', tga)[0], ['short.tga', 'truncated'])

# --- NaN positions render the rest; no faces draws nothing
nan_scene = obj_scene('nanpos', 'v nan 0 0\nv 1 0 0\nv 0 1 0\nv -1 -1 0\nv 1 -1 0\nv 0 0.5 0\nf 1 2 3\nf 4 5 6\n')[0]
out = os.path.join(work, 'nan.png')
r = subprocess.run([exe, 'render', nan_scene, '-o', out], capture_output=True, text=True, timeout=60)
if r.returncode != 0 or not os.path.exists(out):
    failures.append('NaN positions: exit %d %s' % (r.returncode, r.stderr.strip()))
else:
    print('ok   NaN positions render the rest')
empty = ply_scene('noface', 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n')[0]
r = subprocess.run([exe, 'render', empty, '-o', os.path.join(work, 'empty.png')], capture_output=True, text=True, timeout=60)
if r.returncode != 0:
    failures.append('mesh with no faces: exit %d %s' % (r.returncode, r.stderr.strip()))
else:
    print('ok   mesh with no faces draws nothing')

if failures:
    print('\nFAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('all bad-input cases behave')
