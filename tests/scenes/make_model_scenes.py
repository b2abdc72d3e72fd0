#!/usr/bin/env python3
"""Writes the conformance scenes made from model files (tests/scenes/model_*.json) and the
small glTF, GLB and OBJ+MTL models they draw (tests/scenes/models/). Between them the models
use what the model loader reads: a node tree with instancing (one mesh under several nodes),
several materials, base color factors and textures (external file, embedded in a GLB, a data
URI), vertex colors, a second texture coordinate set, KHR_texture_transform, the three alpha
modes, double-sided materials, non-indexed strips and fans, lines and points. More scenes draw
models of Debian's assimp-testmodels (a test dependency) in place. ctest renders each with
softraster and with Mesa llvmpipe (tests/reference) and compares. Run it again after editing;
the files it writes are committed."""
import base64, json, math, struct

from make_scenes import pattern, png, write

CORPUS = '/usr/share/assimp/models'
LIGHTS = {"ambient": [0.2, 0.2, 0.22],
          "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.8, 0.78, 0.75]},
                          {"direction": [0.6, -0.2, 0.3], "color": [0.25, 0.25, 0.3]}]}


def scene(name, objects, eye, target=(0, 0, 0), fov_y=45, width=160, height=120, near=0.1, far=100, **image):
    s = {"version": 2, "image": {"width": width, "height": height, "background": [0.1, 0.12, 0.16, 1], **image},
         "camera": {"eye": list(eye), "target": list(target), "fov_y": fov_y, "near": near, "far": far},
         "lights": LIGHTS, "objects": objects}
    write(name + '.json', json.dumps(s, indent=1))


