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

# --- version 2 keys: each bad value names its JSON path
def v2(name, obj=None, **image):
    s = json.loads(json.dumps(BASE))
    s['version'] = 2
    s['image'].update(image)
    if obj is not None:
        s['objects'] = [dict({"builtin": {"type": "cube"}}, **obj)]
    return write(name, json.dumps(s))


def v1_with(name, obj):
    return write(name, json.dumps(dict(BASE, objects=[dict({"builtin": {"type": "cube"}}, **obj)])))


expect_bad('v2 key in v1 (stencil)', v1_with('v1stencil.json', {"stencil": {"func": "always"}}), ['objects[0].stencil', 'version 2 key'])
expect_bad('v2 key in v1 (supersample)', scene_with('v1ss.json', image__supersample=2), ['image.supersample', 'version 2'])
expect_bad('v2 key in v1 (color_mask)', v1_with('v1mask.json', {"material": {"color_mask": [True] * 4}}), ['objects[0].material.color_mask', 'version 2'])
expect_bad('v2 blend object in v1', v1_with('v1blend.json', {"material": {"blend": {"equation": "min"}}}), ['objects[0].material.blend', 'version 2'])
expect_bad('v1 samples 8', scene_with('v1s8.json', image__samples=8), ['image.samples', 'version 2'])
expect_bad('version 3', write('v3.json', json.dumps(dict(BASE, version=3))), ['version', 'out of range'])
expect_bad('samples 6', v2('v2s6.json', samples=6), ['image.samples', 'must be 1, 2, 4, 8 or 16'])
expect_bad('supersample 5', v2('v2ss5.json', supersample=5), ['image.supersample', 'out of range'])
expect_bad('supersample too big', v2('v2ssbig.json', width=9000, supersample=2), ['image.supersample', 'exceed'])
def with_ao(name, ao, version=2):
    s = json.loads(json.dumps(BASE))
    s['version'] = version
    s['ambient_occlusion'] = ao
    return write(name, json.dumps(s))


expect_bad('ao radius 0', with_ao('ao0.json', {"radius": 0}), ['ambient_occlusion.radius', 'out of range'])
expect_bad('ao bias 1', with_ao('aob.json', {"bias": 1}), ['ambient_occlusion.bias', 'out of range'])
expect_bad('ao unknown key', with_ao('aok.json', {"samples": 32}), ['ambient_occlusion', 'samples'])
expect_bad('ao not an object', with_ao('aot.json', True), ['ambient_occlusion', 'object'])
expect_bad('ao in v1', with_ao('aov1.json', {"radius": 1}, version=1), ['ambient_occlusion', 'version 2'])
expect_bad('clear_stencil 256', v2('v2cs.json', clear_stencil=256), ['image.clear_stencil', 'out of range'])
# "model" objects (version 2)
def model_obj(name, obj, version=2):
    s = json.loads(json.dumps(BASE))
    s['version'] = version
    s['objects'] = [obj]
    return write(name, json.dumps(s))


write('cube.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n')
expect_bad('model in v1', model_obj('v1model.json', {"model": "cube.obj"}, 1), ['objects[0].model', 'version 2'])
expect_bad('model and builtin', model_obj('v2mb.json', {"model": "cube.obj", "builtin": {"type": "cube"}}), ['objects[0]', "'model'"])
expect_bad('model with wireframe', model_obj('v2mw.json', {"model": "cube.obj", "wireframe": {}}), ['objects[0].wireframe', 'not with'])
expect_bad('model with a material color', model_obj('v2mc.json', {"model": "cube.obj", "material": {"color": [1, 0, 0]}}),
           ['objects[0].material.color', 'unknown key'])
expect_bad('model missing', model_obj('v2mm.json', {"model": "gone.glb"}), ['gone.glb', 'not found'])
expect_bad('model not a model', model_obj('v2mt.json', {"model": "v2mm.json"}), ['v2mm.json', 'not a model file'])
write('badtex.obj', 'mtllib badtex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl t\nf 1 2 3\n')
write('badtex.mtl', 'newmtl t\nmap_Kd nowhere.png\n')
expect_bad('model texture missing (scene files are strict)', model_obj('v2mtex.json', {"model": "badtex.obj"}),
           ['badtex.obj', 'nowhere.png', 'not found'])
