#!/usr/bin/env python3
"""dask_test.py SOFTRASTER PYTHON_DIR CORPUS WORKDIR: softraster.dask on a LocalCluster of two
worker processes over every glTF, GLB, OBJ, FBX, STL, DAE, 3DS and PLY file of Debian's
assimp-testmodels (the files of cli/thumbnails_corpus_test.py).

  * The cluster's pictures and statuses are those of one `softraster thumbnails` run over the
    same files, byte for byte; the known-bad files fail with their reason.
  * Again with one worker killed partway: every file is reported once, every picture is
    there and the same, and nothing half-written is left.
  * A second run over the same folder draws nothing: every picture is skipped.
  * The command `python3 -m softraster.dask`."""
import json, os, shutil, signal, subprocess, sys, threading, time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from checks import check, failures, finish  # noqa: E402

# (Dask's worker processes import this file again as __mp_main__: nothing runs at import.)
sys.path.insert(0, sys.argv[2] if len(sys.argv) > 2 else '')
from dask.distributed import Client, LocalCluster  # noqa: E402
from softraster.dask import render_files  # noqa: E402

EXTENSIONS = ('.gltf', '.glb', '.obj', '.fbx', '.stl', '.dae', '.3ds', '.ply')



def main(exe, python_dir, corpus, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    files = sorted(os.path.join(root, f) for root, _, names in os.walk(corpus) for f in names if f.lower().endswith(EXTENSIONS))
    check('corpus', len(files) >= 140, len(files))

    # The reference: one `softraster thumbnails` run.
    ref_dir = os.path.join(work, 'reference')
    subprocess.run([exe, 'thumbnails', *files, '--out', ref_dir, '--quiet', '--size', '64'], capture_output=True)
    reference = {os.path.abspath(e['input']): e for e in json.load(open(os.path.join(ref_dir, 'thumbnails.json')))['inputs']}
    root = os.path.commonpath([os.path.dirname(f) for f in files])


    def picture(out, f):
        path = os.path.join(out, os.path.relpath(f, root) + '.png')
        return open(path, 'rb').read() if os.path.exists(path) else None


    def same_as_reference(name, out, report):
        by_input = {}
        for e in report['inputs']:
            by_input.setdefault(e['input'], []).append(e)
        check(name + ': each file once', sorted(by_input) == sorted(files) and all(len(v) == 1 for v in by_input.values()),
              [k for k, v in by_input.items() if len(v) != 1])
        for f in files:
            want, got = reference[f], by_input.get(f, [{}])[0]
            drawn = want['status'] == 'ok'
            if drawn != (got.get('status') in ('ok', 'skipped')) or (not drawn and got.get('reason') != want.get('reason')):
                failures.append('%s: %s is %s (%s), not %s' % (name, f, got.get('status'), got.get('reason'), want['status']))
            elif drawn and picture(out, f) != picture(ref_dir, f):
                failures.append('%s: %s picture differs from the reference' % (name, f))
        leftovers = [os.path.join(d, n) for d, _, names in os.walk(out) for n in names if n.endswith('.tmp')]
        check(name + ': nothing half-written', not leftovers, leftovers)


    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(cluster)
    try:
        out = os.path.join(work, 'run')
        report = render_files(files, out, client=client, batch=16, size=64, program=exe)
        same_as_reference('cluster', out, report)
        s = report['summary']
        check('summary', s['ok'] == sum(e['status'] == 'ok' for e in reference.values()) and s['failed'] > 10 and s['skipped'] == 0, s)
        check('report.json', json.load(open(os.path.join(out, 'report.json')))['summary']['files'] == len(files))
        again = render_files(files, out, client=client, batch=16, size=64, program=exe)
        check('a second run skips every picture', again['summary']['ok'] == 0 and again['summary']['skipped'] == s['ok'], again['summary'])

        # Views: a folder per model, its cameras.json last; a bad file fails alone.
        out = os.path.join(work, 'views')
        some = [os.path.join(corpus, 'Collada', 'duck.dae'), os.path.join(corpus, 'invalid', 'empty.obj'), os.path.join(corpus, 'OBJ', 'spider.obj')]
        report = render_files(some, out, client=client, batch=2, size=32, views=2, options=['--depth'], program=exe)
        status = {os.path.basename(e['input']): e for e in report['inputs']}
        check('views', [status[n]['status'] for n in ('duck.dae', 'empty.obj', 'spider.obj')] == ['ok', 'failed', 'ok']
              and 'too small' in status['empty.obj']['reason']
              and len(json.load(open(os.path.join(status['duck.dae']['output'], 'cameras.json')))['views']) == 2
              and os.path.exists(os.path.join(status['spider.obj']['output'], '001_depth.exr'))
              and not os.path.exists(os.path.join(out, 'invalid')), report['inputs'])
        again = render_files(some, out, client=client, batch=2, size=32, views=2, options=['--depth'], program=exe)
        check('views skipped', again['summary']['skipped'] == 2 and again['summary']['failed'] == 1, again['summary'])

        # One worker killed partway (its process, with SIGKILL: as a machine lost). The nanny
        # starts another; the lost batches run again and skip what was already written.
        out = os.path.join(work, 'killed')
        pids = client.run(os.getpid)
        victim = sorted(pids.values())[0]

        def kill_when_started():
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                done = sum(n.endswith('.png') for _, _, names in os.walk(out) for n in names) if os.path.isdir(out) else 0
                if done >= 10:
                    os.kill(victim, signal.SIGKILL)
                    return
                time.sleep(0.005)
        killer = threading.Thread(target=kill_when_started)
        killer.start()
        report = render_files(files, out, client=client, batch=4, size=64, program=exe)
        killer.join()
        check('the worker was killed', victim not in client.run(os.getpid).values())
        same_as_reference('killed worker', out, report)
    finally:
        client.close()
        cluster.close()

    # The command, with its own LocalCluster; bad usage exits 2.
    out = os.path.join(work, 'command')
    env = dict(os.environ, PYTHONPATH=python_dir, SOFTRASTER_PROGRAM=exe)
    r = subprocess.run([sys.executable, '-m', 'softraster.dask', *files[:20], '--out', out, '--workers', '2', '--quiet', '--', '--size', '32'],
                       capture_output=True, text=True, env=env)
    check('command', r.returncode in (0, 1) and '20 files' in r.stderr and os.path.exists(os.path.join(out, 'report.json')), r.stderr)
    r = subprocess.run([sys.executable, '-m', 'softraster.dask', files[0], '--out', out, '--batch', '0'], capture_output=True, text=True, env=env)
    check('bad usage', r.returncode == 2 and 'batch' in r.stderr, r.stderr)

    finish()


if __name__ == '__main__':
    main(*sys.argv[1:5])
