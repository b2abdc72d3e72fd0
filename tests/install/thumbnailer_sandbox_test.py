#!/usr/bin/env python3
"""thumbnailer_sandbox_test.py BUILD CORPUS WORKDIR: the installed thumbnailer run as GNOME
runs it, in bubblewrap: only /usr, read-only; no network, no $HOME, no display; the input
file alone under /tmp. It must draw glTF, GLB, OBJ, STL, PLY and FBX files there, and a
file whose sidecars (.mtl, .bin, textures) are out of reach untextured where it can. In the
same sandbox without /proc (a chroot or a minimal container has none), the installed program
finds its modules where they are installed: it writes a video through the FFmpeg module.

"Installed": `cmake --install` into a staging folder, laid over the system's /usr by an
overlay mount in a mount namespace of the test's own (unshare -m: the machine's /usr is
untouched), so that bubblewrap gets exactly GNOME's `--ro-bind /usr /usr`. That needs root
(CI runs as root); Debian 12's bubblewrap (0.8) has no overlay option of its own.

CORPUS is Debian's assimp-testmodels folder (/usr/share/assimp/models)."""
import base64, json, os, re, shlex, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from imgdiff import read_png  # noqa: E402

build, corpus, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
stage = os.path.join(work, 'stage')
subprocess.run(['cmake', '--install', build], check=True, capture_output=True, env=dict(os.environ, DESTDIR=stage))
prefix = re.search(r'^CMAKE_INSTALL_PREFIX:PATH=(.*)$', open(os.path.join(build, 'CMakeCache.txt')).read(), re.M).group(1)
if prefix != '/usr':
    sys.exit('the build must be configured with CMAKE_INSTALL_PREFIX=/usr (scripts/test.sh does), not %s' % prefix)
entry = open(os.path.join(stage, 'usr/share/thumbnailers/softraster.thumbnailer')).read()
exec_line = re.search(r'^Exec=(.*)$', entry, re.M).group(1)
failures = []


def drawn(path, size):
    """Whether the file is a size x size RGBA PNG with the model in it (a twentieth of it opaque)."""
    w, h, ch, pixels = read_png(path)
    return (w, h, ch) == (size, size, 4) and pixels[3::4].count(255) > size * size // 20


def sandbox(tmp, model, inside_in, proc=True):
    """gnome-desktop's thumbnail script's bubblewrap arguments (less its seccomp filter), run
    where /usr has the staged installation laid over it (proc: with /proc mounted)."""
    overlay = 'mount -t overlay overlay -o lowerdir=%s:/usr /usr && exec "$@"' % shlex.quote(os.path.join(stage, 'usr'))
    return ['unshare', '-m', 'sh', '-c', overlay, 'sh',
            'bwrap', '--ro-bind', '/usr', '/usr', '--ro-bind', '/etc/ld.so.cache', '/etc/ld.so.cache',
            '--symlink', 'usr/lib', '/lib', '--symlink', 'usr/lib64', '/lib64', '--symlink', 'usr/bin', '/bin',
            '--symlink', 'usr/sbin', '/sbin'] + (['--proc', '/proc'] if proc else []) + ['--dev', '/dev', '--chdir', '/',
            '--clearenv', '--setenv', 'PATH', '/usr/bin', '--setenv', 'GIO_USE_VFS', 'local',
            '--unshare-all', '--die-with-parent', '--bind', tmp, '/tmp', '--ro-bind', model, inside_in]


def thumbnail(model, ext, size=256):
    """Runs the Exec line as gnome-desktop's thumbnail script does; returns (result, output path)."""
    tmp = os.path.join(work, 'tmp-' + os.path.basename(model) + ext)
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    inside_in = '/tmp/gnome-desktop-file-to-thumbnail' + ext
    inside_out = '/tmp/gnome-desktop-thumbnailer.png'
    command = [w.replace('%i', inside_in).replace('%o', inside_out).replace('%s', str(size)) for w in shlex.split(exec_line)]
    r = subprocess.run(sandbox(tmp, model, inside_in) + command, capture_output=True, text=True, timeout=120)
    return r, os.path.join(tmp, 'gnome-desktop-thumbnailer.png')


