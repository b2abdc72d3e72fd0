#!/usr/bin/env python3
"""Times two softraster programs on the same scenes, taking turns, and prints how much the
second one's frame time differs from the first one's.

  scripts/ab-compare.py OLD NEW [--rounds 6] [--threads 1] [--frames 20] SCENE ...

OLD and NEW are two builds of the `softraster` program (say, main's and a change's, copied
aside). A SCENE is a scene file, or the name of one in bench/scenes (bench_trilinear).
Each round runs `PROGRAM bench SCENE --threads T --frames F --json` once for each program,
OLD first in the odd rounds and NEW first in the even ones (AB BA AB ...), so that a machine
whose speed drifts, or a cache the first run warms, favours neither. Per scene it prints
the median of each program's frame times (each run's own median) and the median of the
rounds' ratios NEW / OLD, which one slow spell does not move, and the median of each run's
fastest frame, which a run slowed throughout by a busy neighbour moves least. Exit status 2
on bad arguments, 1 on a failed run (as bench-compare.py)."""
import argparse, importlib.util, os, statistics, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The runs and their JSON as bench-compare.py takes them (its run_json).
_spec = importlib.util.spec_from_file_location('bench_compare', os.path.join(ROOT, 'scripts', 'bench-compare.py'))
bench_compare = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bench_compare)


def frame_ms(program, scene, threads, frames):
    """A run's median and fastest frame times."""
    j = bench_compare.run_json([program, 'bench', scene, '--threads', str(threads), '--frames', str(frames), '--json'])
    return float(j['median_ms']), float(j['min_ms'])


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0], epilog='The two take turns at running first (see the header of the script).')
    p.add_argument('old', help='the first program (the baseline)')
    p.add_argument('new', help='the second program (the change)')
    p.add_argument('scenes', nargs='+', metavar='SCENE', help='a scene file, or a name in bench/scenes')
    p.add_argument('--rounds', type=int, default=6, help='rounds per scene (default 6)')
    p.add_argument('--threads', type=int, default=1, help='threads of each run (default 1)')
    p.add_argument('--frames', type=int, default=20, help='timed frames of each run (default 20)')
    a = p.parse_args()
    for program in (a.old, a.new):
        if not (os.path.isfile(program) and os.access(program, os.X_OK)):
            p.error('%s: not an executable file' % program)
    if a.rounds < 1 or a.threads < 1 or a.frames < 1:
        p.error('--rounds, --threads and --frames must be at least 1')
    scenes = [bench_compare.scene_path(s, 'ab-compare') for s in a.scenes]
    for scene in scenes:
        programs, times, fastest = {'old': a.old, 'new': a.new}, {'old': [], 'new': []}, {'old': [], 'new': []}
        for k in range(a.rounds):
            for which in (('old', 'new') if k % 2 == 0 else ('new', 'old')):  # OLD first in rounds 0, 2, 4, ...
                median, least = frame_ms(programs[which], scene, a.threads, a.frames)
                times[which].append(median), fastest[which].append(least)
        old, new = statistics.median(times['old']), statistics.median(times['new'])
        ratio = statistics.median(n / o for o, n in zip(times['old'], times['new']))
        print('%s: old %.2f ms, new %.2f ms (%+.1f%%; median of the rounds\' ratios %+.1f%%)' %
              (os.path.basename(scene), old, new, (new / old - 1) * 100, (ratio - 1) * 100))
        print('  old: %s\n  new: %s' % (' '.join('%.2f' % t for t in times['old']), ' '.join('%.2f' % t for t in times['new'])))
        old_f, new_f = statistics.median(fastest['old']), statistics.median(fastest['new'])
        print('  fastest frames, median over the rounds: old %.2f ms, new %.2f ms (%+.1f%%)' % (old_f, new_f, (new_f / old_f - 1) * 100))


if __name__ == '__main__':
    main()
