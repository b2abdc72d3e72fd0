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


def llvmpipe_can_draw(scene):
    """llvmpipe offers 1 and 4 samples only: scenes with others are timed for softraster alone."""
    return json.load(open(scene))['image'].get('samples', 1) in (1, 4)


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
            if not llvmpipe_can_draw(scene):
                rows.append((name, t, ours['median_ms'], None, None))
                print('%-22s %d thread(s): softraster %8.1f ms   (llvmpipe cannot draw it)' % (name, t, ours['median_ms']), flush=True)
                continue
            theirs = run_json([gl, scene, '--time', '--frames', str(a.frames), '--warmup', str(a.warmup)], env)
            ratio = ours['median_ms'] / theirs['median_ms']
            rows.append((name, t, ours['median_ms'], theirs['median_ms'], ratio))
            print('%-22s %d thread(s): softraster %8.1f ms   llvmpipe %8.1f ms   ratio %.2f %s' %
                  (name, t, ours['median_ms'], theirs['median_ms'], ratio, 'ok' if ratio <= 0.5 else 'MISSED'), flush=True)
    by = {(n, t): (s, l) for n, t, s, l, _ in rows}
    scaling = []
    if 1 in threads and 2 in threads:
        for name in dict.fromkeys(r[0] for r in rows):
            theirs = by[(name, 1)][1] / by[(name, 2)][1] if by[(name, 1)][1] else None
            scaling.append((name, by[(name, 1)][0] / by[(name, 2)][0], theirs))
    if a.report:
        with open(a.report, 'w') as f:
            f.write(HEAD.format(date=time.strftime('%Y-%m-%d'), machine=machine(), frames=a.frames, warmup=a.warmup,
                                threads=a.threads))
            f.write('| scene | threads | softraster (ms) | llvmpipe (ms) | softraster / llvmpipe | target (<= 0.5) |\n|---|---|---|---|---|---|\n')
            for n, t, s, l, r in rows:
                if l is None:
                    f.write('| %s | %d | %.1f | (cannot draw it) | | |\n' % (n, t, s))
                    continue
                f.write('| %s | %d | %.1f | %.1f | %.2f | %s |\n' % (n, t, s, l, r, 'met' if r <= 0.5 else 'missed'))
            if scaling:
                f.write('\n| scene | softraster 1 -> 2 threads | llvmpipe 1 -> 2 threads |\n|---|---|---|\n')
                for n, s, l in scaling:
                    f.write('| %s | %.2fx | %s |\n' % (n, s, '%.2fx' % l if l else ''))
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
- softraster: `softraster bench SCENE --threads T --json` (clear, every draw, and with MSAA the
  resolve into a picture buffer; single-sampled, the framebuffer is the picture).
- llvmpipe: `build-release/tests/glref SCENE --time` with `LP_NUM_THREADS=T` (clear, every
  draw, resolve, `glFinish`), one GLSL program per material (no branches on material state).

"""

TAIL = """
## How the time is spent

- Front end, in parallel over chunks: vertex shading (once per vertex; the shader one
  vertex at a time, then the outcode, perspective divide, viewport mapping and snapping
  eight vertices at a time), then primitive assembly and clipping
  (`include/softraster/pipeline/primitive_assembly.h`), culling and binning into 64x64
  tiles (`binning.h`), which also sums each tile's covered area (the overdraw estimate
  for hidden-surface removal). A triangle is bounded by the pixels with a sample inside
  its bounding box (`sample_pattern.h`): most triangles of a mesh finer than the pixels
  fall between the samples and are dropped before they are binned.
