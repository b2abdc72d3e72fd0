#!/usr/bin/env python3
"""Writes the many-draws bench scenes: thousands of small objects at 1920x1080, one draw and
one material each, seen in perspective from above a grid. What they measure is the cost per
draw (front end, binning, the tiles' command lists), not per pixel.

  bench/scenes/make_bench_many_draws.py > bench/scenes/bench_many_draws.json
      20,000 cubes (12 triangles each), each covering about a hundred pixels
  bench/scenes/make_bench_many_draws.py --shape sphere > bench/scenes/bench_many_spheres.json
      20,000 small spheres (8 rings, 16 segments: 288 triangles each; 5.8 million in all),
      lit with Blinn-Phong: the per-draw costs with real vertex work behind each draw

--objects N draws N objects (a grid of 2:1, 20,000 by default); --seed picks the colors and
turns."""
import argparse, json, math, random

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument('--shape', choices=['cube', 'sphere'], default='cube')
ap.add_argument('--objects', type=int, default=20000)
ap.add_argument('--seed', type=int, default=20000)
a = ap.parse_args()

rows = max(1, round(math.sqrt(a.objects / 2)))
columns = math.ceil(a.objects / rows)
rng = random.Random(a.seed)
objects = []
for r in range(rows):
    for c in range(columns):
        if len(objects) == a.objects:
            break
        x = (c - (columns - 1) / 2) * 0.6
        z = -(r * 0.6) - 4
        color = [round(0.35 + 0.6 * c / columns, 3), round(0.35 + 0.6 * r / rows, 3), round(rng.uniform(0.3, 0.9), 3), 1]
        turn = round(rng.uniform(0, 90), 1)
        if a.shape == 'cube':
            mesh = {"type": "cube", "size": 0.36}
            material = {"shading": "lambert", "color": color}
        else:
            mesh = {"type": "uv_sphere", "radius": 0.22, "rings": 8, "segments": 16}
            material = {"shading": "blinn_phong", "color": color, "specular": [0.3, 0.3, 0.3], "shininess": 32}
        objects.append({
            "builtin": mesh,
            "transform": {"translate": [round(x, 3), 0, round(z, 3)], "rotate": [0, turn, 0]},
            "material": material,
        })
scene = {
    "version": 1,
    "image": {"width": 1920, "height": 1080, "background": [0.15, 0.15, 0.18, 1]},
    "camera": {"eye": [0, 34, 12], "target": [0, 0, -34], "fov_y": 55, "near": 1, "far": 200},
    "lights": {"ambient": [0.12, 0.12, 0.14],
               "directional": [{"direction": [-0.4, -0.7, -0.6], "color": [0.85, 0.82, 0.78]},
                               {"direction": [0.8, -0.2, 0.3], "color": [0.25, 0.3, 0.4]}]},
}
# One object per line: a readable diff, a tenth of the indented size.
head = json.dumps(scene, indent=1)[:-2]
print(head + ',\n "objects": [\n' + ',\n'.join('  ' + json.dumps(o) for o in objects) + '\n ]\n}')