class Gltf:
    """A glTF 2.0 asset built in memory: one binary buffer, accessors appended to it."""
    TYPES = {1: 'SCALAR', 2: 'VEC2', 3: 'VEC3', 4: 'VEC4'}
    FORMATS = {5126: 'f', 5125: 'I', 5123: 'H', 5121: 'B'}

    def __init__(self):
        self.bin = bytearray()
        self.j = {"asset": {"version": "2.0", "generator": "softraster make_model_scenes.py"},
                  "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                  "buffers": [], "bufferViews": [], "accessors": []}

    def view(self, data):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.j["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.j["bufferViews"]) - 1

    def accessor(self, rows, ctype=5126, normalized=False):
        comps = len(rows[0]) if isinstance(rows[0], (list, tuple)) else 1
        flat = [v for r in rows for v in (r if comps > 1 else [r])]
        a = {"bufferView": self.view(struct.pack('<%d%s' % (len(flat), self.FORMATS[ctype]), *flat)),
             "componentType": ctype, "count": len(rows), "type": self.TYPES[comps]}
        if normalized:
            a["normalized"] = True
        if comps == 3 and ctype == 5126:  # positions need their bounds
            a["min"] = [min(r[i] for r in rows) for i in range(3)]
            a["max"] = [max(r[i] for r in rows) for i in range(3)]
        self.j["accessors"].append(a)
        return len(self.j["accessors"]) - 1

    def mesh(self, primitives):
        self.j["meshes"].append({"primitives": primitives})
        return len(self.j["meshes"]) - 1

    def material(self, **m):
        self.j["materials"].append(m)
        return len(self.j["materials"]) - 1

    def node(self, root=True, **n):
        self.j["nodes"].append(n)
        index = len(self.j["nodes"]) - 1
        if root:
            self.j["scenes"][0]["nodes"].append(index)
        return index

    def texture(self, png_bytes, embed, sampler=None):
        self.j.setdefault("images", [])
        self.j.setdefault("textures", [])
        if embed == 'buffer':
            self.j["images"].append({"bufferView": self.view(png_bytes), "mimeType": "image/png"})
        elif embed == 'uri':
            self.j["images"].append({"uri": "data:image/png;base64," + base64.b64encode(png_bytes).decode()})
        else:
            self.j["images"].append({"uri": embed})
        t = {"source": len(self.j["images"]) - 1}
        if sampler:
            self.j.setdefault("samplers", []).append(sampler)
            t["sampler"] = len(self.j["samplers"]) - 1
        self.j["textures"].append(t)
        return len(self.j["textures"]) - 1

    def gltf(self):
        self.j["buffers"] = [{"byteLength": len(self.bin),
                              "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()}]
        return json.dumps(self.j, indent=1)

    def glb(self):
        self.j["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(self.j).encode()
        text += b' ' * (-len(text) % 4)
        data = bytes(self.bin) + b'\0' * (-len(self.bin) % 4)
        body = struct.pack('<I4s', len(text), b'JSON') + text + struct.pack('<I4s', len(data), b'BIN\0') + data
        return struct.pack('<4sII', b'glTF', 2, 12 + len(body)) + body


def cube():
    """24 corners (4 per face, each with its face normal and UVs), 36 indices."""
    pos, nrm, uv, idx = [], [], [], []
    for axis in range(3):
        for sign in (1, -1):
            n = [0, 0, 0]
            n[axis] = sign
            u = [0, 0, 0]
            u[(axis + 1) % 3] = 1
            v = [0, 0, 0]
            v[(axis + 2) % 3] = 1
            if sign < 0:
                u, v = v, u
            base = len(pos)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                pos.append([0.5 * (n[i] + a * u[i] + b * v[i]) for i in range(3)])
                nrm.append(n)
                uv.append([(a + 1) / 2, (1 - b) / 2])
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, uv, idx


def quad(size=1.0):
    h = size / 2
    return ([[-h, -h, 0], [h, -h, 0], [h, h, 0], [-h, h, 0]], [[0, 0, 1]] * 4,
            [[0, 1], [1, 1], [1, 0], [0, 0]], [0, 1, 2, 0, 2, 3])


def make_instanced():
    """A node tree: a parent turned and raised, three children placing one cube mesh (two
    of them with the red material, one scaled), a second mesh with two primitives."""
    g = Gltf()
    pos, nrm, uv, idx = cube()
    red = g.material(pbrMetallicRoughness={"baseColorFactor": [0.9, 0.2, 0.15, 1]})
    blue = g.material(pbrMetallicRoughness={"baseColorFactor": [0.2, 0.4, 0.9, 1]})
    attrs = {"POSITION": g.accessor(pos), "NORMAL": g.accessor(nrm)}
    box = g.mesh([{"attributes": attrs, "indices": g.accessor(idx, 5123), "material": red}])
    ppos, pnrm, _, pidx = quad(3.0)
    floor = g.mesh([{"attributes": {"POSITION": g.accessor(ppos), "NORMAL": g.accessor(pnrm)},
                     "indices": g.accessor(pidx, 5125), "material": blue}])
    a = g.node(False, mesh=box, translation=[-1.1, 0, 0])
    b = g.node(False, mesh=box, translation=[1.1, 0, 0], scale=[0.6, 1.4, 0.6])
    s = math.sin(math.radians(20)) ; c = math.cos(math.radians(20))
    c_ = g.node(False, mesh=box, matrix=[c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0.2, -1.2, 1])
    f = g.node(False, mesh=floor, rotation=[-math.sin(math.pi / 4), 0, 0, math.cos(math.pi / 4)], translation=[0, -0.7, 0])
    g.node(True, children=[a, b, c_, f], rotation=[0, math.sin(math.radians(15)), 0, math.cos(math.radians(15))],
           translation=[0, 0.2, 0])
    write('models/instanced.gltf', g.gltf())


def make_textured_glb():
    """A GLB with its texture in the binary chunk, clamped, and KHR_texture_transform."""
    g = Gltf()
    g.j["extensionsUsed"] = ["KHR_texture_transform"]
    tex = g.texture(png(16, 16, pattern(16, 16), 3), 'buffer', {"wrapS": 33071, "wrapT": 33071})
    plain = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex}})
    moved = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex, "extensions": {
        "KHR_texture_transform": {"offset": [0.25, -0.1], "rotation": 0.4, "scale": [0.7, 1.3]}}}})
    pos, nrm, uv, idx = quad(1.6)
    attrs = {"POSITION": g.accessor(pos), "NORMAL": g.accessor(nrm), "TEXCOORD_0": g.accessor(uv)}
    left = g.mesh([{"attributes": attrs, "indices": g.accessor(idx, 5123), "material": plain}])
    right = g.mesh([{"attributes": attrs, "indices": g.accessor(idx, 5123), "material": moved}])
    g.node(mesh=left, translation=[-0.9, 0, 0])
    g.node(mesh=right, translation=[0.9, 0, 0])
    write('models/textured.glb', g.glb())


