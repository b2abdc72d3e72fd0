#!/usr/bin/env python3
"""commands_test.py SOFTRASTER EXAMPLE WORKDIR: --help texts, the showcase, the example."""
import os, shutil, subprocess, sys, zlib, struct

exe, example, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def run(args):
    return subprocess.run(args, capture_output=True, text=True, timeout=120)


def png_size(path):
    with open(path, 'rb') as f:
        data = f.read(24)
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path
    return struct.unpack('>II', data[16:24])


r = run([exe, '--help'])
if r.returncode != 0 or 'render' not in r.stdout or 'showcase' not in r.stdout:
    failures.append('softraster --help: %d %s' % (r.returncode, r.stdout[:200]))
r = run([exe, 'render', '--help'])
if r.returncode != 0 or '--output' not in r.stdout:
    failures.append('softraster render --help: %d' % r.returncode)
r = run([exe])
if r.returncode != 2 or len(r.stderr.strip().split('\n')) != 1:
    failures.append('no subcommand should exit 2 with one line: %d %r' % (r.returncode, r.stderr))

out = os.path.join(work, 'showcase.png')
r = run([exe, 'showcase', '-o', out])
if r.returncode != 0 or png_size(out) != (960, 540):
    failures.append('showcase: %d %s' % (r.returncode, r.stderr))
r = run([exe, 'showcase', '-o', os.path.join(work, 'no_such_dir', 'x.png')])
if r.returncode != 2:
    failures.append('showcase into a missing folder should exit 2, got %d' % r.returncode)

out = os.path.join(work, 'triangle.png')
r = run([example, out])
if r.returncode != 0 or png_size(out) != (480, 360):
    failures.append('example: %d %s' % (r.returncode, r.stderr))

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('commands behave')
