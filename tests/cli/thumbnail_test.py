#!/usr/bin/env python3
"""thumbnail_test.py SOFTRASTER CORPUS WORKDIR: `softraster thumbnail`, the freedesktop
thumbnailer's command: a PNG at the asked size whatever the output's name, the format read
from the bytes where the name lies, the size and time limits, and no partial output.

CORPUS is Debian's assimp-testmodels folder (/usr/share/assimp/models)."""
import os, shutil, subprocess, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from checks import check, failures, finish  # noqa: E402
from imgdiff import read_png  # noqa: E402

exe, corpus, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
GLB = os.path.join(corpus, 'glTF2', 'BoxTextured-glTF-Binary', 'BoxTextured.glb')
PLY = os.path.join(corpus, 'PLY', 'Wuson.ply')
FBX = os.path.join(corpus, 'FBX', 'spider.fbx')
STL = os.path.join(corpus, 'STL', 'Spider_binary.stl')



def run(*args, timeout=120):
    return subprocess.run([exe, 'thumbnail', *args], capture_output=True, text=True, timeout=timeout)


def a_thumbnail(path, size):
    """Whether `path` is a size x size PNG: transparent corners, an opaque model in the middle."""
    w, h, ch, pixels = read_png(path)
    alpha = pixels[3::4]
    opaque = alpha.count(255)
    return (w, h, ch) == (size, size, 4) and alpha[0] == 0 and alpha[-1] == 0 and opaque > size * size // 20


def left_nothing(out):
    return not os.path.exists(out) and not os.path.exists(out + '.tmp')


# Each format at the sizes file managers ask for; the output named anything.
for model, size, name in [(GLB, 128, 'a.png'), (PLY, 256, 'b.png'), (FBX, 64, 'c.jpg'), (STL, 100, 'no-extension')]:
    out = os.path.join(work, name)
    r = run('--size', str(size), model, out)
    check('thumbnail %s' % os.path.basename(model), r.returncode == 0 and a_thumbnail(out, size), '%d %r' % (r.returncode, r.stderr))

# A file whose extension lies, or that has none: read by its bytes, the same picture.
reference = os.path.join(work, 'reference.png')
run('--size', '96', GLB, reference)
for disguise in ['model.obj', 'model.stl', 'model', 'model.bin']:
    path = os.path.join(work, disguise)
    shutil.copy(GLB, path)
    out = os.path.join(work, disguise + '.png')
    r = run('--size', '96', path, out)
    check('a GLB named %s' % disguise, r.returncode == 0 and open(out, 'rb').read() == open(reference, 'rb').read(), r.stderr)
ply = os.path.join(work, 'mesh.fbx')
shutil.copy(PLY, ply)
r = run('--size', '48', ply, os.path.join(work, 'mesh.png'))
check('a PLY named .fbx', r.returncode == 0 and a_thumbnail(os.path.join(work, 'mesh.png'), 48), r.stderr)

# Bad input: one line naming the file and what is wrong, exit 2, nothing written.
garbage = os.path.join(work, 'garbage.glb')
open(garbage, 'wb').write(b'glTF\x02\x00\x00\x00' + os.urandom(200))
for args, want in [([GLB], '--max-file-size'), ([garbage], garbage), ([os.path.join(work, 'missing.glb')], 'file not found')]:
    out = os.path.join(work, 'bad.png')
    extra = ['--max-file-size', '0.001'] if want == '--max-file-size' else []
    r = run(*extra, *args, out)
    check('bad %s' % args, r.returncode == 2 and want in r.stderr and len(r.stderr.strip().splitlines()) == 1 and left_nothing(out),
          '%d %r' % (r.returncode, r.stderr))

# The time limit: a model that takes seconds to read (millions of faces), given one second.
slow = os.path.join(work, 'slow.obj')
with open(slow, 'wb') as f:
    f.write(b'v 0 0 0\nv 1 0 0\nv 0 1 0\n' + b'f 1 2 3\n' * 4000000)
out = os.path.join(work, 'slow.png')
r = run('--timeout', '1', slow, out)
check('timeout', r.returncode == 3 and '--timeout' in r.stderr and slow in r.stderr and left_nothing(out), '%d %r' % (r.returncode, r.stderr))
os.remove(slow)

finish()
