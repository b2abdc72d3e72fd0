#!/usr/bin/env python3
"""Times softraster and Mesa llvmpipe on the benchmark scenes, interleaved, in one run, at
each thread count, and prints a table with the ratios (and writes it to --report).

  scripts/bench-compare.py [--build build-release] [--threads 1,2] [--frames 10] [--warmup 2]
                           [--rounds 3] [--report docs/performance.md] [SCENE.json ...]

softraster: `softraster bench SCENE --threads T --json` (clear, all draws, MSAA resolve).
llvmpipe:   `glref SCENE --time` with LP_NUM_THREADS=T (clear, all draws, resolve, glFinish).
Both report the median frame time of --frames frames after --warmup frames. Each scene is
timed in --rounds rounds; a round times every thread count, the two renderers one after the
other at each (llvmpipe first in every other round). A round's ratio is of its two medians,
and its 1 -> 2 thread speed-up is of softraster's two medians in that round; a row gives the
median of the rounds' times, ratios and speed-ups. On a shared machine, whose speed drifts
from second to second, a single pair of runs can land one renderer in a slow spell;
the rounds' ratios show it, and their median does not follow one outlier.

With threads 1 and 2, each round also runs `softraster bench SCENE --threads 2 --scaling`,
which draws the frames on one thread and on two in turn, frame by frame, in one process: a
slow spell then falls on both thread counts alike, where the two runs above may land in
different ones. The report gives both speed-ups."""
import argparse, glob, json, os, platform, statistics, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGET = 0.35   # softraster's time at most this share of llvmpipe's (issue 43)
SCALING = 1.8   # and at least this much faster with 2 threads than with 1


def run_json(cmd, env=None):
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit('failed: %s\n%s' % (' '.join(cmd), r.stderr))
    return json.loads(r.stdout.strip().splitlines()[-1])


