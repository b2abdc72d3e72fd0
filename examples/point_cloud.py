#!/usr/bin/env python3
"""point_cloud.py MODEL OUT.ply [--views N] [--size S]: a colored point cloud of a model from
N views (docs/python.md walks through it).

Each view gives the color, the depth and the mask (the pixels with a surface); each masked
pixel (u, v) with depth d is the camera-space point d K^-1 (u + 0.5, v + 0.5, 1) in OpenCV's
axes, and inv(world_to_camera) takes it to the model's world space.
"""
import argparse

import numpy as np
import softraster


def point_cloud(path, views=8, size=256):
    """World-space points, their colors (uint8 RGB) and their triangles' ids, from `views` views."""
    model = softraster.Model(path)
    points, colors, triangles = [], [], []
    for shot in softraster.views(model, count=views, size=size, samples=1, depth=True, ids=True):
        mask = shot['object_id'] >= 0                  # where a surface is
        v, u = np.nonzero(mask)
        d = shot['depth'][v, u]                        # distance along the view axis
        K, world_to_camera = shot['camera']['K'], shot['camera']['world_to_camera']
        rays = np.linalg.inv(K) @ np.stack([u + 0.5, v + 0.5, np.ones(len(u))])  # z = 1 in camera space
        camera = np.vstack([rays * d, np.ones(len(u))])                          # homogeneous, camera space
        points.append((np.linalg.inv(world_to_camera) @ camera)[:3].T)
        colors.append(shot['color'][v, u, :3])
        triangles.append(np.stack([shot['object_id'][v, u], shot['triangle_id'][v, u]], axis=1))
    return np.concatenate(points), np.concatenate(colors), np.concatenate(triangles)


def write_ply(path, points, colors):
    with open(path, 'w') as f:
        f.write('ply\nformat ascii 1.0\nelement vertex %d\n' % len(points))
        f.write('property float x\nproperty float y\nproperty float z\n')
        f.write('property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n')
        for p, c in zip(points, colors):
            f.write('%g %g %g %d %d %d\n' % (p[0], p[1], p[2], c[0], c[1], c[2]))


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('model')
    parser.add_argument('out')
    parser.add_argument('--views', type=int, default=8)
    parser.add_argument('--size', type=int, default=256)
    args = parser.parse_args()
    points, colors, _ = point_cloud(args.model, args.views, args.size)
    write_ply(args.out, points, colors)
    print('%s: %d points' % (args.out, len(points)))
