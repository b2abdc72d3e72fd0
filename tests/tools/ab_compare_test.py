#!/usr/bin/env python3
"""ab_compare_test.py SCRIPT WORKDIR: scripts/ab-compare.py runs the two programs in turns
(old first, then new first, ...), as many rounds as asked, and reports the medians, the
median of the rounds' ratios and that of the runs' fastest frames; a bad scene or program is
exit 2 with its error on stderr
(argparse adds its usage line for a program), and a scene may be named as in bench/scenes.
bench-compare.py's bad arguments are exit 2 too.
Two stand-in programs answer `bench ... --json` with set frame times (median and fastest) and
log each call."""
import os, stat, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish

script, work = sys.argv[1:3]
os.makedirs(work, exist_ok=True)
log = os.path.join(work, 'calls.log')
if os.path.exists(log):
    os.remove(log)


def stand_in(name, times):
    """A program that prints the next of `times` as its median frame time on each call, and
    one less as its fastest."""
    path = os.path.join(work, name)
    with open(path, 'w') as f:
        f.write('#!/bin/sh\n'
                'n=$(grep -c "^%s " "%s" 2>/dev/null || true)\n'
                'echo "%s $*" >> "%s"\n'
                'set -- %s\n'
                'shift "${n:-0}"\n'
                'echo "{\\"median_ms\\": $1, \\"min_ms\\": $(($1 - 1))}"\n' % (name, log, name, log, ' '.join(times)))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


old = stand_in('old', ['10', '10', '30', '10'])  # one slow round (30): the medians do not follow it
new = stand_in('new', ['12', '12', '12', '11'])
scene = os.path.join(work, 'scene.json')
open(scene, 'w').write('{}')
r = subprocess.run([sys.executable, script, old, new, scene, '--rounds', '4', '--threads', '2', '--frames', '7'],
                   capture_output=True, text=True)
check('runs', r.returncode == 0, r.stderr)
calls = [line.split() for line in open(log)] if os.path.exists(log) else []
check('eight runs in turns', [c[0] for c in calls] == ['old', 'new', 'new', 'old', 'old', 'new', 'new', 'old'], calls)
check('each run benches the scene at the threads and frames asked',
      all(c[1:] == ['bench', scene, '--threads', '2', '--frames', '7', '--json'] for c in calls), calls)
# Old's times 10 10 30 10 (median 10), new's 12 12 12 11 (median 12); the rounds' ratios
# 1.2 1.2 0.4 1.1 have the median 1.15.
check('medians and ratio', "old 10.00 ms, new 12.00 ms (+20.0%; median of the rounds' ratios +15.0%)" in r.stdout, r.stdout)
# The fastest frames: old's 9 9 29 9 (median 9), new's 11 11 11 10 (median 11).
check('fastest frames', 'fastest frames, median over the rounds: old 9.00 ms, new 11.00 ms (+22.2%)' in r.stdout, r.stdout)

# A scene named without its path is bench/scenes' file of that name (bench-compare's scene_path).
os.remove(log)
r = subprocess.run([sys.executable, script, old, new, 'bench_fill', '--rounds', '1'], capture_output=True, text=True)
named = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(script))), 'bench', 'scenes', 'bench_fill.json')
calls = [line.split() for line in open(log)] if os.path.exists(log) else []
check('a scene by name', r.returncode == 0 and len(calls) == 2 and all(c[2] == named for c in calls), (r.stderr, calls))

# bench-compare (beside it) takes the same names, and says so of a missing one.
bench_compare = os.path.join(os.path.dirname(script), 'bench-compare.py')
for args, what in ((['no_such_scene'], "bench-compare's missing scene"), (['--threads', '1,x'], "bench-compare's bad --threads")):
    r = subprocess.run([sys.executable, bench_compare] + args, capture_output=True, text=True)
    check(what, r.returncode == 2 and r.stdout == '' and r.stderr.strip() != '' and 'Traceback' not in r.stderr, (r.returncode, r.stderr))

for args, what in (([old, new, os.path.join(work, 'missing.json')], 'a missing scene'),
                   ([os.path.join(work, 'nothing'), new, scene], 'a missing program')):
    r = subprocess.run([sys.executable, script] + args, capture_output=True, text=True)
    lines = r.stderr.strip().splitlines()
    check(what, r.returncode == 2 and len(lines) >= 1 and r.stdout == '', (r.returncode, r.stderr))
finish()
