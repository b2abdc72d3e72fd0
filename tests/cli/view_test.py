#!/usr/bin/env python3
"""view_test.py SOFTRASTER WORKDIR: `softraster view` in a virtual X server (Xvfb).

Keys are sent with xdotool; the screenshot key writes the exact frame shown, which must be
byte-identical to `render` of the same view: two presses of the right arrow turn the scene
by 30 degrees (render --turntable 24 --time 2), `s` switches pbr to lambert. The window
survives a broken scene file (the last good scene stays, and the mended file is drawn with
the view kept) and a resize. What the window shows, read back from the X server with xwd,
is that frame pixel for pixel above a status line of light text. Without a display, or
without the window module: one line, exit 2. (One window for all of
it: a second window in the same virtual display sometimes went unfound under load.)"""
import json, re, os, shutil, struct, subprocess, sys, time

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'tools'))
from checks import check, failures  # noqa: E402
import imgdiff  # noqa: E402



def same(a, b):
    try:
        return open(a, 'rb').read() == open(b, 'rb').read()
    except OSError:
        return False


def render(out, *args):
    r = subprocess.run([exe, 'render'] + list(args) + ['-o', out], capture_output=True, text=True, timeout=120)
    check('render %s' % (args,), r.returncode == 0, r.stderr)


# No display.
env = {k: v for k, v in os.environ.items() if k not in ('DISPLAY', 'WAYLAND_DISPLAY', 'SDL_VIDEODRIVER')}
r = subprocess.run([exe, 'view', os.path.join(HERE, '..', 'scenes', 'models', 'normal_mapped.gltf')], capture_output=True, text=True,
                   timeout=60, env=env)
check('no display: exit 2, one line', r.returncode == 2 and 'animate' in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr)
# The program alone, without its window module (src/io/modules.h): one line that names the
# module and how to point at it, exit 2.
alone = os.path.join(work, 'alone')
os.makedirs(alone)
shutil.copy2(exe, alone)
r = subprocess.run([os.path.join(alone, os.path.basename(exe)), 'view', os.path.join(HERE, '..', 'scenes', 'models', 'normal_mapped.gltf')],
                   capture_output=True, text=True, timeout=60, env={k: v for k, v in env.items() if k not in ('SOFTRASTER_MODULE_DIR', 'LD_LIBRARY_PATH')})
check('no window module: exit 2, one line', r.returncode == 2 and 'libsoftraster_window.so' in r.stderr and 'SOFTRASTER_MODULE_DIR' in r.stderr
      and len(r.stderr.strip().splitlines()) == 1, r.stderr)

