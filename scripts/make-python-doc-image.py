#!/usr/bin/env python3
"""make-python-doc-image.py OUT.png: docs/python.md's picture, one view of the duck as
softraster's Python module gives it: color, depth, normals (camera space), triangle ids
(each triangle a color of its own) and the point cloud of examples/point_cloud.py drawn back
(eight views) drawn back by softraster.render_model, which reads PLY point clouds.

  PYTHONPATH=build/python /usr/bin/python3 scripts/make-python-doc-image.py docs/images/python_outputs.png
"""
import os, sys, tempfile

import numpy as np
import softraster

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', 'examples'))
from point_cloud import point_cloud, write_ply  # noqa: E402

DUCK = '/usr/share/assimp/models/Collada/duck.dae'
S = 192
shot = softraster.Model(DUCK).render(size=S, view='three-quarter', samples=1, depth=True, normals='camera', ids=True,
                                     background='0.12,0.12,0.14')
empty = shot['object_id'] < 0
d = shot['depth']
near, far = d[~empty].min(), d[~empty].max()
gray = np.where(empty, 0, 255 - 200 * (d - near) / (far - near)).astype(np.uint8)
depth = np.dstack([gray, gray, gray, np.full_like(gray, 255)])
normals = np.dstack([np.where(empty[..., None], 0, (shot['normals'] * 0.5 + 0.5) * 255).astype(np.uint8), np.full((S, S), 255, np.uint8)])
tid = shot['triangle_id'].astype(np.uint32)
hashed = (tid * 2654435761) & 0xffffff  # each triangle its own color
ids = np.dstack([(hashed >> 16) & 255, (hashed >> 8) & 255, hashed & 255, np.full((S, S), 255)]).astype(np.uint8)
ids[empty] = (0, 0, 0, 255)

with tempfile.TemporaryDirectory() as tmp:
    points, colors, _ = point_cloud(DUCK, views=8, size=128)
    write_ply(os.path.join(tmp, 'duck.ply'), points, colors)
    from_render = softraster.render_model(os.path.join(tmp, 'duck.ply'), size=S, background='0.12,0.12,0.14')

gap = np.zeros((S, 4, 4), np.uint8)
gap[..., 3] = 255
row = [shot['color'], gap, depth, gap, normals, gap, ids, gap, from_render]
softraster.write_png(sys.argv[1], np.ascontiguousarray(np.concatenate(row, axis=1)))
print('wrote', sys.argv[1])
