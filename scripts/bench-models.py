#!/usr/bin/env python3
"""The glTF path end to end, as users run it: the wall time of

  softraster render MODEL -o OUT.png --size 1024           (one model: read, draw, resolve, write)
  softraster thumbnails FILE... --size 256 --out DIR -q    (the first --count glTF/GLB files under --models)

each the median of --rounds runs, with the files on the page cache (one untimed run first).

  scripts/bench-models.py [--build build-release] [--model M.gltf] [--models /usr/share/assimp/models]
                          [--count 50] [--rounds 5] [--threads N]

The default model is Cesium's milk truck from Debian's assimp-testmodels (a 2048x2048 sRGB
base color texture, trilinear), which bench/scenes/bench_textured_asset.json draws at 1600x1600."""
import argparse, glob, json, os, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = '/usr/share/assimp/models'


def wall(cmd, rounds, ok=(0,)):
    """The median and fastest wall time of cmd; ok: the exit codes that count as done
    (thumbnails exits 1 when some of its files could not be drawn, as some of the corpus's
    test files cannot)."""
    times = []
    for r in range(rounds + 1):  # the first untimed: the files into the page cache
        t0 = time.perf_counter()
        done = subprocess.run(cmd, capture_output=True, text=True)
        if r: times.append(time.perf_counter() - t0)
        if done.returncode not in ok:
            sys.exit('failed: %s\n%s' % (' '.join(cmd), done.stderr))
    return statistics.median(times), min(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--build', default=os.path.join(ROOT, 'build-release'))
    ap.add_argument('--model', default=os.path.join(MODELS, 'glTF', 'CesiumMilkTruck', 'CesiumMilkTruck.gltf'))
    ap.add_argument('--models', default=MODELS)
    ap.add_argument('--count', type=int, default=50)
    ap.add_argument('--rounds', type=int, default=5)
    ap.add_argument('--threads', type=int, default=0, help='render --threads and thumbnails --jobs (0: one per core)')
    a = ap.parse_args()
    sr = os.path.join(a.build, 'softraster')
    files = sorted(f for f in glob.glob(os.path.join(a.models, '**', '*'), recursive=True) if f.lower().endswith(('.gltf', '.glb')))
    files = files[:a.count]
    if not os.path.exists(a.model) or len(files) < a.count:
        sys.exit('need %s and %d glTF files under %s (Debian: assimp-testmodels)' % (a.model, a.count, a.models))
    with tempfile.TemporaryDirectory() as tmp:
        median, fastest = wall([sr, 'render', a.model, '-o', os.path.join(tmp, 'one.png'), '--size', '1024', '--threads', str(a.threads)], a.rounds)
        print('render %s at 1024x1024: median %.3f s, fastest %.3f s' % (os.path.basename(a.model), median, fastest))
        out = os.path.join(tmp, 'thumbs')
        median, fastest = wall([sr, 'thumbnails', *files, '--size', '256', '--out', out, '-q', '--jobs', str(a.threads)], a.rounds, ok=(0, 1))
        summary = json.load(open(os.path.join(out, 'thumbnails.json')))['summary']
        print('thumbnails of %d glTF files at 256x256 (%s drawn, %s failed): median %.3f s (%.1f files/s), fastest %.3f s' %
              (len(files), summary.get('ok'), summary.get('failed'), median, len(files) / median, fastest))


if __name__ == '__main__':
    main()