- Cost per triangle, not per draw and tile: a chunk's counting sort covers only the
  rectangle of tiles its triangles touch, and after binning each tile gets the list of
  the draws that touch it, in draw order (`Context::execute`, as llvmpipe's scene bins).
  bench_many_draws (20,000 cubes, one draw and one material each) went from 291 ms to
  about 45 ms at 1 thread with this; before, every tile visited every draw and every
  chunk counted every tile (about 12 us per draw at 1080p).
- Small draws (one chunk of vertices and primitives, as in bench_many_objects and
  bench_many_draws) are one front-end item each: binned right after their vertices are
  shaded, while those are still in the core's cache. The post-transform vertex keeps its
  varyings once (72 bytes for Blinn-Phong): a million-triangle mesh writes and reads that
  buffer every frame.
- Back end (`tile_back_end.h`), one thread per tile, the tile's draws in order: the clear
  (prefetching the rows ahead: a tile's rows are too far apart for the hardware
  prefetcher, BM_ClearTiles 1.9 -> 1.3 ms at 1080p), triangle setup in two parts,
  coverage (integer edge functions) and then the interpolation planes rebased to the
  tile, made only once a triangle covers a sample (many triangles of a million-triangle
  mesh cover none), with the vertices of the triangles a few places ahead prefetched
  (GCC 12 drops a prefetch whose address is chosen by a condition: without the
  prefetch bench_many_objects took 10% longer); rasterization in row spans (a 64-bit
  division only where an edge crosses the row; bench_highpoly -10% at 1 thread), in
  32-bit lanes for triangles of a few narrow rows (bench_many_objects -2.5%; for
  triangles of fewer than six pixels of bounds the walk is quicker: bench_highpoly_480
  took 3-5% longer with lanes), and in groups of eight pixels aligned to multiples of
  eight (whole-vector loads and stores; a group never straddles two tiles), the early
  depth test (`depth_stencil.h`), then shading specialized at compile time for the
  model, texture and vertex colors, and 8-bit fixed-point blending.
- Small triangles of opaque draws go through the fragment queue
  (`include/softraster/pipeline/fragment_queue.h`): depth is tested and written at once,
  and the fragments that pass wait to be shaded eight at a time whatever triangle they
  came from, so a one-pixel triangle no longer pays for eight lanes of shading. With 4x
  MSAA, small triangles are covered eight pixels (32 samples) at a time in 32-bit lanes
  (`rasterization_small.h`).
- Stacks of opaque draws (bench_fill) are drawn in two passes per tile: visibility, then
  shading of the last writer of each pixel only (`hidden_surface_removal.h`).
- Depth is interpolated from a plane whose origin value is two floats (hi + lo): one
  more addition per eight pixels, for depths that are the exact plane rounded once.

Microbenchmarks (Google Benchmark) of setup, traversal, shading, the clear and resolve:
`build-release/bench/micro_benchmarks` (built when libbenchmark-dev is installed).

## Build time

Compiling is a user's first cost: `scripts/showcase.sh` on a fresh clone spends nearly all
its time building the per-shading-model draw code (`src/scene/record_surface_draw.h`, one
generated source per model). Measured on this 2-core machine, `cmake --build` of the
program alone (`--target softraster`, Release, dependencies installed), from scratch:

| change | program build | full Release build with tests |
|---|---|---|
| before (one copy per blend mode, both CPU copies flattened, loop unswitching) | 9 min 45 s for showcase.sh on a fresh machine (the issue's measurement) | 10 min 55 s |
| the generic copy not flattened; vertex processing and binning compiled once per shader / per varying count, not per blend mode and sample count; no line and point code for scene draws | | 5 min 41 s |
| `-fno-unswitch-loops` (the flattened AVX2 loops had whole loop nests copied per run-time condition: record_Lambert_draw 122 -> 63 s, no bench row slower) | 3 min 27 s | |
| blended draws compiled once (the mode read per group), texture lookups of eight lanes out of line (one call per eight texels instead of the sampler inlined per lane) | 2 min 48 s | 4 min 16 s (a fresh clone's `.ci/run`) |

Tried and dropped: `-O2` for everything (the program built in 2 min 32 s, but
bench_highpoly took 31% longer, bench_many_objects 23%); a depth-only path for opaque
draws without color writes (it made bench_highpoly_480 30% slower through code layout
in the flattened loop, and saved no build time).

## Version 2 scenes

`bench/scenes/make_bench_v2.py` writes them. bench_msaa16 is bench_msaa's sphere with 16
samples, which llvmpipe cannot draw (it offers 1 and 4): the row has softraster's time only.
bench_stencil (a mirror floor marks the stencil, six reflected objects draw where it is 1,
then the blended mirror and the objects) and bench_blend_modes (twelve full-screen layers,
each with another equation and factors, depth test off) do not meet the target yet:

- Draws with any blend equation run in the fast back end, eight pixels at a time
  (`blend_channels<simd::i8>`); the blend settings are made once per draw and tile. A
  custom layer still costs about 40% more than an alpha-preset layer of bench_blend
  (10.5 against 7.4 ms per 1080p layer at 1 thread): the factor and equation choices are
  switches inside the pixel loop. Next: choose them once per draw (a table of the eight
  factor sources and an invert mask, selected without branches).
- Stencil draws run in the general back end (`general_back_end.h`): one fragment at a
  time, one indirect call per pixel, the shader run on one pixel. The reflected objects
  are about a third of bench_stencil's time; the stencil-only mirror pass no longer runs
  its shader (no color is written). Next: a stencil test in the fast back end's groups of
  eight (its depth-stencil stage is already a template parameter), compiled only for the
  shaders of draws that test stencil.

## Where the rest of the gap is

What the profiles (`perf record` on `softraster bench`) point at next:

- Triangle-heavy scenes at 1 thread (bench_highpoly*, bench_many_objects): per triangle,
  setup (the planes take about 13-21 ns in double precision: `BM_SetupPlanes`), binning
  (branches on culling and clipping that a mesh's triangle order makes hard to predict)
  and the clear. Running the vertex shader's matrix products eight vertices at a time
  measured no faster than one at a time.
- bench_fill: the visibility pass walks every layer. A coarse per-tile depth bound (skip
  a triangle whose nearest depth is behind the tile's farthest stored depth) would skip
  the hidden layers when they are drawn front to back.
- bench_blend: eight-lane shading and 8-bit blending per layer; keeping the tile's color
  in registers or a planar layout across draws would save the unpacking per layer.
"""

if __name__ == '__main__':
    main()
