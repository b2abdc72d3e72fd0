"""softraster.dask: pictures of many model files (folders of millions) on a Dask cluster.

    python3 -m softraster.dask [--scheduler tcp://HOST:8786] MODELS... --out DIR [--size 256]
    python3 -m softraster.dask MODELS... --out DIR --views 24 [-- --depth --mask]

or from Python:

    from softraster.dask import render_files
    report = render_files(["models/"], "thumbs/", client=client, size=256)

How the work is cut and why (docs/distributed.md):
  * One task is a batch of files (--batch, 64), not one file: Dask's scheduler spends
    hundreds of microseconds per task, as long as drawing a small model.
  * A batch is drawn by `softraster thumbnails` in a child process of the worker, which
    draws each file in a child of its own; with views, by one `softraster views` child per
    file. An importer that crashes fails one file, not the worker. The children are killed
    if the worker dies.
  * Pictures mirror the input tree under DIR: NAME.EXT.png, or with views a folder NAME.EXT/
    of `softraster views` (its cameras.json written last). Every file is written to a
    temporary name and renamed: it is either whole or absent. A file whose picture (or
    cameras.json) exists is skipped, so a task that Dask runs twice (a worker lost, a task
    stolen) draws nothing twice.
  * The report (DIR/report.json) gives each file's status (ok, failed, skipped), its
    reason and its time.
"""
import argparse
import ctypes
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

EXTENSIONS = ('.gltf', '.glb', '.obj', '.fbx', '.stl', '.ply', '.dae', '.3ds', '.off', '.x', '.blend', '.lwo', '.ms3d')


def find_models(inputs):
    """The model files that files, folders (searched recursively) and glob patterns name, sorted."""
    found, missing = set(), []
    for item in inputs:
        item = os.fspath(item)
        if os.path.isdir(item):
            for root, _, files in os.walk(item):
                found.update(os.path.join(root, f) for f in files if f.lower().endswith(EXTENSIONS))
        elif os.path.isfile(item):
            found.add(item)
        else:
            matches = glob.glob(item, recursive=True)
            if not matches:
                missing.append(item)
            found.update(m for m in matches if os.path.isfile(m))
    return sorted(os.path.abspath(f) for f in found), missing


def _root(files):
    """The deepest folder that holds all the files (as `softraster thumbnails` mirrors them)."""
    return os.path.commonpath([os.path.dirname(f) for f in files]) if files else ''


def output_for(path, root, out, views=None):
    """Where `path`'s picture goes: its place under `root`, under `out`, with .png added (with
    views: the folder of that name, without .png)."""
    return os.path.join(out, os.path.relpath(path, root) + ('' if views else '.png'))


def _done(output, views):
    return os.path.exists(os.path.join(output, 'cameras.json') if views else output)


