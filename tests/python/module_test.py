#!/usr/bin/env python3
"""module_test.py SOFTRASTER PYTHON_DIR CORPUS WORKDIR: the Python module against the command
line (the same pictures, byte for byte), depth and cameras, errors, and renders from several
Python threads at once."""
import json, os, shutil, subprocess, sys, threading

exe, python_dir, corpus, work = sys.argv[1:5]
sys.path.insert(0, python_dir)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from checks import check, failures, finish  # noqa: E402
import numpy as np  # noqa: E402
import softraster  # noqa: E402
from imgdiff import read_png  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
DUCK = os.path.join(corpus, 'Collada', 'duck.dae')



def cli_picture(*args):
    out = os.path.join(work, 'cli.png')
    r = subprocess.run([exe, 'render', *args, '-o', out], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    w, h, ch, pixels = read_png(out)
    return np.frombuffer(bytes(pixels), np.uint8).reshape(h, w, ch)


# A plane at z = -5 seen by a camera at the origin looking down -z (fov 60, 64 x 48).
scene = {"version": 1, "image": {"width": 64, "height": 48, "background": [0, 0, 0, 1]},
         "camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "fov_y": 60, "near": 0.5, "far": 50},
         "objects": [{"builtin": {"type": "plane", "size": 2}, "transform": {"translate": [0, 0, -5], "rotate": [90, 0, 0]},
                      "material": {"shading": "unlit", "color": [1, 0.5, 0.25, 1]}}]}
path = os.path.join(work, 'plane.json')
json.dump(scene, open(path, 'w'))
want = cli_picture(path)
for given, what in [(scene, 'dict'), (json.dumps(scene), 'JSON string'), (path, 'path'), (__import__('pathlib').Path(path), 'Path')]:
    got = softraster.render(given)
    check('render(%s)' % what, got.dtype == np.uint8 and got.shape == (48, 64, 4) and np.array_equal(got, want), got.shape)

# Depth: 5 on the plane, inf around it; the camera's intrinsics and pose.
out = softraster.render(scene, depth=True)
d, color = out['depth'], out['color']
on = color[:, :, 0] > 0
check('depth on the plane', on.any() and np.allclose(d[on], 5.0, rtol=1e-4), d[on][:5] if on.any() else 'nothing drawn')
check('depth where nothing is drawn', (~on).any() and np.isinf(d[~on]).all())
check('window z where nothing is drawn', np.all(out['window_z'][~on] == 1.0))
cam = out['camera']
f = 24 / np.tan(np.radians(30))
check('K', np.allclose(cam['K'], [[f, 0, 32], [0, f, 24], [0, 0, 1]]), cam['K'])
check('world_to_camera (OpenCV)', np.allclose(cam['world_to_camera'], np.diag([1, -1, -1, 1])), cam['world_to_camera'])
check('world_to_camera_gl', np.allclose(cam['world_to_camera_gl'], np.eye(4)), cam['world_to_camera_gl'])
# Re-projection: each drawn pixel's point, from depth and K, lies on the plane (world z = -5)
# and inside its square (|x|, |y| <= 1).
v, u = np.nonzero(on)
rays = np.linalg.inv(cam['K']) @ np.stack([u + 0.5, v + 0.5, np.ones_like(u, dtype=float)])
points_cv = rays * d[v, u]
world = np.linalg.inv(cam['world_to_camera']) @ np.vstack([points_cv, np.ones(len(u))])
check('re-projected points on the plane', np.allclose(world[2], -5, atol=1e-3) and np.abs(world[:2]).max() <= 1.02, world[:, :3])

# Model files: the same picture as `softraster render MODEL`; a Model drawn from many cameras.
got = softraster.render_model(DUCK, size=(80, 60), view='front', samples=1)
check('render_model', np.array_equal(got, cli_picture(DUCK, '--size', '80x60', '--view', 'front', '--samples', '1')))
model = softraster.Model(DUCK)
for view in ['left', 'top']:
    r = model.render(size=40, view=view, depth=True)
    check('Model.render %s' % view, np.array_equal(r['color'], cli_picture(DUCK, '--size', '40', '--view', view))
          and r['depth'].shape == (40, 40) and np.isfinite(r['depth']).any() and r['camera']['K'].shape == (3, 3))
check('Model.objects', model.objects >= 1 and model.path == DUCK)

# The data-set outputs of one view of the duck, checked against its own mesh: each drawn
# pixel's depth, back-projected through K and world_to_camera, lies on the triangle that
# triangle_id names, within one pixel's footprint (depth / f); the normals are that
# triangle's, unit length, and agree with the 8-bit normals shading; the linear color is the
# sRGB picture decoded.
shot = model.render(size=96, view='iso', samples=1, depth=True, normals='world', ids=True, linear=True)
mesh = model.mesh(0)
oid, tid, d, K = shot['object_id'], shot['triangle_id'], shot['depth'], shot['camera']['K']
v, u = np.nonzero(oid >= 0)
check('ids cover the depth', len(u) > 1000 and np.isfinite(d[v, u]).all() and np.isinf(d[oid < 0]).mean() > 0.99, len(u))
check('object ids', set(np.unique(oid)) <= set([-1] + list(range(model.objects))) and (tid[oid < 0] == -1).all())
rays = np.linalg.inv(K) @ np.stack([u + 0.5, v + 0.5, np.ones(len(u))])
points = (np.linalg.inv(shot['camera']['world_to_camera']) @ np.vstack([rays * d[v, u], np.ones(len(u))]))[:3].T
obj0 = oid[v, u] == 0
tri = mesh['positions'][mesh['triangles'][tid[v, u][obj0]]].astype(np.float64)  # (n, 3 corners, xyz)
face = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
face /= np.linalg.norm(face, axis=1)[:, None]
off_plane = np.abs(np.einsum('ij,ij->i', points[obj0] - tri[:, 0], face))
footprint = d[v, u][obj0] / K[0, 0]
check('back-projected points on their triangles', (off_plane <= footprint).all(), (off_plane / footprint).max())
n = shot['normals']
check('normals unit where drawn, 0 elsewhere', np.allclose(np.linalg.norm(n[v, u], axis=1), 1, atol=1e-5) and not n[oid < 0].any())
corner_normals = mesh['normals'][mesh['triangles'][tid[v, u][obj0]]]
check('normals within their corners\' cone', (np.einsum('ij,ikj->ik', n[v, u][obj0], corner_normals).max(axis=1) > 0.5).all())
linear_model = softraster.Model(DUCK, color_space='linear')  # (the normals shading's 0.5 n + 0.5 stored as is)
shaded = linear_model.render(size=96, view='iso', samples=1, shading='normals')['color'][v, u, :3] / 255.0 * 2 - 1
check('normals agree with the normals shading', np.abs(shaded - n[v, u]).max() < 0.02, np.abs(shaded - n[v, u]).max())
cam = shot['camera']['world_to_camera'][:3, :3]
in_camera = model.render(size=96, view='iso', samples=1, normals='camera')['normals']
check('camera-space normals', np.allclose(in_camera[v, u], n[v, u] @ cam.T, atol=1e-5))
srgb = shot['color'][..., :3] / 255.0
check('linear color', np.allclose(shot['linear'][..., :3], np.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4), atol=1e-6)
      and np.allclose(shot['linear'][..., 3], shot['color'][..., 3] / 255.0))
