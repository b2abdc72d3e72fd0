#!/usr/bin/env python3
"""Thumbnails of one folder of models with softraster and with f3d, timed on the same machine.

  scripts/bench-thumbnails.py [--build build-release] [--models /usr/share/assimp/models]
                              [--size 256] [--jobs N] [--report docs/thumbnails.md]
                              [--sheet docs/thumbnails_sheet.png]

The models: every glTF, GLB, OBJ, FBX, STL, DAE, 3DS and PLY file under --models (Debian's
assimp-testmodels by default). softraster: one `softraster thumbnails` run over all of them.
f3d (Debian's, VTK through OpenGL, so Mesa llvmpipe here): `f3d FILE --output=OUT.png
--resolution=W,H` per file, --jobs at a time, on one Xvfb server started for the run.
Prints, for each tool, files per second and the number of good pictures (the tool exited 0
and its picture is not just background), and with --sheet writes a contact sheet: each
model's two pictures side by side (softraster left, f3d right; red where there is none)."""
import argparse, concurrent.futures, json, os, shutil, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'tests', 'tools'))
from imgdiff import PngError, read_png, write_png_rgb  # noqa: E402

EXTENSIONS = ('.gltf', '.glb', '.obj', '.fbx', '.stl', '.dae', '.3ds', '.ply')
MIN_COVERAGE = 0.002  # share of pixels that must differ from the background (the corner)


def good_picture(path):
    try:
        w, h, ch, pix = read_png(path)
    except (PngError, OSError):
        return False
    corner = pix[0:ch]
    differing = sum(1 for i in range(0, len(pix), ch) if pix[i:i + ch] != corner)
    return differing >= max(1, MIN_COVERAGE * w * h)


def run_softraster(exe, files, out, size, jobs):
    report = os.path.join(out, 'report.json')
    start = time.monotonic()
    subprocess.run([exe, 'thumbnails', *files, '--out', out, '--size', str(size), '--jobs', str(jobs), '--report', report,
                    '--quiet'], capture_output=True, text=True)
    seconds = time.monotonic() - start
    pictures = {}
    for e in json.load(open(report))['inputs']:
        pictures[e['input']] = e['output'] if e['status'] == 'ok' else None
    return seconds, pictures


def run_f3d(files, out, size, jobs):
    display = ':%d' % (90 + os.getpid() % 9)
    xvfb = subprocess.Popen(['Xvfb', display, '-screen', '0', '1280x1024x24', '-nolisten', 'tcp'],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(1.0)
    env = dict(os.environ, DISPLAY=display)

    def one(k_file):
        k, f = k_file
        target = os.path.join(out, '%04d.png' % k)
        try:
            r = subprocess.run(['f3d', f, '--output=' + target, '--resolution=%d,%d' % (size, size)], env=env,
                               capture_output=True, timeout=120)
            return f, target if r.returncode == 0 and os.path.exists(target) else None
        except subprocess.TimeoutExpired:
            return f, None

    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        pictures = dict(pool.map(one, enumerate(files)))
    seconds = time.monotonic() - start
    xvfb.terminate()
    xvfb.wait()
    return seconds, pictures


def contact_sheet(path, files, ours, theirs, tile, pairs_per_row=8):
    """Each model's pictures side by side, scaled down to `tile` pixels (nearest texel)."""
    rows = (len(files) + pairs_per_row - 1) // pairs_per_row
    gap = 4
    width = pairs_per_row * (2 * tile + gap) - gap
    height = rows * (tile + gap) - gap
    sheet = bytearray([24, 24, 28] * (width * height))

    def paste(picture, x0, y0):
        if picture is None:
            w = h = 0
        else:
            try:
                w, h, ch, pix = read_png(picture)
            except (PngError, OSError):
                picture, w, h = None, 0, 0
        for y in range(tile):
            row = (y0 + y) * width
            for x in range(tile):
                d = (row + x0 + x) * 3
                if picture is None:
                    sheet[d:d + 3] = b'\x90\x20\x20'
                else:
                    s = ((y * h // tile) * w + (x * w // tile)) * ch
                    sheet[d:d + 3] = pix[s:s + 3] if ch >= 3 else bytes([pix[s]] * 3)

    for k, f in enumerate(files):
        x0 = (k % pairs_per_row) * (2 * tile + gap)
        y0 = (k // pairs_per_row) * (tile + gap)
        paste(ours.get(f), x0, y0)
        paste(theirs.get(f), x0 + tile, y0)
    write_png_rgb(path, width, height, bytes(sheet))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', default=os.path.join(ROOT, 'build-release'))
    ap.add_argument('--models', default='/usr/share/assimp/models')
    ap.add_argument('--size', type=int, default=256)
    ap.add_argument('--jobs', type=int, default=os.cpu_count())
    ap.add_argument('--report')
    ap.add_argument('--sheet')
    a = ap.parse_args()
    for tool in ('f3d', 'Xvfb'):
        if not shutil.which(tool):
            sys.exit('%s not found: apt-get install f3d xvfb' % tool)
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.models) for f in fs if f.lower().endswith(EXTENSIONS))
    work = tempfile.mkdtemp(prefix='bench-thumbnails-')
    try:
        os.makedirs(os.path.join(work, 'f3d'))
        ours_s, ours = run_softraster(os.path.join(a.build, 'softraster'), files, os.path.join(work, 'softraster'), a.size, a.jobs)
        theirs_s, theirs = run_f3d(files, os.path.join(work, 'f3d'), a.size, a.jobs)
        ours_good = sum(1 for f in files if ours.get(f) and good_picture(ours[f]))
        theirs_good = sum(1 for f in files if theirs.get(f) and good_picture(theirs[f]))
        f3d_version = subprocess.run(['f3d', '--version'], capture_output=True, text=True).stdout.split('\n')[0].strip()
        rows = [('softraster thumbnails', ours_s, ours_good), (f3d_version or 'f3d', theirs_s, theirs_good)]
        lines = ['%d model files (%s under %s), %dx%d, %d jobs, %d cores:' % (
                     len(files), ', '.join(e[1:] for e in EXTENSIONS), a.models, a.size, a.size, a.jobs, os.cpu_count()),
                 '', '| tool | seconds | files per second | good pictures |', '|---|---|---|---|']
        for name, s, good in rows:
            lines.append('| %s | %.1f | %.1f | %d of %d |' % (name, s, len(files) / s, good, len(files)))
        lines += ['', 'softraster: %.1fx the files per second of f3d, %d more good pictures.' % (
            theirs_s / ours_s, ours_good - theirs_good)]
        text = '\n'.join(lines)
        print(text)
        if a.sheet:
            contact_sheet(a.sheet, files, ours, theirs, tile=64)
            print('contact sheet: %s' % a.sheet)
        if a.report:
            with open(a.report, 'w') as f:
                f.write('# Thumbnails against f3d\n\nMeasured by `scripts/bench-thumbnails.py --report %s%s` on %s.\n\n%s\n' % (
                    a.report, ' --sheet ' + a.sheet if a.sheet else '', time.strftime('%Y-%m-%d'), text))
                if a.sheet:
                    f.write('\nEvery model, softraster\'s picture left and f3d\'s right (red: no picture, the tool '
                            'failed on the file):\n\n![contact sheet](%s)\n' % os.path.relpath(a.sheet, os.path.dirname(a.report)))
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == '__main__':
    main()
