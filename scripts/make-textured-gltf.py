#!/usr/bin/env python3
"""make-textured-gltf.py OUT.gltf [--segments N --rings M]: a textured glTF 2.0 model for the
Python benchmarks (scripts/bench-python.py): a torus of 2 N M triangles (400 x 160 = 128,000
by default) with normals and uv, its base color the bench's tile texture
(bench/scenes/textures/tiles_1024.png, copied beside it) in sRGB as glTF has it. Writes
OUT.gltf, OUT.bin and the texture."""
import argparse, json, math, os, shutil, struct

parser = argparse.ArgumentParser()
parser.add_argument('out')
parser.add_argument('--segments', type=int, default=400)
parser.add_argument('--rings', type=int, default=160)
args = parser.parse_args()
N, M, R, r = args.segments, args.rings, 1.0, 0.4

positions, normals, uvs = [], [], []
for i in range(N + 1):  # around the big circle; the seam's vertices repeat for their uv
    a = 2 * math.pi * i / N
    for j in range(M + 1):
        b = 2 * math.pi * j / M
        n = (math.cos(a) * math.cos(b), math.sin(b), math.sin(a) * math.cos(b))
        positions += [R * math.cos(a) + r * n[0], r * n[1], R * math.sin(a) + r * n[2]]
        normals += list(n)
        uvs += [4.0 * i / N, 1.0 * j / M]
indices = []
for i in range(N):
    for j in range(M):
        k0, k1 = i * (M + 1) + j, (i + 1) * (M + 1) + j
        indices += [k0, k0 + 1, k1, k1, k0 + 1, k1 + 1]  # counter-clockwise seen from outside

blobs = [struct.pack('<%df' % len(positions), *positions), struct.pack('<%df' % len(normals), *normals),
         struct.pack('<%df' % len(uvs), *uvs), struct.pack('<%dI' % len(indices), *indices)]
base = os.path.splitext(args.out)[0]
with open(base + '.bin', 'wb') as f:
    f.write(b''.join(blobs))
offsets = [sum(len(b) for b in blobs[:k]) for k in range(4)]
count = (N + 1) * (M + 1)
xs, ys, zs = positions[0::3], positions[1::3], positions[2::3]
texture = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'bench', 'scenes', 'textures', 'tiles_1024.png')
shutil.copy(texture, os.path.join(os.path.dirname(os.path.abspath(args.out)), 'tiles_1024.png'))
gltf = {
    'asset': {'version': '2.0', 'generator': 'softraster make-textured-gltf.py'},
    'scene': 0, 'scenes': [{'nodes': [0]}], 'nodes': [{'mesh': 0}],
    'meshes': [{'primitives': [{'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3, 'material': 0}]}],
    'materials': [{'pbrMetallicRoughness': {'baseColorTexture': {'index': 0}, 'metallicFactor': 0.0, 'roughnessFactor': 0.6}}],
    'textures': [{'source': 0, 'sampler': 0}], 'images': [{'uri': 'tiles_1024.png'}],
    'samplers': [{'magFilter': 9729, 'minFilter': 9987, 'wrapS': 10497, 'wrapT': 10497}],
    'buffers': [{'uri': os.path.basename(base) + '.bin', 'byteLength': offsets[3] + len(blobs[3])}],
    'bufferViews': [{'buffer': 0, 'byteOffset': o, 'byteLength': len(b), 'target': 34963 if k == 3 else 34962}
                    for k, (o, b) in enumerate(zip(offsets, blobs))],
    'accessors': [{'bufferView': 0, 'componentType': 5126, 'count': count, 'type': 'VEC3',
                   'min': [min(xs), min(ys), min(zs)], 'max': [max(xs), max(ys), max(zs)]},
                  {'bufferView': 1, 'componentType': 5126, 'count': count, 'type': 'VEC3'},
                  {'bufferView': 2, 'componentType': 5126, 'count': count, 'type': 'VEC2'},
                  {'bufferView': 3, 'componentType': 5125, 'count': len(indices), 'type': 'SCALAR'}],
}
with open(args.out, 'w') as f:
    json.dump(gltf, f)
print('%s: %d triangles' % (args.out, len(indices) // 3))
