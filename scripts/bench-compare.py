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
        tail = kept_tail(a.report)
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
            f.write(tail)
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

# Everything after the tables is prose kept in the report file itself, from this heading on.
TAIL_HEADING = '## How the time is spent'


def kept_tail(path):
    """The report file's text from TAIL_HEADING on (the prose the tables do not replace)."""
    try:
        text = open(path).read()
    except OSError:
        return '\n' + TAIL_HEADING + '\n'
    at = text.find(TAIL_HEADING)
    return '\n' + (text[at:] if at >= 0 else TAIL_HEADING + '\n')


if __name__ == '__main__':
    main()
