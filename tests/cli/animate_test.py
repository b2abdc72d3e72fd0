#!/usr/bin/env python3
"""animate_test.py SOFTRASTER WORKDIR: `softraster animate` and `render --time [--turntable]`.

Numbered PNG frames are exact: frame k is byte-identical to `render` at time k / fps. Videos
and GIFs are read back with ffprobe (frame count, duration, codec) and a frame of the video
extracted with ffmpeg is compared with `render` at its time (within the codec's loss). GIF
frame delays and the loop block are read from the file itself. Bad outputs are refused
before anything is rendered and leave no file."""
import base64, json, os, shutil, struct, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'tools'))
from checks import check, failures  # noqa: E402
import imgdiff  # noqa: E402

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
MODEL = os.path.join(HERE, '..', 'scenes', 'models', 'normal_mapped.gltf')
COMMON = ['--turntable', '2', '--fps', '10', '--size', '96x64', '--samples', '1']


def run(args, cwd=work):
    return subprocess.run([exe] + args, capture_output=True, text=True, timeout=300, cwd=cwd)



def probe(path):
    r = subprocess.run(['ffprobe', '-v', 'error', '-count_frames', '-show_entries',
                        'stream=codec_name,nb_read_frames,width,height:format=duration', '-of', 'json', path],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return None
    j = json.loads(r.stdout)
    s = j['streams'][0]
    return s['codec_name'], int(s['nb_read_frames']), float(j['format']['duration']), s['width'], s['height']


def psnr(a, b):
    line, _ = imgdiff.compare(a, b)
    return json.loads(line)['psnr_db']


# Numbered pictures: 20 frames (2 s at 10 fps); frames 0, 3 and 7 equal render at 0, 0.3, 0.7 s.
r = run(['animate', MODEL, '-o', 'frames/%03d.png'] + COMMON)
check('animate png frames', r.returncode == 0, r.stderr)
names = sorted(os.listdir(os.path.join(work, 'frames'))) if os.path.isdir(os.path.join(work, 'frames')) else []
check('20 numbered frames', names == ['%03d.png' % k for k in range(20)], names)
for k in (0, 3, 7):
    target = 'render_%d.png' % k
    r = run(['render', MODEL, '-o', target, '--time', '%g' % (k / 10)] + [a for a in COMMON if a not in ('--fps', '10')])
    check('render --time %g' % (k / 10), r.returncode == 0, r.stderr)
    with open(os.path.join(work, target), 'rb') as a, open(os.path.join(work, 'frames', '%03d.png' % k), 'rb') as b:
        check('frame %d is render --time' % k, a.read() == b.read())
r = run(['render', MODEL, '-o', 'plain.png', '--size', '96x64', '--samples', '1'])
with open(os.path.join(work, 'plain.png'), 'rb') as a, open(os.path.join(work, 'frames', '000.png'), 'rb') as b:
    check('frame 0 is the plain render', a.read() == b.read())
with open(os.path.join(work, 'render_3.png'), 'rb') as a, open(os.path.join(work, 'plain.png'), 'rb') as b:
    check('the model turns', a.read() != b.read())

# Videos: codec, frame count and duration read back; frame 5 within the codec's loss of render at 0.5 s.
for name, codec in (('spin.mp4', 'h264'), ('spin.webm', 'vp9')):
    r = run(['animate', MODEL, '-o', name] + COMMON)
    check('animate ' + name, r.returncode == 0, r.stderr)
    got = probe(os.path.join(work, name))
    check(name + ' read back', got is not None and got[0] == codec and got[1] == 20 and abs(got[2] - 2.0) < 1e-3 and got[3:] == (96, 64), got)
    still = name + '.5.png'
    subprocess.run(['ffmpeg', '-v', 'error', '-y', '-i', os.path.join(work, name), '-vf', r'select=eq(n\,5)', '-frames:v', '1',
                    os.path.join(work, still)], check=False)
    r = run(['render', MODEL, '-o', 'render_5.png', '--time', '0.5'] + [a for a in COMMON if a not in ('--fps', '10')])
    p = psnr(os.path.join(work, 'render_5.png'), os.path.join(work, still)) if os.path.exists(os.path.join(work, still)) else 0
    check(name + ' frame 5 is render --time 0.5 (PSNR %.1f)' % p, p > 30, p)
    check(name + ' no temporary left', not os.path.exists(os.path.join(work, name + '.part')))


# GIF: 20 frames, each 10/100 s, looping; read from the blocks of the file.
def gif_blocks(path):
    data = open(path, 'rb').read()
    assert data[:6] == b'GIF89a', data[:6]
    flags = data[10]
    at = 13 + (3 * 2 ** ((flags & 7) + 1) if flags & 0x80 else 0)
    frames, delays, loops = 0, [], False

    def skip_sub_blocks(i):
        while data[i]:
            i += data[i] + 1
        return i + 1

    while data[at] != 0x3B:
        if data[at] == 0x21:  # extension
            label = data[at + 1]
            if label == 0xF9:
                delays.append(struct.unpack('<H', data[at + 4:at + 6])[0])
            if label == 0xFF and data[at + 3:at + 14] == b'NETSCAPE2.0':
                loops = True
            at = skip_sub_blocks(at + 2)
        elif data[at] == 0x2C:  # image
            frames += 1
            packed = data[at + 9]
            at += 10 + (3 * 2 ** ((packed & 7) + 1) if packed & 0x80 else 0)
            at = skip_sub_blocks(at + 1)  # LZW minimum code size, then the data
        else:
            raise ValueError('bad block %#x at %d' % (data[at], at))
    return frames, delays, loops


r = run(['animate', MODEL, '-o', 'spin.gif'] + COMMON)
check('animate gif', r.returncode == 0, r.stderr)
try:
    frames, delays, loops = gif_blocks(os.path.join(work, 'spin.gif'))
    check('gif frames and delays', frames == 20 and delays == [10] * 20 and loops, (frames, delays, loops))
except (OSError, ValueError, AssertionError, IndexError) as e:
    check('gif readable', False, e)
# 30 fps: delays of 3 and 4 hundredths keep the total on time (20 frames = 2/3 s).
r = run(['animate', MODEL, '-o', 'fast.gif', '--fps', '30', '--duration', '0.6667', '--size', '32', '--samples', '1'])
frames, delays, _ = gif_blocks(os.path.join(work, 'fast.gif')) if r.returncode == 0 else (0, [], False)
check('gif at 30 fps', frames == 20 and set(delays) == {3, 4} and sum(delays) == 67, (r.stderr, frames, delays))

# Bad outputs and flags: one line, exit 2, nothing written.
for args, what in [(['-o', 'spin.avi'], 'spin.avi'), (['-o', 'f/%d_%d.png'], '%d'), (['-o', 'odd.mp4', '--size', '95x64'], 'even'),
                   (['-o', 'x.gif', '--fps', '0'], '--fps'), (['-o', 'x.gif', '--turntable', '0'], '--turntable')]:
    r = run(['animate', MODEL] + args)
    target = os.path.join(work, args[1])
    check('animate %s' % args, r.returncode == 2 and what in r.stderr and len(r.stderr.strip().splitlines()) == 1
          and not os.path.exists(target) and not os.path.exists(target + '.part'), '%d %r' % (r.returncode, r.stderr))
# Outputs that cannot be written (a folder that is not there; /proc, where no file can be
# made, even by root): exit 2 and one line, no file left, and under ASan no leak of the
# encoders' objects (a leak report would change the exit code).
for out, what in [('nodir/x.mp4', 'does not exist'), ('nodir/x.gif', 'does not exist'),
                  ('/proc/softraster_test.mp4', 'cannot write'), ('/proc/softraster_test.gif', 'cannot write'),
                  ('/proc/softraster_test/%02d.png', 'softraster_test')]:
    r = run(['animate', MODEL, '-o', out] + COMMON)
    check('animate -o %s' % out, r.returncode == 2 and what in r.stderr and out.split('/')[0 if out[0] != '/' else 2] in r.stderr
          and len(r.stderr.strip().splitlines()) == 1 and not os.path.exists(os.path.join(work, out)), '%d %r' % (r.returncode, r.stderr))
# The program alone, without its FFmpeg module (src/io/modules.h): a video is refused with one
# line that names the module and how to point at it, exit 2 and no file; a GIF needs no module.
alone = os.path.join(work, 'alone')
os.makedirs(alone)
shutil.copy2(exe, alone)
env = {k: v for k, v in os.environ.items() if k not in ('SOFTRASTER_MODULE_DIR', 'LD_LIBRARY_PATH')}
r = subprocess.run([os.path.join(alone, os.path.basename(exe)), 'animate', MODEL, '-o', 'alone.mp4'] + COMMON,
                   capture_output=True, text=True, timeout=300, cwd=work, env=env)
check('animate without the video module', r.returncode == 2 and 'libsoftraster_video.so' in r.stderr and 'SOFTRASTER_MODULE_DIR' in r.stderr
      and len(r.stderr.strip().splitlines()) == 1 and not os.path.exists(os.path.join(work, 'alone.mp4'))
      and not os.path.exists(os.path.join(work, 'alone.mp4.part')), '%d %r' % (r.returncode, r.stderr))
r = subprocess.run([os.path.join(alone, os.path.basename(exe)), 'animate', MODEL, '-o', 'alone.gif'] + COMMON,
                   capture_output=True, text=True, timeout=300, cwd=work, env=env)
check('a GIF without the video module', r.returncode == 0 and os.path.exists(os.path.join(work, 'alone.gif')), r.stderr)
r = run(['animate', 'missing.glb', '-o', 'm.gif'])
check('animate missing model', r.returncode == 2 and 'missing.glb' in r.stderr and not os.path.exists(os.path.join(work, 'm.gif')), r.stderr)


# Keyframes of a scene file: animate plays them to the last key (1.5 s at 10 fps: 15 frames),
# each frame byte-identical to render --time, and things move.
KEYS = {'version': 2, 'image': {'width': 48, 'height': 32},
        'camera': {'eye': [0, 0, 4], 'target': [0, 0, 0],
                   'animation': {'interpolation': 'smooth', 'keys': [{'time': 0, 'eye': [0, 0, 4]}, {'time': 1.5, 'eye': [1, 1, 4]}]}},
        'lights': {'ambient': [0.2, 0.2, 0.2], 'directional': [{'direction': [0, 0, -1], 'color': [1, 1, 1]}]},
        'objects': [{'builtin': {'type': 'cube'}, 'animation': {'keys': [
            {'time': 0, 'translate': [-1, 0, 0], 'rotate': [0, 0, 0]},
            {'time': 1, 'translate': [1, 0, 0], 'rotate': [0, 90, 0], 'scale': 0.5}]}}]}
with open(os.path.join(work, 'keys.json'), 'w') as f:
    json.dump(KEYS, f)
r = run(['animate', 'keys.json', '-o', 'keys/%02d.png', '--fps', '10'])
names = sorted(os.listdir(os.path.join(work, 'keys'))) if os.path.isdir(os.path.join(work, 'keys')) else []
check('keyframes: 15 frames', r.returncode == 0 and names == ['%02d.png' % k for k in range(15)], (r.stderr, names))
pictures = {}
for k in (0, 4, 12):
    r = run(['render', 'keys.json', '-o', 'keys_%d.png' % k, '--time', '%g' % (k / 10)])
    with open(os.path.join(work, 'keys_%d.png' % k), 'rb') as a, open(os.path.join(work, 'keys', '%02d.png' % k), 'rb') as b:
        pictures[k] = a.read()
        check('keyframes: frame %d is render --time' % k, r.returncode == 0 and pictures[k] == b.read(), r.stderr)
check('keyframes: the frames differ', len(set(pictures.values())) == 3)
r = run(['render', 'keys.json', '-o', 'keys_default.png'])
with open(os.path.join(work, 'keys_default.png'), 'rb') as a:
    check('keyframes: render without --time is time 0', a.read() == pictures.get(0))


# A glTF node animation (a triangle whose node moves along x over 2 s): animate plays it (no
# turntable unless asked), frames equal render --time, and the triangle moves.
def animated_gltf():
    data = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack('<2f', 0, 2) + struct.pack('<6f', 0, 0, 0, 3, 0, 0)
    return {'asset': {'version': '2.0'}, 'scene': 0, 'scenes': [{'nodes': [0]}],
            'nodes': [{'mesh': 0}], 'meshes': [{'primitives': [{'attributes': {'POSITION': 0}}]}],
            'animations': [{'samplers': [{'input': 1, 'output': 2}], 'channels': [{'sampler': 0, 'target': {'node': 0, 'path': 'translation'}}]}],
            'buffers': [{'byteLength': len(data), 'uri': 'data:application/octet-stream;base64,' + base64.b64encode(data).decode()}],
            'bufferViews': [{'buffer': 0, 'byteOffset': 0, 'byteLength': 36}, {'buffer': 0, 'byteOffset': 36, 'byteLength': 8},
                            {'buffer': 0, 'byteOffset': 44, 'byteLength': 24}],
            'accessors': [{'bufferView': 0, 'componentType': 5126, 'count': 3, 'type': 'VEC3', 'min': [0, 0, 0], 'max': [1, 1, 0]},
                          {'bufferView': 1, 'componentType': 5126, 'count': 2, 'type': 'SCALAR', 'min': [0], 'max': [2]},
                          {'bufferView': 2, 'componentType': 5126, 'count': 2, 'type': 'VEC3'}]}


with open(os.path.join(work, 'moving.gltf'), 'w') as f:
    json.dump(animated_gltf(), f)
r = run(['animate', 'moving.gltf', '-o', 'moving/%02d.png', '--fps', '5', '--size', '64x48', '--samples', '1'])
names = sorted(os.listdir(os.path.join(work, 'moving'))) if os.path.isdir(os.path.join(work, 'moving')) else []
check('glTF animation: 10 frames', r.returncode == 0 and names == ['%02d.png' % k for k in range(10)], (r.stderr, names))
moving = {}
for k in (0, 7):
    r = run(['render', 'moving.gltf', '-o', 'moving_%d.png' % k, '--time', '%g' % (k / 5), '--size', '64x48', '--samples', '1'])
    with open(os.path.join(work, 'moving_%d.png' % k), 'rb') as a, open(os.path.join(work, 'moving', '%02d.png' % k), 'rb') as b:
        moving[k] = a.read()
        check('glTF animation: frame %d is render --time' % k, r.returncode == 0 and moving[k] == b.read(), r.stderr)
check('glTF animation: the triangle moves', moving.get(0) != moving.get(7))

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('ok')