def make_alpha_modes():
    """OPAQUE, MASK (cutoff 0.4, alpha from a texture in a data URI) and BLEND quads in
    front of a backdrop; the MASK quad is double-sided and seen from behind."""
    g = Gltf()
    w = h = 8
    rgba = []
    for y in range(h):
        for x in range(w):
            rgba += [230, 200, 60, int(255 * ((x + y) % 8) / 7)]
    tex = g.texture(png(w, h, rgba), 'uri', {"magFilter": 9728, "minFilter": 9728})
    backdrop = g.material(pbrMetallicRoughness={"baseColorFactor": [0.3, 0.8, 0.4, 1]})
    opaque = g.material(pbrMetallicRoughness={"baseColorFactor": [0.8, 0.3, 0.3, 0.5]}, alphaMode="OPAQUE")
    mask = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex}}, alphaMode="MASK", alphaCutoff=0.4,
                      doubleSided=True)
    blend = g.material(pbrMetallicRoughness={"baseColorFactor": [0.3, 0.4, 1.0, 0.45]}, alphaMode="BLEND")
    pos, nrm, uv, idx = quad(1.0)
    attrs = {"POSITION": g.accessor(pos), "NORMAL": g.accessor(nrm), "TEXCOORD_0": g.accessor(uv)}
    ind = g.accessor(idx, 5121)
    for mat, x, z, turn in ((opaque, -1.1, 0, 0), (mask, 0, 0, 180), (blend, 1.1, 0.3, 0)):
        m = g.mesh([{"attributes": attrs, "indices": ind, "material": mat}])
        g.node(mesh=m, translation=[x, 0, z], rotation=[0, math.sin(math.radians(turn / 2)), 0, math.cos(math.radians(turn / 2))])
    bpos, bnrm, _, bidx = quad(4.0)
    back = g.mesh([{"attributes": {"POSITION": g.accessor(bpos), "NORMAL": g.accessor(bnrm)},
                    "indices": g.accessor(bidx, 5123), "material": backdrop}])
    g.node(mesh=back, translation=[0, 0, -0.8])
    write('models/alpha_modes.gltf', g.gltf())


def make_strips_fans():
    """Non-indexed triangle strip and fan (modes 5 and 6) with vertex colors as normalized
    bytes and as floats, a second texture coordinate set read by the texture (texCoord 1)."""
    g = Gltf()
    n = 8
    strip_pos = [[-1.6 + 0.4 * (i // 2), 0.5 * (i % 2) - 0.25 + 0.08 * math.sin(i), 0] for i in range(n)]
    strip_col = [[40 + 25 * i, 255 - 25 * i, 90 + (i % 2) * 120, 255] for i in range(n)]
    fan_pos = [[1.0, 0, 0]] + [[1.0 + 0.8 * math.cos(a), 0.8 * math.sin(a), 0]
                               for a in (math.radians(20 + 40 * k) for k in range(8))]
    fan_col = [[1, 1, 1, 1]] + [[0.5 + 0.5 * math.cos(k), 0.5 + 0.5 * math.sin(k), 0.3, 1] for k in range(8)]
    tex = g.texture(png(16, 16, pattern(16, 16), 3), 'uri')
    textured = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex, "texCoord": 1}}, doubleSided=True)
    plain = g.material(doubleSided=True)
    up = [[0, 0, 1]] * n
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(strip_pos), "NORMAL": g.accessor(up),
                                        "COLOR_0": g.accessor(strip_col, 5121, normalized=True)},
                         "mode": 5, "material": plain}]))
    uv0 = [[0, 0]] * len(fan_pos)
    uv1 = [[(p[0] - 0.2) / 1.6, (0.8 - p[1]) / 1.6] for p in fan_pos]
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(fan_pos), "NORMAL": g.accessor([[0, 0, 1]] * len(fan_pos)),
                                        "COLOR_0": g.accessor(fan_col), "TEXCOORD_0": g.accessor(uv0),
                                        "TEXCOORD_1": g.accessor(uv1)},
                         "mode": 6, "material": textured}]))
    write('models/strips_fans.gltf', g.gltf())