expect_bad('unknown draw_order', write('v2order.json', json.dumps(dict(BASE, version=2, draw_order="random"))), ['draw_order', "unknown value 'random'"])
expect_bad('unknown stencil op', v2('v2op.json', {"stencil": {"pass": "increment"}}), ['objects[0].stencil.pass', "unknown value 'increment'"])
expect_bad('unknown stencil func', v2('v2sf.json', {"stencil": {"front": {"func": "lequal"}}}), ['objects[0].stencil.front.func', 'unknown value'])
expect_bad('stencil ref 300', v2('v2ref.json', {"stencil": {"ref": 300}}), ['objects[0].stencil.ref', 'out of range'])
expect_bad('stencil mask not integer', v2('v2mask.json', {"stencil": {"write_mask": 1.5}}), ['objects[0].stencil.write_mask', 'integer'])
expect_bad('unknown stencil key', v2('v2sk.json', {"stencil": {"front": {}, "side": {}}}), ['objects[0].stencil.side', 'unknown key'])
expect_bad('depth test not bool', v2('v2dt.json', {"depth": {"test": 1}}), ['objects[0].depth.test', 'true or false'])
expect_bad('unknown depth func', v2('v2df.json', {"depth": {"func": "lower"}}), ['objects[0].depth.func', 'unknown value'])
expect_bad('depth offset one number', v2('v2do.json', {"depth": {"offset": 1}}), ['objects[0].depth.offset', '2 numbers'])
expect_bad('scissor of 3', v2('v2sc.json', {"scissor": [0, 0, 4]}), ['objects[0].scissor', '[x, y, width, height]'])
expect_bad('scissor negative', v2('v2scn.json', {"scissor": [-1, 0, 4, 4]}), ['objects[0].scissor[0]', 'out of range'])
expect_bad('unknown blend factor', v2('v2bf.json', {"material": {"blend": {"src": "source_alpha"}}}), ['objects[0].material.blend.src', 'unknown value'])
expect_bad('unknown blend equation', v2('v2be.json', {"material": {"blend": {"equation": "multiply"}}}), ['objects[0].material.blend.equation', 'unknown value'])
expect_bad('blend constant out of range', v2('v2bc.json', {"material": {"blend": {"constant": [0, 0, 2, 1]}}}), ['objects[0].material.blend.constant', '[0, 1]'])
expect_bad('color_mask of 3', v2('v2cm.json', {"material": {"color_mask": [True, True, True]}}), ['objects[0].material.color_mask', '4 booleans'])
expect_bad('color_mask not bool', v2('v2cmb.json', {"material": {"color_mask": [1, 1, 1, 1]}}), ['objects[0].material.color_mask[0]', 'true or false'])
expect_bad('alpha_cutoff 2', v2('v2ac.json', {"material": {"alpha_cutoff": 2}}), ['objects[0].material.alpha_cutoff', 'out of range'])
expect_bad('alpha_to_coverage without MSAA', v2('v2a2c.json', {"material": {"alpha_to_coverage": True}}), ['objects[0].material.alpha_to_coverage', 'samples'])
expect_bad('unknown interpolation', v2('v2int.json', {"material": {"interpolation": "linear"}}), ['objects[0].material.interpolation', 'unknown value'])
expect_bad('unknown min_filter', v2('v2minf.json', {"material": {"min_filter": "trilinear"}}), ['objects[0].material.min_filter', 'unknown value'])
expect_bad('unknown mag_filter', v2('v2magf.json', {"material": {"mag_filter": "linear_mipmap_linear"}}), ['objects[0].material.mag_filter', 'unknown value'])
expect_bad('wrap of 3', v2('v2wrap3.json', {"material": {"wrap": ["repeat", "clamp", "mirror"]}}), ['objects[0].material.wrap', 'array of 2'])
expect_bad('unknown wrap per axis', v2('v2wrapa.json', {"material": {"wrap": ["repeat", "mirrored"]}}), ['objects[0].material.wrap[1]', 'unknown value'])
expect_bad('border_color out of range', v2('v2border.json', {"material": {"border_color": [0, 0, 1.5, 1]}}), ['objects[0].material.border_color', '0..1'])
expect_bad('anisotropy 17', v2('v2an17.json', {"material": {"anisotropy": 17}}), ['objects[0].material.anisotropy', 'out of range'])
expect_bad('anisotropy 2.5', v2('v2an25.json', {"material": {"anisotropy": 2.5}}), ['objects[0].material.anisotropy', 'integer'])
expect_bad('anisotropy in v1', v1_with('v1an.json', {"material": {"anisotropy": 4}}), ['objects[0].material.anisotropy', 'version 2'])
expect_bad('trilinear in v1', v1_with('v1tri.json', {"material": {"filter": "trilinear"}}), ['objects[0].material.filter', 'version 2'])
expect_bad('mirror in v1', v1_with('v1mirror.json', {"material": {"wrap": "mirror"}}), ['objects[0].material.wrap', 'version 2'])
expect_bad('min_filter in v1', v1_with('v1minf.json', {"material": {"min_filter": "linear"}}), ['objects[0].material.min_filter', 'version 2'])