def scene_path(name, tool='bench-compare'):
    """A scene file, or the file of that name in bench/scenes (bench_trilinear); exits with
    status 2 and one line on stderr if there is neither."""
    if os.path.isfile(name):
        return name
    named = os.path.join(ROOT, 'bench', 'scenes', name + ('' if name.endswith('.json') else '.json'))
    if os.path.isfile(named):
        return named
    print('%s: %s: no such scene file, nor one of that name in bench/scenes' % (tool, name), file=sys.stderr)
    sys.exit(2)


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
    # (AVX-512 as softraster's texture lookup takes it: BW, VL and DQ; pipeline/simd.h)
    avx512 = all(' %s' % f in flags for f in ('avx512bw', 'avx512vl', 'avx512dq'))
    simd = 'AVX-512' if avx512 else 'AVX2' if ' avx2' in flags else ('SSE4.2' if 'sse4_2' in flags else 'baseline')
    return '%s, %d cores, %s, %s' % (model or platform.processor(), os.cpu_count(), simd, platform.platform())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0], epilog='How the rounds are paired: see the header of the script.')
    ap.add_argument('--build', default=os.path.join(ROOT, 'build-release'), help='the build holding softraster and tests/glref (default build-release)')
    ap.add_argument('--threads', default='1,2', help='thread counts, comma-separated (default 1,2)')
    ap.add_argument('--frames', type=int, default=10, help='timed frames of each run (default 10)')
    ap.add_argument('--warmup', type=int, default=2, help='frames before the timed ones (default 2)')
    ap.add_argument('--rounds', type=int, default=3, help='rounds per scene (default 3)')
    ap.add_argument('--report', metavar='FILE', help='also write the table to FILE')
    ap.add_argument('scenes', nargs='*', metavar='SCENE', help='a scene file, or a name in bench/scenes (default: every scene there)')
    a = ap.parse_args()
    try:
        threads = [int(t) for t in a.threads.split(',')]
    except ValueError:
        ap.error('--threads: %s is not a comma-separated list of counts' % a.threads)
    if min(threads) < 1 or a.frames < 1 or a.warmup < 0 or a.rounds < 1:
        ap.error('--threads, --frames and --rounds must be at least 1, --warmup at least 0')
    scenes = [scene_path(s) for s in a.scenes] or sorted(glob.glob(os.path.join(ROOT, 'bench', 'scenes', '*.json')))
    sr = os.path.join(a.build, 'softraster')
    gl = os.path.join(a.build, 'tests', 'glref')
    rows, scaling = [], []
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        ours_cmd = lambda t: [sr, 'bench', scene, '--threads', str(t), '--frames', str(a.frames), '--warmup', str(a.warmup), '--json']
        theirs_cmd = [gl, scene, '--time', '--frames', str(a.frames), '--warmup', str(a.warmup)]
        drawn = llvmpipe_can_draw(scene)
        # Each round times every thread count, so a round's 1 -> 2 thread speed-up is of two runs
        # seconds apart rather than of two rows timed minutes apart.
        ours = {t: [] for t in threads}
        theirs = {t: [] for t in threads}
        both = 1 in threads and 2 in threads
        in_turn = []  # each round's speed-up, frame by frame in one process
        for r in range(a.rounds):
            for t in threads:
                env = dict(os.environ, LP_NUM_THREADS=str(t))
                if drawn and r % 2: theirs[t].append(run_json(theirs_cmd, env)['median_ms'])
                ours[t].append(run_json(ours_cmd(t))['median_ms'])
                if drawn and not r % 2: theirs[t].append(run_json(theirs_cmd, env)['median_ms'])
            if both:
                in_turn.append(run_json(ours_cmd(2)[:-1] + ['--scaling', '--json'])['speedup'])
        for t in threads:
            if not drawn:
                rows.append((name, t, statistics.median(ours[t]), None, None))
                print('%-22s %d thread(s): softraster %8.1f ms   (llvmpipe cannot draw it)' % (name, t, rows[-1][2]), flush=True)
                continue
            ratios = [o / l for o, l in zip(ours[t], theirs[t])]
            ratio = statistics.median(ratios)
            rows.append((name, t, statistics.median(ours[t]), statistics.median(theirs[t]), ratio))
            print('%-22s %d thread(s): softraster %8.1f ms   llvmpipe %8.1f ms   ratio %.2f %s   (rounds: %s)' %
                  (name, t, rows[-1][2], rows[-1][3], ratio, 'ok' if ratio <= TARGET else 'MISSED',
                   ' '.join('%.2f' % x for x in ratios)), flush=True)
        if both:
            gains = [one / two for one, two in zip(ours[1], ours[2])]
            theirs_gain = statistics.median(one / two for one, two in zip(theirs[1], theirs[2])) if drawn else None
            scaling.append((name, statistics.median(gains), statistics.median(in_turn), theirs_gain))
            print('%-22s 1 -> 2 threads: softraster %.2fx %s   (rounds: %s)   frame by frame %.2fx %s   (rounds: %s)%s' %
                  (name, scaling[-1][1], 'ok' if scaling[-1][1] >= SCALING else 'MISSED', ' '.join('%.2f' % x for x in gains),
                   scaling[-1][2], 'ok' if scaling[-1][2] >= SCALING else 'MISSED', ' '.join('%.2f' % x for x in in_turn),
                   '   llvmpipe %.2fx' % theirs_gain if drawn else ''), flush=True)
    if a.report:
        tail = kept_tail(a.report)
        with open(a.report, 'w') as f:
            f.write(HEAD.format(date=time.strftime('%Y-%m-%d'), machine=machine(), frames=a.frames, warmup=a.warmup, rounds=a.rounds,
                                threads=a.threads))
            f.write('| scene | threads | softraster (ms) | llvmpipe (ms) | softraster / llvmpipe | target (<= %.2f) |\n|---|---|---|---|---|---|\n' % TARGET)
            for n, t, s, l, r in rows:
                if l is None:
                    f.write('| %s | %d | %.1f | (cannot draw it) | | |\n' % (n, t, s))
                    continue
                f.write('| %s | %d | %.1f | %.1f | %.2f | %s |\n' % (n, t, s, l, r, 'met' if r <= TARGET else 'missed'))
            if scaling:
                f.write('\n| scene | softraster 1 -> 2 threads, runs in turn | target (>= %.1fx) | frame by frame in one process | target | '
                        'llvmpipe 1 -> 2 threads |\n|---|---|---|---|---|---|\n' % SCALING)
                met = lambda x: 'met' if x >= SCALING else 'missed'
                for n, s, f1, l in scaling:
                    f.write('| %s | %.2fx | %s | %.2fx | %s | %s |\n' % (n, s, met(s), f1, met(f1), '%.2fx' % l if l else ''))
            f.write(tail)
        print('wrote', a.report)


HEAD = """# Performance

softraster against Mesa llvmpipe on the scenes in `bench/scenes/` (the `make_bench_*.py`
scripts there write most of them), measured on the same machine, in the same run, interleaved,
at the same thread count. Lower is better; the target is softraster at most 0.35 of
llvmpipe's median frame time, and 1.8 times as fast with two threads as with one.

- Machine: {machine}
- Date: {date}; {frames} timed frames after {warmup} warm-up frames; threads {threads}; {rounds}
  rounds, each timing every thread count, the two renderers in turn (a row: the median of the
  rounds' times and ratios; a speed-up: the median of the rounds' one-thread over two-thread times,
  and of the rounds' `softraster bench SCENE --threads 2 --scaling`, which draws one-thread and
  two-thread frames in turn in one process, so that a slow spell of the machine falls on both)
- Command: `scripts/bench-compare.py --report docs/performance.md` after
  `cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release && cmake --build build-release`
- softraster: `softraster bench SCENE --threads T --json` (clear, every draw, and with MSAA the
  resolve into a picture buffer; single-sampled, the framebuffer is the picture).
- llvmpipe: `build-release/tests/glref SCENE --time` with `LP_NUM_THREADS=T` (clear, every
  draw, resolve, `glFinish`), one GLSL program per material (no branches on material state).

"""

# Everything after the tables is prose kept in the report file itself, from this heading on.
TAIL_HEADING = '## What version 2 costs version 1 scenes'


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
