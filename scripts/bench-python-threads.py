#!/usr/bin/env python3
"""bench-python-threads.py [MODEL] [--views N] [--size S]: whether Python threads draw in
parallel. One Model, N views drawn each with threads=1 (one core a picture), first one after
another on one Python thread, then on N Python threads at once; the GIL is released while a
picture is drawn, so the second should take about 1/N of the time on N free cores.

  PYTHONPATH=build/python /usr/bin/python3 scripts/bench-python-threads.py
"""
import argparse, os, sys, threading, time

parser = argparse.ArgumentParser()
parser.add_argument('model', nargs='?', default='/usr/share/assimp/models/Collada/duck.dae')
parser.add_argument('--views', type=int, default=os.cpu_count() or 2)
parser.add_argument('--size', type=int, default=512)
parser.add_argument('--rounds', type=int, default=5)
args = parser.parse_args()
import softraster  # noqa: E402

model = softraster.Model(args.model)
views = (['front', 'back', 'left', 'right', 'top', 'bottom', 'iso', 'three-quarter'] * 8)[:args.views]


def draw(view):
    model.render(size=args.size, view=view, threads=1)


def one_thread():
    for v in views:
        draw(v)


def many_threads():
    workers = [threading.Thread(target=draw, args=(v,)) for v in views]
    for t in workers:
        t.start()
    for t in workers:
        t.join()


def best(f):
    times = []
    for _ in range(args.rounds):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return sorted(times)[len(times) // 2]


draw(views[0])  # (warm up)
a, b = best(one_thread), best(many_threads)
print('%d views of %s at %dx%d, threads=1 each, median of %d rounds:' % (len(views), os.path.basename(args.model), args.size, args.size, args.rounds))
print('  one Python thread:  %.1f ms' % (a * 1000))
print('  %d Python threads:   %.1f ms  (%.2fx)' % (len(views), b * 1000, a / b))