def make_lines_points():
    """Line segments, a line strip and points (modes 1, 3, 0)."""
    g = Gltf()
    yellow = g.material(pbrMetallicRoughness={"baseColorFactor": [1, 0.85, 0.2, 1]})
    cyan = g.material(pbrMetallicRoughness={"baseColorFactor": [0.2, 0.9, 1, 1]})
    segs = [[-1.5 + 0.3 * k, -0.8, 0] for k in range(0, 10)] + [[-1.5 + 0.3 * k + 0.2, 0.8, 0] for k in range(0, 10)]
    seg_idx = [v for k in range(10) for v in (k, 10 + k)]
    spiral = [[0.6 * math.cos(t) * (t / 12), 0.6 * math.sin(t) * (t / 12), 0] for t in [0.3 * k for k in range(40)]]
    grid = [[-1.4 + 0.2 * i, -1.0 + 0.2 * j, -0.2] for i in range(15) for j in range(11)]
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(segs)}, "indices": g.accessor(seg_idx, 5123),
                         "mode": 1, "material": yellow}]))
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(spiral)}, "mode": 3, "material": cyan}]))
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(grid)}, "mode": 0, "material": yellow}]))
    write('models/lines_points.gltf', g.gltf())


def make_obj_mtl():
    """OBJ with an MTL file: a textured material (map_Kd), a plain one (Kd) and a
    translucent one (d 0.5)."""
    write('models/obj_texture.png', png(16, 16, pattern(16, 16), 3))
    write('models/materials.mtl', '\n'.join([
        'newmtl textured', 'Kd 1 1 1', 'map_Kd obj_texture.png', '',
        'newmtl orange', 'Kd 0.95 0.55 0.15', '',
        'newmtl glass', 'Kd 0.3 0.6 1.0', 'd 0.5', '']))
    lines = ['mtllib materials.mtl', 'vn 0 0 1', 'vt 0 0', 'vt 1 0', 'vt 1 1', 'vt 0 1']
    v = 1
    for name, x0, z in (('textured', -1.8, 0), ('orange', -0.4, 0), ('glass', 0.4, 0.3)):
        lines += ['v %g -0.6 %g' % (x0, z), 'v %g -0.6 %g' % (x0 + 1.4, z), 'v %g 0.6 %g' % (x0 + 1.4, z),
                  'v %g 0.6 %g' % (x0, z), 'usemtl ' + name,
                  'f %d/1/1 %d/2/1 %d/3/1 %d/4/1' % (v, v + 1, v + 2, v + 3)]
        v += 4
    write('models/materials.obj', '\n'.join(lines) + '\n')


