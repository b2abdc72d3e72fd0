#!/usr/bin/env python3
"""Renders scenes with softraster and with Mesa llvmpipe (glref) and writes, for each, one
picture with the two side by side and the difference (times 8) on the right, for the docs.

  scripts/side-by-side.py [--build build-release] --out docs/images SCENE.json ...

Prints one Markdown table row per scene (its picture, PSNR, share of pixels off by more
than 2/255), for pasting into a page."""
import argparse, json, os, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tests', 'tools'))
import imgdiff  # noqa: E402  (the project's PNG reader and writer)


def rgb(path):
    w, h, ch, px = imgdiff.read_png(path)
    if ch == 3:
        return w, h, bytes(px)
    out = bytearray(3 * w * h)
    for i in range(w * h):
        out[3 * i:3 * i + 3] = px[ch * i:ch * i + 3]
    return w, h, bytes(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', default=os.path.join(ROOT, 'build-release'))
    ap.add_argument('--out', required=True)
    ap.add_argument('scenes', nargs='+')
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    sr, gl = os.path.join(a.build, 'softraster'), os.path.join(a.build, 'tests', 'glref')
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes:
            name = os.path.splitext(os.path.basename(scene))[0]
            ours, theirs = os.path.join(tmp, 'ours.png'), os.path.join(tmp, 'theirs.png')
            for args in ([sr, 'render', scene, '-o', ours], [gl, scene, '-o', theirs]):
                r = subprocess.run(args, capture_output=True, text=True)
                if r.returncode:
                    sys.exit('%s: %s' % (' '.join(args), r.stderr.strip()))
            stats = json.loads(subprocess.run([sys.executable, os.path.join(ROOT, 'tests', 'tools', 'imgdiff.py'), theirs, ours],
                                              capture_output=True, text=True).stdout)
            (w, h, a_px), (_, _, b_px) = rgb(ours), rgb(theirs)
            gap = 4
            row = 3 * (3 * w + 2 * gap)
            out = bytearray(b'\xff' * (row * h))
            for y in range(h):
                line = out[y * row:(y + 1) * row]
                for k, src in enumerate((a_px, b_px)):
                    x0 = 3 * k * (w + gap)
                    line[x0:x0 + 3 * w] = src[3 * w * y:3 * w * (y + 1)]
                x0 = 3 * 2 * (w + gap)
                line[x0:x0 + 3 * w] = bytes(min(255, 8 * abs(p - q)) for p, q in zip(a_px[3 * w * y:3 * w * (y + 1)],
                                                                                      b_px[3 * w * y:3 * w * (y + 1)]))
                out[y * row:(y + 1) * row] = line
            path = os.path.join(a.out, name + '.png')
            imgdiff.write_png_rgb(path, 3 * w + 2 * gap, h, bytes(out))
            rel = os.path.relpath(path, os.path.join(ROOT, 'docs'))
            print('| `%s` | ![%s](%s) | %.1f dB | %.3f%% |' % (name, name, rel, stats['psnr_db'], 100 * stats['frac_over_2']))


if __name__ == '__main__':
    main()