# The sandbox is what we think it is: nothing but /usr and the input, no home, no display, no network.
tmp = os.path.join(work, 'probe')
os.makedirs(tmp)
model = os.path.join(corpus, 'PLY', 'Wuson.ply')
r = subprocess.run(sandbox(tmp, model, '/tmp/in.ply') +
                   ['sh', '-c', 'ls -A / /tmp; echo "HOME=$HOME DISPLAY=$DISPLAY"; tail -n +3 /proc/net/dev | cut -d: -f1'],
                   capture_output=True, text=True)
seen = r.stdout.split()
if r.returncode != 0 or 'HOME= DISPLAY=' not in r.stdout or seen[-1] != 'lo' or 'home' in seen or 'etc' not in seen or 'in.ply' not in seen:
    failures.append('the sandbox is not as GNOME makes it: %r %r' % (r.stdout, r.stderr))

box_gltf = os.path.join(corpus, 'glTF2', 'BoxTextured-glTF', 'BoxTextured.gltf')
# A glTF whose buffer is inside it (a data URI) but whose texture is a file beside it.
embedded = os.path.join(work, 'BoxBufferInside.gltf')
g = json.load(open(box_gltf))
for b in g['buffers']:
    b['uri'] = 'data:application/octet-stream;base64,' + base64.b64encode(
        open(os.path.join(os.path.dirname(box_gltf), b['uri']), 'rb').read()).decode()
json.dump(g, open(embedded, 'w'))
cases = [
    (os.path.join(corpus, 'glTF2', 'BoxTextured-glTF-Embedded', 'BoxTextured.gltf'), '.gltf'),
    (os.path.join(corpus, 'glTF2', 'BoxTextured-glTF-Binary', 'BoxTextured.glb'), '.glb'),
    (os.path.join(corpus, 'OBJ', 'spider.obj'), '.obj'),        # its .mtl and textures out of reach
    (os.path.join(corpus, 'STL', 'Spider_binary.stl'), '.stl'),
    (os.path.join(corpus, 'STL', 'Spider_ascii.stl'), '.stl'),
    (os.path.join(corpus, 'PLY', 'Wuson.ply'), '.ply'),
    (os.path.join(corpus, 'FBX', 'spider.fbx'), '.fbx'),
    (embedded, '.gltf'),                                        # its texture out of reach: untextured
    (os.path.join(corpus, 'glTF2', 'BoxTextured-glTF-Binary', 'BoxTextured.glb'), '.png'),  # a lying extension
]
for model, ext in cases:
    r, out = thumbnail(model, ext)
    if r.returncode != 0 or not os.path.exists(out) or not drawn(out, 256):
        failures.append('%s as %s: exit %d, %r' % (model, ext, r.returncode, r.stderr.strip()))
# A glTF whose geometry is in a .bin out of reach: nothing to draw, said in one line, no output.
r, out = thumbnail(box_gltf, '.gltf')
if r.returncode != 2 or os.path.exists(out) or len(r.stderr.strip().splitlines()) != 1:
    failures.append('glTF without its .bin: want exit 2 and no picture, got %d %r' % (r.returncode, r.stderr))

# No /proc: the program finds its FFmpeg module from the name it was started by.
tmp = os.path.join(work, 'no-proc')
os.makedirs(tmp)
r = subprocess.run(sandbox(tmp, os.path.join(corpus, 'glTF2', 'BoxTextured-glTF-Binary', 'BoxTextured.glb'), '/tmp/in.glb', proc=False) +
                   ['sh', '-c', 'test ! -e /proc/self/exe && exec softraster animate /tmp/in.glb --size 64 --fps 5 --duration 0.4 -o /tmp/box.mp4'],
                   capture_output=True, text=True, timeout=120)
video = os.path.join(tmp, 'box.mp4')
if r.returncode != 0 or not os.path.exists(video) or os.path.getsize(video) == 0:
    failures.append('a video without /proc: exit %d, %r' % (r.returncode, r.stderr.strip()))

for f in failures:
    print('FAIL:', f)
print('%d passed, %d failed' % (0 if failures else 1, len(failures)))
sys.exit(1 if failures else 0)