def make_pbr_lights():
    """glTF metallic-roughness materials (factors, a metallic-roughness map, an occlusion map
    and an emissive map) on a floor and two cubes, and
    KHR_lights_punctual lights: a directional, a point with a range and a spot, placed by
    nodes (the spot's node turned to point down)."""
    g = Gltf()
    mr = png(8, 8, [c for y in range(8) for x in range(8) for c in (0, 60 + 25 * x, 255 if y < 4 else 0)], 3)
    ao = png(8, 8, [c for y in range(8) for x in range(8) for c in (255 if 1 <= x <= 6 and 1 <= y <= 6 else 90, 0, 0)], 3)
    glow = png(8, 8, [c for y in range(8) for x in range(8) for c in ((255, 140, 20) if (x + y) % 5 == 0 else (0, 0, 0))], 3)
    floor = g.material(pbrMetallicRoughness={"baseColorFactor": [0.7, 0.7, 0.75, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6,
                                             "metallicRoughnessTexture": {"index": g.texture(mr, 'uri')}},
                       occlusionTexture={"index": g.texture(ao, 'uri'), "strength": 0.7})
    gold = g.material(pbrMetallicRoughness={"baseColorFactor": [1.0, 0.78, 0.34, 1], "metallicFactor": 1.0, "roughnessFactor": 0.3})
    lamp = g.material(pbrMetallicRoughness={"baseColorFactor": [0.2, 0.2, 0.2, 1], "metallicFactor": 0.0},
                      emissiveFactor=[1, 0.9, 0.8], emissiveTexture={"index": g.texture(glow, 'uri')})
    pos, nrm, uv, idx = cube()
    cube_prim = {"POSITION": g.accessor(pos), "NORMAL": g.accessor(nrm), "TEXCOORD_0": g.accessor(uv)}
    cube_idx = g.accessor(idx, 5123)
    fp = [[-2, 0, 2], [2, 0, 2], [2, 0, -2], [-2, 0, -2]]
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(fp), "NORMAL": g.accessor([[0, 1, 0]] * 4),
                                        "TEXCOORD_0": g.accessor([[0, 2], [2, 2], [2, 0], [0, 0]])},
                         "indices": g.accessor([0, 1, 2, 0, 2, 3], 5123), "material": floor}]))
    g.node(mesh=g.mesh([{"attributes": cube_prim, "indices": cube_idx, "material": gold}]), translation=[-0.7, 0.5, 0],
           rotation=[0, 0.2588, 0, 0.9659])
    g.node(mesh=g.mesh([{"attributes": cube_prim, "indices": cube_idx, "material": lamp}]), translation=[0.8, 0.4, -0.3],
           scale=[0.8, 0.8, 0.8])
    g.j["extensionsUsed"] = ["KHR_lights_punctual"]
    g.j["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "color": [1, 0.95, 0.9], "intensity": 0.8},
        {"type": "point", "color": [0.4, 0.6, 1.0], "intensity": 6, "range": 6},
        {"type": "spot", "color": [1, 0.9, 0.7], "intensity": 12, "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}}]}}
    # A light shines along its node's -z: turned -90 degrees about x, the spot looks down.
    g.node(extensions={"KHR_lights_punctual": {"light": 0}}, rotation=[-0.3827, 0.3, 0, 0.8739])
    g.node(extensions={"KHR_lights_punctual": {"light": 1}}, translation=[1.5, 1.2, 1.0])
    g.node(extensions={"KHR_lights_punctual": {"light": 2}}, translation=[-0.5, 3.0, 0.5], rotation=[-0.7071, 0, 0, 0.7071])
    write('models/pbr_lights.gltf', g.gltf())


def make_normal_mapped():
    """glTF normal maps (normalTexture with a scale): a floor without TANGENT (softraster
    generates its tangents) and a cube whose TANGENT attribute runs along v instead of u,
    so the file's tangents, not generated ones, decide how its bumps are lit."""
    from make_normal_map_scenes import bump
    g = Gltf()
    bumps = png(128, 128, [c for y in range(128) for x in range(128) for c in bump(x, y)[:3]], 3)
    nmap = g.texture(bumps, 'uri')
    floor = g.material(pbrMetallicRoughness={"baseColorFactor": [0.75, 0.72, 0.7, 1], "metallicFactor": 0.0, "roughnessFactor": 0.6},
                       normalTexture={"index": nmap})
    box = g.material(pbrMetallicRoughness={"baseColorFactor": [0.4, 0.6, 0.85, 1], "metallicFactor": 0.0, "roughnessFactor": 0.55},
                     normalTexture={"index": nmap, "scale": 0.7})
    fp = [[-2, 0, 2], [2, 0, 2], [2, 0, -2], [-2, 0, -2]]
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(fp), "NORMAL": g.accessor([[0, 1, 0]] * 4),
                                        "TEXCOORD_0": g.accessor([[0, 2], [2, 2], [2, 0], [0, 0]])},
                         "indices": g.accessor([0, 1, 2, 0, 2, 3], 5123), "material": floor}]))
    pos, nrm, uv, idx = cube()
    # Each face's v axis (the corner order of cube() runs u first, then v), w = +1.
    tangents = []
    for f in range(6):
        p0, p3 = pos[4 * f], pos[4 * f + 3]
        v = [p3[i] - p0[i] for i in range(3)]
        tangents += [v + [1.0]] * 4
    g.node(mesh=g.mesh([{"attributes": {"POSITION": g.accessor(pos), "NORMAL": g.accessor(nrm), "TEXCOORD_0": g.accessor(uv),
                                        "TANGENT": g.accessor(tangents)},
                         "indices": g.accessor(idx, 5123), "material": box}]), translation=[0, 0.6, 0],
           rotation=[0, 0.3827, 0, 0.9239])
    write('models/normal_mapped.gltf', g.gltf())