# A virtual display: Xvfb picks a free number and writes it to the pipe (nothing if it could
# not start: then again).
for attempt in range(5):
    read_fd, write_fd = os.pipe()
    xvfb = subprocess.Popen(['Xvfb', '-displayfd', str(write_fd), '-screen', '0', '800x600x24', '-nolisten', 'tcp'],
                            pass_fds=(write_fd,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_fd)
    number = b''
    while not number.endswith(b'\n'):
        chunk = os.read(read_fd, 16)
        if not chunk:
            break
        number += chunk
    os.close(read_fd)
    if number.strip():
        break
    xvfb.wait()
    time.sleep(1)
display = ':' + number.decode().strip()
xenv = dict(env, DISPLAY=display)
# Under AddressSanitizer: libdbus and the X11 libraries SDL loads keep a few blocks to the
# end (not softraster's); memory errors are still caught, leaks are not counted here.
if 'ASAN_OPTIONS' in xenv:
    xenv['ASAN_OPTIONS'] += ':detect_leaks=0'


def xdotool(*args):
    return subprocess.run(['xdotool'] + list(args), capture_output=True, text=True, timeout=30, env=xenv).stdout.strip()


def start_view(input_path, shots, *args):
    os.makedirs(shots, exist_ok=True)
    p = subprocess.Popen([exe, 'view', input_path, '--screenshots', shots] + list(args), env=xenv, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    start = time.time()
    while time.time() - start < 60:
        ids = xdotool('search', '--name', 'softraster view')
        if ids:
            time.sleep(0.5)  # (mapped and taking input)
            return p, ids.split()[0]
        if p.poll() is not None:
            break
        time.sleep(0.05)
    p.kill()
    failures.append('view %s: no window after %.1f s (exit %s): %s' % (input_path, time.time() - start, p.poll(), p.communicate()[1][-300:]))
    return p, None


def window_pixels(window):
    """The window's content as the X server holds it (xwd's dump): width, height, rows of (r, g, b)."""
    data = subprocess.run(['xwd', '-id', window, '-silent'], capture_output=True, timeout=30, env=xenv).stdout
    if len(data) < 100:
        return 0, 0, []
    f = struct.unpack('>25I', data[:100])
    header, width, height, byte_order, bpp, line = f[0], f[4], f[5], f[7], f[11], f[12]
    masks, ncolors = f[14:17], f[19]
    at = header + 12 * ncolors
    if bpp != 32:
        return 0, 0, []
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            v = struct.unpack('<I' if byte_order == 0 else '>I', data[at + y * line + 4 * x:at + y * line + 4 * x + 4])[0]
            row.append(tuple((v & m) >> (m & -m).bit_length() - 1 for m in masks))
        rows.append(row)
    return width, height, rows


def screenshot(window, shots, n, *keys):
    path = os.path.join(shots, 'softraster-view-%03d.png' % n)
    xdotool('key', '--window', window, *(list(keys) + ['p']))
    for _ in range(400):
        if os.path.exists(path):
            time.sleep(0.1)
            return path
        time.sleep(0.05)
    return path


def write_scene(path, background, shading):
    with open(path + '.tmp', 'w') as f:
        json.dump({'version': 2, 'image': {'width': 96, 'height': 64, 'background': background},
                   'camera': {'eye': [1.6, 1.3, 2.6], 'target': [0, 0, 0]},
                   'lights': {'ambient': [0.2, 0.2, 0.2], 'directional': [{'direction': [-0.4, -1, -0.6], 'color': [0.9, 0.9, 0.9]}]},
                   'objects': [{'builtin': {'type': 'cube'}, 'material': {'shading': shading, 'color': [0.9, 0.5, 0.2, 1],
                                                                          'roughness': 0.4}},
                               {'builtin': {'type': 'plane', 'size': 3}, 'transform': {'translate': [0, -0.5, 0]},
                                'material': {'shading': shading}}]}, f)
    os.replace(path + '.tmp', path)


# One window on a scene file: turned, shaded, broken and mended on disk, resized, closed.
try:
    scene = os.path.join(work, 'scene.json')
    write_scene(scene, [0, 0, 0.4, 1], 'pbr')
    shots = os.path.join(work, 'shots')
    view, window = start_view(scene, shots)
    check('window opens', window is not None)
    if window:
        turned = screenshot(window, shots, 0, 'Right', 'Right')
        render(os.path.join(work, 'turned.png'), scene, '--turntable', '24', '--time', '2')
        check('two right arrows = render --turntable 24 --time 2', same(turned, os.path.join(work, 'turned.png')))
        # The window shows that frame, and below it the status line in DejaVu Sans.
        w, h, shown = window_pixels(window)
        pw, ph, ch, pix = imgdiff.read_png(turned)
        frame = [[tuple(pix[(y * pw + x) * ch:(y * pw + x) * ch + 3]) for x in range(pw)] for y in range(ph)]
        check('the window shows the frame', w == pw and h > ph and [r[:pw] for r in shown[:ph]] == frame, (w, h, pw, ph))
        text = sum(1 for r in shown[ph:] for p in r if min(p) > 150)
        check('the status line has text', text > 100, text)
        lambert = screenshot(window, shots, 1, 's')
        write_scene(os.path.join(work, 'lambert.json'), [0, 0, 0.4, 1], 'lambert')
        render(os.path.join(work, 'lambert.png'), os.path.join(work, 'lambert.json'), '--turntable', '24', '--time', '2')
        check('s = lambert shading', same(lambert, os.path.join(work, 'lambert.png')) and not same(lambert, turned))
        time.sleep(1.1)  # (file times: a new second)
        with open(scene, 'w') as f:
            f.write('{"version": 2, "image": ')
        time.sleep(1.0)
        broken = screenshot(window, shots, 2)
        check('a broken file keeps the last good scene', same(lambert, broken) and view.poll() is None)
        time.sleep(1.1)
        write_scene(scene, [0.4, 0, 0, 1], 'pbr')
        time.sleep(1.0)
        mended = screenshot(window, shots, 3)
        write_scene(os.path.join(work, 'mended.json'), [0.4, 0, 0, 1], 'lambert')
        render(os.path.join(work, 'mended.png'), os.path.join(work, 'mended.json'), '--turntable', '24', '--time', '2')
        check('the mended file is drawn (the view kept)', same(mended, os.path.join(work, 'mended.png')))
        xdotool('windowsize', window, '160', '142')
        time.sleep(0.5)
        shot = screenshot(window, shots, 4)
        w, h = (0, 0)
        if os.path.exists(shot):
            data = open(shot, 'rb').read(24)
            w, h = int.from_bytes(data[16:20], 'big'), int.from_bytes(data[20:24], 'big')
        check('resized: the frame follows the window', (w, h) == (160, 120) and view.poll() is None, (w, h))
        xdotool('key', '--window', window, 'q')
        try:
            code = view.wait(timeout=30)
            check('q quits', code == 0, '(exit %s) %s' % (code, view.stderr.read()[-600:]))
        except subprocess.TimeoutExpired:
            check('q quits', False, '(still running after 30 s)')
    view.kill()
    # The measured orbit (docs/performance.md): it draws its frames and quits by itself.
    r = subprocess.run([exe, 'view', scene, '--orbit-frames', '12'], env=xenv, capture_output=True, text=True, timeout=120)
    check('--orbit-frames prints the rate and quits', r.returncode == 0 and re.fullmatch(r'12 frames in [0-9.]+ s: [0-9.]+ frames/s\n', r.stdout),
          (r.returncode, r.stdout, r.stderr[-300:]))
finally:
    xvfb.terminate()  # (SIGTERM: the server removes its lock file)
    xvfb.wait()

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('ok')
