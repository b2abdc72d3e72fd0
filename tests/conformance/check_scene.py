#!/usr/bin/env python3
"""check_scene.py SOFTRASTER SCENE.json OUTDIR: renders SCENE with softraster and compares it
with SCENE's .ref.png (drawn by Mesa llvmpipe) by the conformance bar: at most 0.1% of pixels
with a channel off by more than 2/255 and a PSNR of at least 38 dB; fill_rule exactly."""
import json, os, subprocess, sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, '..', 'tools'))
import imgdiff  # noqa: E402

MAX_FRAC_OVER_2 = 0.001
MIN_PSNR = 38.0
EXACT = {'fill_rule'}


def main():
    exe, scene, outdir = sys.argv[1:4]
    name = os.path.splitext(os.path.basename(scene))[0]
    os.makedirs(outdir, exist_ok=True)
    out = os.path.join(outdir, name + '.png')
    r = subprocess.run([exe, 'render', scene, '-o', out], capture_output=True, text=True)
    if r.returncode != 0:
        print('render failed (%d): %s' % (r.returncode, r.stderr.strip()))
        return 1
    ref = os.path.join(os.path.dirname(scene), name + '.ref.png')
    result = subprocess.run([sys.executable, imgdiff.__file__, ref, out], capture_output=True, text=True)
    stats = json.loads(result.stdout)
    print(name, json.dumps(stats))
    if name in EXACT:
        ok = stats['identical']
    else:
        ok = stats['frac_over_2'] <= MAX_FRAC_OVER_2 and stats['psnr_db'] >= MIN_PSNR
    print('PASS' if ok else 'FAIL: over the conformance bar')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