# Two objects in a scene: each pixel's object id is the one its color says.
two = dict(scene, objects=[dict(scene['objects'][0], transform={"translate": [x, 0, -5], "rotate": [90, 0, 0], "scale": [0.5, 0.5, 0.5]},
                                material={"shading": "unlit", "color": c}) for x, c in [(-1, [1, 0, 0, 1]), (1, [0, 1, 0, 1])]])
r = softraster.render(two, ids=True)
red, green = r['color'][..., 0] > 128, r['color'][..., 1] > 128
check('object ids of a scene', red.any() and green.any() and (r['object_id'][red] == 0).all() and (r['object_id'][green] == 1).all()
      and (r['object_id'][~(red | green)] == -1).all() and set(np.unique(r['triangle_id'][red])) <= {0, 1})

# docs/python.md's example (examples/point_cloud.py), end to end: every point it makes lies on
# the triangle its ids name, within one pixel's footprint at that distance.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'examples'))
from point_cloud import point_cloud  # noqa: E402
points, colors, ids = point_cloud(DUCK, views=4, size=64)
meshes = [model.mesh(i) for i in range(model.objects)]
tri = np.stack([meshes[o]['positions'][meshes[o]['triangles'][t]] for o, t in ids]).astype(np.float64)
face = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
face /= np.linalg.norm(face, axis=1)[:, None]
distance = np.abs(np.einsum('ij,ij->i', points - tri[:, 0], face))
radius = np.linalg.norm(meshes[0]['positions'] - meshes[0]['positions'].mean(axis=0), axis=1).max()
check('point cloud example', len(points) > 4 * 500 and colors.dtype == np.uint8 and (distance <= 0.05 * radius).all()
      and np.median(distance) < 0.002 * radius, (len(points), distance.max() / radius))