def main():
    make_normal_mapped()
    make_pbr_lights()
    make_instanced()
    make_textured_glb()
    make_alpha_modes()
    make_strips_fans()
    make_lines_points()
    make_obj_mtl()
    scene('model_instanced', [{"model": "models/instanced.gltf"}], eye=(2.5, 2.2, 4.2))
    scene('model_instanced_transformed', [{"model": "models/instanced.gltf", "material": {"shading": "normals"},
                                           "transform": {"translate": [0.3, -0.2, 0], "rotate": [0, -40, 10], "scale": 0.8}},
                                          {"model": "models/instanced.gltf", "cull": "none",
                                           "transform": {"translate": [0, 0, -3.5]}}], eye=(0, 1.5, 5.5))
    scene('model_glb_texture_transform', [{"model": "models/textured.glb"}], eye=(0, 0, 3.2))
    scene('model_alpha_modes', [{"model": "models/alpha_modes.gltf"}], eye=(0.4, 0.3, 3.4))
    scene('model_strips_fans_colors', [{"model": "models/strips_fans.gltf"}], eye=(0, 0, 3.5), target=(-0.1, 0, 0))
    scene('model_lines_points', [{"model": "models/lines_points.gltf"}], eye=(0, 0, 3.5))
    scene('model_obj_mtl', [{"model": "models/materials.obj"}], eye=(0.3, 0.4, 3.6))
    # (A model object is lit by the scene's lights; `render MODEL` uses the file's.)
    scene('model_pbr_maps', [{"model": "models/pbr_lights.gltf"}], eye=(0.5, 2.4, 3.6), target=(0, 0.3, 0))
    scene('model_normal_maps', [{"model": "models/normal_mapped.gltf"}], eye=(1.2, 1.6, 3.0), target=(0, 0.3, 0),
          width=192, height=128)
    # Models of Debian's assimp-testmodels, in place.
    scene('model_box_textured', [{"model": CORPUS + "/glTF2/BoxTextured-glTF/BoxTextured.gltf"}], eye=(1.6, 1.3, 2.2))
    scene('model_engine_glb', [{"model": CORPUS + "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"}],
          eye=(250, 200, 420), target=(0, 0, 0), near=10, far=2000, width=192, height=144)
    scene('model_texture_transform_test', [{"model": CORPUS + "/glTF2/textureTransform/TextureTransformTest.gltf"}],
          eye=(0, 0, 3.2))
    scene('model_spider_obj', [{"model": CORPUS + "/OBJ/spider.obj"}], eye=(60, 50, 90), target=(0, 0, 0), near=1,
          far=500)
    scene('model_cube_vertex_colors_obj', [{"model": CORPUS + "/OBJ/cube_with_vertexcolors.obj", "cull": "none"}],
          eye=(2.2, 1.8, 3.0))


if __name__ == '__main__':
    main()
