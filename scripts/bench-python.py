#!/usr/bin/env python3
"""bench-python.py [--views N] [--rounds R]: the Python module's numbers for
docs/performance.md ("From Python"), as a Markdown table:

  * views per second: N views (24) of a Model drawn with softraster.views at 512 x 512, on
    1 and 2 threads a picture, for the duck of assimp-testmodels and a textured glTF of
    128,000 triangles (scripts/make-textured-gltf.py, written to a temporary folder);
  * Python's cost per call: a 256 x 256 picture of the duck, the call's wall time against
    the time spent drawing in C++ (the result's 'draw_ms': what the command line spends on
    the same picture, less its file writing);
  * threads: N pictures drawn by N Python threads at once (threads=1 each) against one
    thread drawing them one after another.

  PYTHONPATH=build/python /usr/bin/python3 scripts/bench-python.py
"""
import argparse, os, statistics, subprocess, sys, tempfile, threading, time

parser = argparse.ArgumentParser()
parser.add_argument('--views', type=int, default=24)
parser.add_argument('--rounds', type=int, default=3)
parser.add_argument('--duck', default='/usr/share/assimp/models/Collada/duck.dae')
args = parser.parse_args()
import softraster  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
tmp = tempfile.mkdtemp(prefix='softraster-bench-')
torus = os.path.join(tmp, 'torus.gltf')
subprocess.run([sys.executable, os.path.join(here, 'make-textured-gltf.py'), torus], check=True, capture_output=True)



def best_seconds(f):
    """The fastest of --rounds runs of f()."""
    times = []
    for _ in range(args.rounds):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


print('| what | 1 thread | 2 threads |')
print('|---|---|---|')
for name, path in [('duck (4,212 triangles)', args.duck), ('textured glTF (128,000 triangles, 1024² sRGB texture)', torus)]:
    model = softraster.Model(path)
    cells = []
    for threads in (1, 2):
        best = best_seconds(lambda: softraster.views(model, count=args.views, size=512, threads=threads))
        cells.append('%.1f views/s' % (args.views / best))
    print('| %d views of the %s at 512² | %s | %s |' % (args.views, name, cells[0], cells[1]))

duck = softraster.Model(args.duck)
walls, draws = [], []
for _ in range(60):
    t0 = time.perf_counter()
    r = duck.render(size=256, threads=1)
    walls.append((time.perf_counter() - t0) * 1e3)
    draws.append(r['draw_ms'])
wall, draw = statistics.median(walls), statistics.median(draws)
print('| duck at 256², a call: wall / drawing (draw_ms) / Python\'s share | %.2f ms / %.2f ms / %.1f%% | |'
      % (wall, draw, 100 * (wall - draw) / draw))


def draw_view(view):
    duck.render(size=512, view=view, threads=1)


views = ['front', 'back', 'left', 'right']
one = best_seconds(lambda: [draw_view(v) for v in views])


def together():
    workers = [threading.Thread(target=draw_view, args=(v,)) for v in views]
    for t in workers:
        t.start()
    for t in workers:
        t.join()


many = best_seconds(together)
print('| 4 duck pictures at 512², threads=1 each: one Python thread / four threads | %.1f ms / %.1f ms (%.2fx) | |'
      % (one * 1e3, many * 1e3, one / many))