# write_png: the picture back as read_png reads it.
png_path = os.path.join(work, 'written.png')
softraster.write_png(png_path, shot['color'])
w, h, ch, pixels = read_png(png_path)
check('write_png', (w, h, ch) == (96, 96, 4) and np.array_equal(np.frombuffer(bytes(pixels), np.uint8).reshape(h, w, 4), shot['color']))

# Many views, as `softraster views` draws them: the same pictures and cameras.
out = os.path.join(work, 'views')
subprocess.run([exe, 'views', DUCK, '--out', out, '--count', '3', '--size', '40', '--layout', 'ring'], check=True, capture_output=True)
cams = json.load(open(os.path.join(out, 'cameras.json')))
shots = softraster.views(model, count=3, layout='ring', size=40)
for shot, v in zip(shots, cams['views']):
    w, h, ch, pixels = read_png(os.path.join(out, v['color']))
    check('views picture %s' % v['color'], np.array_equal(shot['color'], np.frombuffer(bytes(pixels), np.uint8).reshape(h, w, ch)))
    check('views camera %s' % v['color'], np.allclose(shot['camera']['K'], v['K']) and np.allclose(shot['camera']['world_to_camera'], v['world_to_camera'])
          and np.allclose(shot['direction'], v['to_eye']))
check('view_directions', len(softraster.view_directions(5, layout='random', seed=3)) == 5)

# Errors: ValueError with the command line's one line, FileNotFoundError.
for call, kind, text in [(lambda: softraster.render({"version": 3}), ValueError, 'version'),
                         (lambda: softraster.render('{"version": 1,'), ValueError, 'malformed JSON'),
                         (lambda: softraster.render(os.path.join(work, 'missing.json')), FileNotFoundError, 'missing.json'),
                         (lambda: softraster.render_model(os.path.join(work, 'missing.glb')), FileNotFoundError, 'missing.glb'),
                         (lambda: softraster.render_model(DUCK, view='sideways'), ValueError, 'sideways'),
                         (lambda: softraster.render_model(DUCK, samples=3), ValueError, 'samples'),
                         (lambda: softraster.render_model(DUCK, size=0), ValueError, 'size'),
                         (lambda: softraster.Model(path), ValueError, 'plane.json'),
                         (lambda: softraster.view_directions(3, layout='cube'), ValueError, 'cube'),
                         (lambda: model.render(direction=(0, 0, 0)), ValueError, 'direction'),
                         (lambda: model.render(normals='object'), ValueError, 'normals'),
                         (lambda: model.mesh(model.objects), IndexError, 'object'),
                         (lambda: softraster.write_png(png_path, np.zeros((4, 4, 3), np.uint8)), ValueError, 'H x W x 4'),
                         (lambda: softraster.write_png(os.path.join(work, 'no', 'x.png'), shot['color']), OSError, 'x.png'),
                         (lambda: softraster.views(model, count=0), ValueError, 'count'),
                         (lambda: model.render(size=(10,)), ValueError, 'size'),
                         (lambda: model.render(threads=-1), ValueError, 'threads')]:
    try:
        call()
        failures.append('no %s for %s' % (kind.__name__, text))
    except kind as e:
        check('%s message' % kind.__name__, text in str(e) and '\n' not in str(e), str(e))
    except Exception as e:  # noqa: BLE001
        failures.append('%s for %s, not %s: %s' % (type(e).__name__, text, kind.__name__, e))

# Several Python threads at once (the GIL released while drawing): each gets its own picture.
views = ['front', 'back', 'left', 'right', 'top', 'iso']
alone = {v: model.render(size=48, view=v, threads=1)['color'] for v in views}
together = {}
workers = [threading.Thread(target=lambda v=v: together.__setitem__(v, model.render(size=48, view=v, threads=1)['color'])) for v in views]
for t in workers:
    t.start()
for t in workers:
    t.join()
check('threads', all(np.array_equal(alone[v], together.get(v)) for v in views))

# help() answers: the options and conventions are documented.
check('docstrings', 'view:' in softraster.render_model.__doc__ and 'world_to_camera' in softraster.__doc__
      and 'depth' in softraster.Model.render.__doc__)

finish()
