#!/usr/bin/env python3
"""bench_compare_test.py SCRIPT WORKDIR: scripts/bench-compare.py times softraster at 1 and 2
threads in each round and, in the same round, `bench --threads 2 --scaling` (one-thread and
two-thread frames in turn in one process); it reports both speed-ups, each the median of its
rounds, against the 1.8x target, in its printout and in --report's table.
Stand-in programs in a stand-in build directory (softraster, tests/glref) answer with set
times and log each call. (That directory is a temporary one, removed at the end: a program
named softraster left in the build tree would pass for the real one to whatever looks for it
there.)"""
import atexit, json, os, shutil, stat, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish

script, work = sys.argv[1:3]
os.makedirs(work, exist_ok=True)
build = tempfile.mkdtemp(prefix='bench_compare_build_')
atexit.register(shutil.rmtree, build, True)
os.makedirs(os.path.join(build, 'tests'))
log = os.path.join(work, 'calls.log')
if os.path.exists(log):
    os.remove(log)

# softraster: 20 ms at one thread; at two, 10, 16, 16 ms in turn (runs in turn: 2.0x, 1.25x,
# 1.25x, median 1.25x); with --scaling, 1.9x, 1.85x, 2.0x in turn (median 1.9x).
# glref: 60 ms at one thread, 40 at two.
STAND_IN = '''#!%s
import json, os, sys
log, name = %r, %r
calls = [l.split() for l in open(log)] if os.path.exists(log) else []
with open(log, 'a') as f:
    f.write(name + ' ' + ' '.join(sys.argv[1:]) + ' LP_NUM_THREADS=' + os.environ.get('LP_NUM_THREADS', '-') + '\\n')
if name == 'glref':
    print(json.dumps({'median_ms': 60.0 if os.environ.get('LP_NUM_THREADS') == '1' else 40.0}))
elif '--scaling' in sys.argv:
    k = sum(1 for c in calls if c[0] == name and '--scaling' in c)
    print(json.dumps({'median_ms': 10.0, 'speedup': [1.9, 1.85, 2.0][k %% 3]}))
else:
    t = sys.argv[sys.argv.index('--threads') + 1]
    k = sum(1 for c in calls if c[0] == name and '--scaling' not in c and c[c.index('--threads') + 1] == '2')
    print(json.dumps({'median_ms': 20.0 if t == '1' else [10.0, 16.0, 16.0][k %% 3]}))
'''


def stand_in(path, name):
    with open(path, 'w') as f:
        f.write(STAND_IN % (sys.executable, log, name))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)


stand_in(os.path.join(build, 'softraster'), 'softraster')
stand_in(os.path.join(build, 'tests', 'glref'), 'glref')
scene = os.path.join(work, 'scene.json')
open(scene, 'w').write(json.dumps({'image': {'width': 8, 'height': 8}}))
report = os.path.join(work, 'report.md')
open(report, 'w').write('old table\n\n## What version 2 costs version 1 scenes\nkept prose\n')
r = subprocess.run([sys.executable, script, '--build', build, '--rounds', '3', '--frames', '7', '--warmup', '1', '--report', report, scene],
                   capture_output=True, text=True)
check('runs', r.returncode == 0, r.stderr)
calls = [line.split() for line in open(log)] if os.path.exists(log) else []
scaling = [c for c in calls if '--scaling' in c]
check('one --scaling run a round, at 2 threads, with the frames and warm-up asked',
      len(scaling) == 3 and all(c[1:10] == ['bench', scene, '--threads', '2', '--frames', '7', '--warmup', '1', '--scaling'] and '--json' in c
                                for c in scaling), scaling)
check('and the plain runs at each thread count', sum(1 for c in calls if c[0] == 'softraster' and '--scaling' not in c) == 6, calls)
check('both speed-ups printed with their verdicts',
      'softraster 1.25x MISSED' in r.stdout and 'frame by frame 1.90x ok' in r.stdout and '(rounds: 1.90 1.85 2.00)' in r.stdout, r.stdout)
text = open(report).read()
row = [l for l in text.splitlines() if l.startswith('| scene | ') and 'frame by frame' in l]
check('the report has a column for each speed-up', len(row) == 1, text)
check("the scene's speed-ups in it", '| scene | 1.25x | missed | 1.90x | met | 1.50x |' in text, text)
check('the prose after the tables kept', text.rstrip().endswith('kept prose'), text)
finish()
