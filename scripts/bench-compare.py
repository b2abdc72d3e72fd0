#!/usr/bin/env python3
"""Times softraster and Mesa llvmpipe on the benchmark scenes, interleaved, in one run, at
each thread count, and prints a table with the ratios (and writes it to --report).

  scripts/bench-compare.py [--build build-release] [--threads 1,2] [--frames 10] [--warmup 2]
                           [--report docs/performance.md] [SCENE.json ...]

softraster: `softraster bench SCENE --threads T --json` (clear, all draws, MSAA resolve).
llvmpipe:   `glref SCENE --time` with LP_NUM_THREADS=T (clear, all draws, resolve, glFinish).
Both report the median frame time of --frames frames after --warmup frames."""
import argparse, glob, json, os, platform, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_json(cmd, env=None):
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit('failed: %s\n%s' % (' '.join(cmd), r.stderr))
    return json.loads(r.stdout.strip().splitlines()[-1])


def machine():
    model = ''
    try:
        for line in open('/proc/cpuinfo'):
            if line.startswith('model name'):
                model = line.split(':', 1)[1].strip()
                break
    except OSError:
        pass
    flags = open('/proc/cpuinfo').read()
    simd = 'AVX2' if ' avx2' in flags else ('SSE4.2' if 'sse4_2' in flags else 'baseline')
    return '%s, %d cores, %s, %s' % (model or platform.processor(), os.cpu_count(), simd, platform.platform())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', default=os.path.join(ROOT, 'build-release'))
    ap.add_argument('--threads', default='1,2')
    ap.add_argument('--frames', type=int, default=10)
    ap.add_argument('--warmup', type=int, default=2)
    ap.add_argument('--report')
    ap.add_argument('scenes', nargs='*')
    a = ap.parse_args()
    scenes = a.scenes or sorted(glob.glob(os.path.join(ROOT, 'bench', 'scenes', '*.json')))
    sr = os.path.join(a.build, 'softraster')
    gl = os.path.join(a.build, 'tests', 'glref')
    threads = [int(t) for t in a.threads.split(',')]
    rows = []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        for t in threads:
            env = dict(os.environ, LP_NUM_THREADS=str(t))
            ours = run_json([sr, 'bench', scene, '--threads', str(t), '--frames', str(a.frames), '--warmup', str(a.warmup), '--json'])
            theirs = run_json([gl, scene, '--time', '--frames', str(a.frames), '--warmup', str(a.warmup)], env)
            ratio = ours['median_ms'] / theirs['median_ms']
            rows.append((name, t, ours['median_ms'], theirs['median_ms'], ratio))
            print('%-22s %d thread(s): softraster %8.1f ms   llvmpipe %8.1f ms   ratio %.2f %s' %
                  (name, t, ours['median_ms'], theirs['median_ms'], ratio, 'ok' if ratio <= 0.5 else 'MISSED'), flush=True)
    by = {(n, t): (s, l) for n, t, s, l, _ in rows}
    scaling = []
    if 1 in threads and 2 in threads:
        for name in dict.fromkeys(r[0] for r in rows):
            scaling.append((name, by[(name, 1)][0] / by[(name, 2)][0], by[(name, 1)][1] / by[(name, 2)][1]))
    if a.report:
        with open(a.report, 'w') as f:
            f.write(HEAD.format(date=time.strftime('%Y-%m-%d'), machine=machine(), frames=a.frames, warmup=a.warmup,
                                threads=a.threads))
            f.write('| scene | threads | softraster (ms) | llvmpipe (ms) | softraster / llvmpipe | target (<= 0.5) |\n|---|---|---|---|---|---|\n')
            for n, t, s, l, r in rows:
                f.write('| %s | %d | %.1f | %.1f | %.2f | %s |\n' % (n, t, s, l, r, 'met' if r <= 0.5 else 'missed'))
            if scaling:
                f.write('\n| scene | softraster 1 -> 2 threads | llvmpipe 1 -> 2 threads |\n|---|---|---|\n')
                for n, s, l in scaling:
                    f.write('| %s | %.2fx | %.2fx |\n' % (n, s, l))
            f.write(TAIL)
        print('wrote', a.report)


HEAD = """# Performance

softraster against Mesa llvmpipe on the scenes in `bench/scenes/` (copies of
`../shared/scenes/bench/`), measured on the same machine, in the same run, interleaved,
at the same thread count. Lower is better; the target is softraster at most half of
llvmpipe's median frame time.

- Machine: {machine}
- Date: {date}; {frames} timed frames after {warmup} warm-up frames; threads {threads}
- Command: `scripts/bench-compare.py --report docs/performance.md` after
  `cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release && cmake --build build-release`
- softraster: `softraster bench SCENE --threads T --json` (clear, every draw, MSAA resolve).
- llvmpipe: `build-release/tests/glref SCENE --time` with `LP_NUM_THREADS=T` (clear, every
  draw, resolve, `glFinish`), one GLSL program per material (no branches on material state).

"""

TAIL = """
## How the time is spent

- Front end, in parallel over chunks: vertex shading (once per vertex, with the
  perspective divide, viewport mapping and snapping), then primitive assembly, clipping,
  culling and binning into 64x64 tiles (`include/softraster/pipeline/binning.h`).
- Back end, one thread per tile, every draw in order: triangle setup with planes rebased
  to the tile, span rasterization (an exact pixel span per row from the edge functions),
  early depth test, the shader specialized at compile time for its model, texture and
  vertex colors, 8-bit fixed-point blending.

Microbenchmarks (Google Benchmark) of setup, traversal, shading and resolve:
`build-release/bench/micro_benchmarks` (built when libbenchmark-dev is installed).

## Where the rest of the gap is

softraster is faster than llvmpipe on every scene at both thread counts; the target (half of
llvmpipe's time) is not yet met everywhere. What the profiles point at next:

- Triangle-heavy scenes (bench_highpoly*, bench_many_objects, bench_msaa at 1 thread): per
  triangle work dominates — setup computes double-precision planes for every varying, and
  every small triangle runs the span walk. Next: set up in SIMD across triangles, and a
  small-triangle path that skips planes for triangles that cover one or two pixels.
- bench_msaa: the 4x path shades scalar; the eight-lane path is single-sampled only.
- bench_fill: hidden-surface removal cut shading 16x; the visibility pass re-walks every
  layer. A coarse per-tile depth bound (reject a triangle whose nearest depth is behind the
  tile's farthest stored depth) would skip most of it.
- bench_blend: eight-lane shading and 8-bit blending; llvmpipe's JIT fuses the whole
  fragment pipeline per quad. Next: keep color in the tile in a planar layout across draws.
"""

if __name__ == '__main__':
    main()