def with_lights(name, lights, version=2):
    s = json.loads(json.dumps(BASE))
    s['version'] = version
    s['lights'] = lights
    return write(name, json.dumps(s))


expect_bad('point light in v1', with_lights('v1point.json', {"point": [{"position": [0, 1, 0]}]}, version=1), ['lights.point', 'version 2 key'])
expect_bad('point light without position', with_lights('pl0.json', {"point": [{"color": [1, 1, 1]}]}), ['lights.point[0].position', 'missing'])
expect_bad('negative range', with_lights('plr.json', {"point": [{"position": [0, 1, 0], "range": -2}]}), ['lights.point[0].range', 'out of range'])
expect_bad('zero range', with_lights('plr0.json', {"point": [{"position": [0, 1, 0], "range": 0}]}), ['lights.point[0].range', 'out of range'])
expect_bad('negative intensity', with_lights('pli.json', {"point": [{"position": [0, 1, 0], "intensity": -1}]}), ['lights.point[0].intensity', 'out of range'])
expect_bad('cone key on a point light', with_lights('plc.json', {"point": [{"position": [0, 1, 0], "outer_angle": 30}]}), ['lights.point[0].outer_angle', 'unknown key'])
expect_bad('spot without direction', with_lights('sp0.json', {"spot": [{"position": [0, 1, 0]}]}), ['lights.spot[0].direction', 'missing'])
expect_bad('spot inner not below outer', with_lights('spio.json', {"spot": [{"position": [0, 1, 0], "direction": [0, -1, 0], "inner_angle": 40, "outer_angle": 30}]}),
           ['lights.spot[0].inner_angle', 'less than outer_angle'])
expect_bad('spot outer over 90', with_lights('spo.json', {"spot": [{"position": [0, 1, 0], "direction": [0, -1, 0], "outer_angle": 120}]}), ['lights.spot[0].outer_angle', 'out of range'])
expect_bad('spot zero direction', with_lights('spd.json', {"spot": [{"position": [0, 1, 0], "direction": [0, 0, 0]}]}), ['lights.spot[0].direction'])
expect_bad('too many lights', with_lights('pl257.json', {"point": [{"position": [0, 1, 0]}] * 257}), ['lights.point', 'at most 256'])
expect_bad('phong in v1', v1_with('v1phong.json', {"material": {"shading": "phong"}}), ['objects[0].material.shading', 'version 2'])
expect_bad('pbr in v1', v1_with('v1pbr.json', {"material": {"shading": "pbr"}}), ['objects[0].material.shading', 'version 2'])
expect_bad('metallic in v1', v1_with('v1metal.json', {"material": {"metallic": 1}}), ['objects[0].material.metallic', 'version 2 key'])
expect_bad('metallic out of range', v2('metal2.json', {"material": {"shading": "pbr", "metallic": 1.5}}), ['objects[0].material.metallic', 'out of range'])
expect_bad('roughness negative', v2('rough.json', {"material": {"shading": "pbr", "roughness": -0.1}}), ['objects[0].material.roughness', 'out of range'])
expect_bad('emissive negative', v2('emis.json', {"material": {"shading": "pbr", "emissive": [1, -1, 0]}}), ['objects[0].material.emissive'])
expect_bad('occlusion_strength out of range', v2('aos.json', {"material": {"shading": "pbr", "occlusion_strength": 2}}),
           ['objects[0].material.occlusion_strength', 'out of range'])
expect_bad('missing metallic-roughness map', v2('mrmiss.json', {"material": {"shading": "pbr", "metallic_roughness_texture": "nope.png"}}),
           ['objects[0].material.metallic_roughness_texture', 'nope.png'])
