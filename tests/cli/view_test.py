#!/usr/bin/env python3
"""view_test.py SOFTRASTER WORKDIR: `softraster view` in a virtual X server (Xvfb).

Keys are sent with xdotool; the screenshot key writes the exact frame shown, which must be
byte-identical to `render` of the same view: two presses of the right arrow turn the model
by 30 degrees (render --turntable 24 --time 2), `s` switches to lambert (render --shading
lambert). The window survives a resize and a broken scene file (the last good scene
stays, and a fixed file is drawn again). Without a display: one line, exit 2."""
import json, os, shutil, subprocess, sys, time

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
HERE = os.path.dirname(os.path.abspath(__file__))
MODEL = os.path.join(HERE, '..', 'scenes', 'models', 'normal_mapped.gltf')
failures = []


def check(name, ok, detail=''):
    if not ok:
        failures.append('%s %s' % (name, detail))


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
r = subprocess.run([exe, 'view', MODEL], capture_output=True, text=True, timeout=60, env=env)
check('no display: exit 2, one line', r.returncode == 2 and 'animate' in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr)

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


def screenshot(window, shots, n, *keys):
    path = os.path.join(shots, 'softraster-view-%03d.png' % n)
    xdotool('key', '--window', window, *(list(keys) + ['p']))
    for _ in range(400):
        if os.path.exists(path):
            time.sleep(0.1)
            return path
        time.sleep(0.05)
    return path


try:
    shots = os.path.join(work, 'model_shots')
    view, window = start_view(MODEL, shots, '--size', '96x64', '--samples', '1')
    check('window opens', window is not None)
    if window:
        shot = screenshot(window, shots, 0, 'Right', 'Right')
        render(os.path.join(work, 'turned.png'), MODEL, '--size', '96x64', '--samples', '1', '--turntable', '24', '--time', '2')
        check('two right arrows = render --turntable 24 --time 2', same(shot, os.path.join(work, 'turned.png')))
        shot = screenshot(window, shots, 1, 's')
        render(os.path.join(work, 'lambert.png'), MODEL, '--size', '96x64', '--samples', '1', '--turntable', '24', '--time', '2',
               '--shading', 'lambert')
        check('s = render --shading lambert', same(shot, os.path.join(work, 'lambert.png')))
        xdotool('windowsize', window, '160', '142')
        time.sleep(0.5)
        shot = screenshot(window, shots, 2)
        w, h = (0, 0)
        if os.path.exists(shot):
            data = open(shot, 'rb').read(24)
            w, h = int.from_bytes(data[16:20], 'big'), int.from_bytes(data[20:24], 'big')
        check('resized: the frame follows the window', (w, h) == (160, 120) and view.poll() is None, (w, h))
        xdotool('key', '--window', window, 'q')
        try:
            check('q quits', view.wait(timeout=30) == 0)
        except subprocess.TimeoutExpired:
            check('q quits', False)
    view.kill()

    # A scene file that breaks and is mended while the window is open.
    scene = os.path.join(work, 'scene.json')

    def write_scene(background):
        with open(scene + '.tmp', 'w') as f:
            json.dump({'version': 1, 'image': {'width': 64, 'height': 48, 'background': background},
                       'camera': {'eye': [1.5, 1.2, 2.5], 'target': [0, 0, 0]},
                       'objects': [{'builtin': {'type': 'cube'}, 'material': {'shading': 'normals'}}]}, f)
        os.replace(scene + '.tmp', scene)

    write_scene([0, 0, 0.5, 1])
    shots = os.path.join(work, 'scene_shots')
    view, window = start_view(scene, shots)
    check('scene window opens', window is not None)
    if window:
        first = screenshot(window, shots, 0)
        time.sleep(1.1)  # (file times: a new second)
        with open(scene, 'w') as f:
            f.write('{"version": 1, "image": ')
        time.sleep(1.0)
        broken = screenshot(window, shots, 1)
        check('a broken file keeps the last good scene', same(first, broken) and view.poll() is None)
        time.sleep(1.1)
        write_scene([0.5, 0, 0, 1])
        time.sleep(1.0)
        mended = screenshot(window, shots, 2)
        render(os.path.join(work, 'mended.png'), scene)
        check('the mended file is drawn', same(mended, os.path.join(work, 'mended.png')) and not same(mended, first))
        xdotool('key', '--window', window, 'Escape')
        try:
            view.wait(timeout=30)
        except subprocess.TimeoutExpired:
            pass
    view.kill()
finally:
    xvfb.terminate()  # (SIGTERM: the server removes its lock file)
    xvfb.wait()

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('ok')