def _die_with_parent():  # (in the child, before exec: SIGKILL when the worker goes)
    ctypes.CDLL('libc.so.6', use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG


def _render_views(path, output, program, options, views, timeout):
    """One file's views, in a child `softraster views`; its report entry."""
    started = time.monotonic()
    cmd = [program, 'views', path, '--out', output, '--count', str(views), *options]
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, preexec_fn=_die_with_parent, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {'input': path, 'output': output, 'status': 'failed', 'reason': 'timed out after %d s' % timeout}
    entry = {'input': path, 'output': output, 'ms': (time.monotonic() - started) * 1e3}
    if run.returncode == 0 and _done(output, views):
        return dict(entry, status='ok')
    reason = (run.stderr.strip().splitlines() or ['exit code %d' % run.returncode])[-1]
    return dict(entry, status='failed', reason=reason.removeprefix('softraster: error: '))


def render_batch(files, root, out, program='softraster', options=(), jobs=1, views=None, timeout=600):
    """Draws one batch in a child `softraster thumbnails` (with views: a child `softraster
    views` per file); returns each file's report entry.

    Files whose picture (or cameras.json) exists are skipped without starting anything."""
    todo = [f for f in files if not _done(output_for(f, root, out, views), views)]
    report = [{'input': f, 'output': output_for(f, root, out, views), 'status': 'skipped', 'reason': 'already drawn'}
              for f in files if f not in set(todo)]
    if not todo:
        return report
    if views:
        return report + [_render_views(f, output_for(f, root, out, views), program, options, views, timeout) for f in todo]
    # `thumbnails` mirrors files named one by one under their deepest shared folder; so the
    # batch's pictures land under `out` at that folder's place below `root`.
    shared = os.path.commonpath([os.path.dirname(f) for f in todo])
    with tempfile.TemporaryDirectory(prefix='softraster-batch-') as tmp:
        report_path = os.path.join(tmp, 'report.json')
        cmd = [program, 'thumbnails', *todo, '--out', os.path.join(out, os.path.relpath(shared, root)),
               '--report', report_path, '--skip-existing', '--quiet', '--jobs', str(jobs), *options]
        run = subprocess.run(cmd, capture_output=True, text=True, preexec_fn=_die_with_parent)
        if run.returncode not in (0, 1) or not os.path.exists(report_path):
            reason = (run.stderr.strip().splitlines() or ['exit code %d' % run.returncode])[-1]
            return report + [{'input': f, 'output': output_for(f, root, out), 'status': 'failed', 'reason': reason} for f in todo]
        with open(report_path) as file:
            entries = json.load(file)['inputs']
    for entry in entries:
        entry['input'] = os.path.abspath(entry['input'])
        entry['output'] = output_for(entry['input'], root, out)
    return report + entries


def _batches(files, size):
    return [files[i:i + size] for i in range(0, len(files), size)]


def render_files(inputs, out, client=None, batch=64, size=None, options=(), program=None, jobs=1, views=None,
                 progress=False):
    """Thumbnails of every model file that `inputs` (files, folders, globs) name, under `out`;
    with views=N, N views of each as `softraster views` draws them (options are then its
    options, e.g. ["--depth", "--mask"]).

    client: a dask.distributed Client (None: a LocalCluster on this machine, closed after).
    batch: files per task. size: picture size (N or "WxH"). options: more `softraster
    thumbnails` options, e.g. ["--view", "front"]. program: the softraster program the
    workers run (default: $SOFTRASTER_PROGRAM, or `softraster` on the PATH). jobs: files a
    task draws at once. progress: show Dask's progress bar.

    Returns the report: {"inputs": [each file's entry], "summary": {...}}, also written to
    out/report.json.
    """
    from dask.distributed import Client, LocalCluster, as_completed
    from dask.distributed import progress as show_progress

    program = program or os.environ.get('SOFTRASTER_PROGRAM') or shutil.which('softraster')
    if not program:
        raise FileNotFoundError('softraster: the program is not on the PATH (give program= or $SOFTRASTER_PROGRAM)')
    program = os.path.abspath(program) if os.sep in program else program
    files, missing = find_models(inputs)
    options = list(options) + (['--size', str(size)] if size is not None else [])
    os.makedirs(out, exist_ok=True)
    out = os.path.abspath(out)
    root = _root(files)
    started = time.monotonic()
    own = client is None
    if own:
        client = Client(LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True))
    try:
        futures = client.map(render_batch, _batches(files, batch), root=root, out=out, program=program,
                             options=options, jobs=jobs, views=views, pure=False, retries=2)
        if progress:
            show_progress(futures)
        entries = [e for future in as_completed(futures) for e in future.result()]
    finally:
        if own:
            client.close()
            client.cluster.close()
    entries += [{'input': m, 'status': 'failed', 'reason': 'no file matches'} for m in missing]
    entries.sort(key=lambda e: e['input'])
    seconds = time.monotonic() - started
    count = {s: sum(e['status'] == s for e in entries) for s in ('ok', 'failed', 'skipped')}
    report = {'inputs': entries, 'summary': dict(count, files=len(entries), seconds=seconds,
                                                   files_per_second=len(entries) / seconds if seconds > 0 else 0.0)}
    tmp = os.path.join(out, '.report.json.tmp')
    with open(tmp, 'w') as file:
        json.dump(report, file, indent=1)
    os.replace(tmp, os.path.join(out, 'report.json'))
    return report


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog='python3 -m softraster.dask',
        description='Pictures of many model files on a Dask cluster (or a LocalCluster on this machine).',
        epilog='More `softraster thumbnails` (or with --views, `softraster views`) options go after --, e.g. '
               '-- --view front --samples 8, or -- --depth --mask. '
               'Exit codes: 0 every file drawn or skipped, 1 some failed (see DIR/report.json), 2 bad usage.')
    parser.add_argument('models', nargs='+', help='model files, folders (searched recursively) and glob patterns')
    parser.add_argument('--out', required=True, help='output folder; pictures mirror the input tree as NAME.EXT.png')
    parser.add_argument('--scheduler', help='the scheduler\'s address, e.g. tcp://HOST:8786 (default: a LocalCluster)')
    parser.add_argument('--workers', type=int, default=os.cpu_count() or 1, help='LocalCluster worker processes (default: one per core)')
    parser.add_argument('--batch', type=int, default=64, help='files per task (default 64)')
    parser.add_argument('--size', help='picture size N or WxH (default: thumbnails 256, views 512)')
    parser.add_argument('--views', type=int, help='N views of each model (`softraster views`) instead of one thumbnail')
    parser.add_argument('--program', help='the softraster program the workers run (default: $SOFTRASTER_PROGRAM or the PATH\'s)')
    parser.add_argument('--quiet', action='store_true', help='no progress bar')
    args, extra = parser.parse_known_args(argv)
    if extra and extra[0] == '--':
        extra = extra[1:]
    elif extra:
        parser.error('unrecognized arguments: %s' % ' '.join(extra))
    if args.batch < 1 or args.workers < 1:
        parser.error('--batch and --workers must be at least 1')
    if args.views is not None and args.views < 1:
        parser.error('--views must be at least 1')
    from dask.distributed import Client, LocalCluster
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None))
    try:
        report = render_files(args.models, args.out, client=client, batch=args.batch, size=args.size, options=extra,
                              program=args.program, views=args.views, progress=not args.quiet)
    except FileNotFoundError as e:
        print(e, file=sys.stderr)
        return 2
    finally:
        client.close()
        if not args.scheduler:
            client.cluster.close()
    for e in report['inputs']:
        if e['status'] == 'failed':
            print('failed  %s: %s' % (e['input'], e.get('reason', '')), file=sys.stderr)
    s = report['summary']
    print('%d files: %d drawn, %d failed, %d skipped in %.1f s (%.1f files/s); report: %s'
          % (s['files'], s['ok'], s['failed'], s['skipped'], s['seconds'], s['files_per_second'],
             os.path.join(args.out, 'report.json')), file=sys.stderr)
    return 1 if s['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