expect_bad('missing occlusion map', v2('aomiss.json', {"material": {"shading": "pbr", "occlusion_texture": "none.png"}}),
           ['objects[0].material.occlusion_texture', 'none.png'])
expect_bad('emissive map not an image', v2('emmiss.json', {"material": {"shading": "pbr", "emissive_texture": "mrmiss.json"}}),
           ['objects[0].material.emissive_texture'])
expect_bad('normal map in v1', v1_with('v1nm.json', {"material": {"normal_texture": "n.png"}}), ['objects[0].material.normal_texture', 'version 2 key'])
expect_bad('normal map without pbr', v2('nmlam.json', {"material": {"shading": "lambert", "normal_texture": "n.png"}}),
           ['objects[0].material.normal_texture', "needs shading 'pbr'"])
expect_bad('missing normal map', v2('nmmiss.json', {"material": {"shading": "pbr", "normal_texture": "gone.png"}}),
           ['objects[0].material.normal_texture', 'gone.png'])
expect_bad('normal_scale not a number', v2('nms.json', {"material": {"shading": "pbr", "normal_scale": "big"}}), ['objects[0].material.normal_scale'])
expect_bad('v2 key in v1 (primitive)', v1_with('v1prim.json', {"primitive": "lines"}), ['objects[0].primitive', 'version 2'])
expect_bad('unknown primitive', v2('v2prim.json', {"primitive": "quads"}), ['objects[0].primitive', "unknown value 'quads'"])
expect_bad('line_width 0.5', v2('v2lw.json', {"line_width": 0.5}), ['objects[0].line_width', 'out of range'])
expect_bad('point_size 300', v2('v2ps.json', {"point_size": 300}), ['objects[0].point_size', 'out of range'])
expect_bad('line_width not a number', v2('v2lws.json', {"line_width": "thick"}), ['objects[0].line_width', 'number'])
expect_bad('wireframe on lines', v2('v2wl.json', {"primitive": "lines", "wireframe": {}}), ['objects[0].wireframe', "primitive 'triangles'"])
expect_bad('wireframe color of 2', v2('v2wc.json', {"wireframe": {"color": [1, 1]}}), ['objects[0].wireframe.color', '3 numbers'])
expect_bad('wireframe unknown key', v2('v2wk.json', {"wireframe": {"colour": [1, 1, 1]}}), ['objects[0].wireframe.colour', 'unknown key'])
expect_bad('wireframe width 0', v2('v2ww.json', {"wireframe": {"width": 0}}), ['objects[0].wireframe.width', 'out of range'])

# --- meshes
s, m = obj_scene('missing_ref', 'v 0 0 0\n'); os.remove(m)
expect_bad('missing mesh', s, ['missing_ref.obj', 'not found'])
expect_bad('obj index out of range', obj_scene('oor', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n')[0], ['oor.obj', 'out of range'])
expect_bad('obj index 0', obj_scene('zero', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n')[0], ['zero.obj:4', 'index 0'])
expect_bad('obj non-numeric index', obj_scene('nonnum', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 c\n')[0], ['nonnum.obj:4'])
expect_bad('obj non-numeric coordinate', obj_scene('coord', 'v 0 0 0\nv 1 x 0\n')[0], ['coord.obj:2', 'not a number'])
expect_bad('obj truncated face', obj_scene('truncface', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2')[0], ['truncface.obj:4'])
expect_bad('obj line of one vertex', obj_scene('line1', 'v 0 0 0\nl 1\n')[0], ['line1.obj:2', 'at least 2 vertices'])
expect_bad('obj line index out of range', obj_scene('lineoor', 'v 0 0 0\nv 1 0 0\nl 1 3\n')[0], ['lineoor.obj', 'out of range'])
expect_bad('obj point with a normal', obj_scene('pointn', 'v 0 0 0\nvn 0 0 1\np 1//1\n')[0], ['pointn.obj:3', 'no normal'])
expect_bad('obj empty point', obj_scene('point0', 'v 0 0 0\np\n')[0], ['point0.obj:2', 'at least 1 vertex'])
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

# --- options only model files take, given with a scene file (the scene sets these itself)
expect_bad('--size with a scene file', write('modelsize.json', json.dumps(BASE)), ['modelsize.json', 'for model files'], ['--size', '64'])
expect_bad('--shadows with a scene file', write('modelshadows.json', json.dumps(BASE)), ['modelshadows.json', 'for model files'], ['--shadows'])

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
