#!/usr/bin/env python3
"""Writes bench_many_draws.json: 20,000 small cubes at 1920x1080, one draw and one material
each, seen in perspective from above a 200 x 100 grid. What it measures is the cost per
draw (front end, binning, the tiles' command lists), not per pixel: each cube covers
about a hundred pixels.

  bench/scenes/make_bench_many_draws.py > bench/scenes/bench_many_draws.json"""
import json, math, random

COLUMNS, ROWS = 200, 100
rng = random.Random(20000)
objects = []
for r in range(ROWS):
    for c in range(COLUMNS):
        x = (c - (COLUMNS - 1) / 2) * 0.6
        z = -(r * 0.6) - 4
        color = [round(0.35 + 0.6 * c / COLUMNS, 3), round(0.35 + 0.6 * r / ROWS, 3), round(rng.uniform(0.3, 0.9), 3), 1]
        objects.append({
            "builtin": {"type": "cube", "size": 0.36},
            "transform": {"translate": [round(x, 3), 0, round(z, 3)],
                          "rotate": [0, round(rng.uniform(0, 90), 1), 0]},
            "material": {"shading": "lambert", "color": color},
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
