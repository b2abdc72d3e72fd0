#!/usr/bin/env python3
"""terminal_test.py SOFTRASTER WORKDIR: `render --terminal` and `view --terminal` draw the
picture in a terminal.

Run inside tmux at 80 x 24 cells: the pane then shows half blocks in 24-bit color, the
scene's background color among them, at most 23 rows (one left for the prompt); without -o
no file is written. Outside a terminal the size comes from $COLUMNS and $LINES."""
import json, os, shutil, subprocess, sys, time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from checks import check, failures  # noqa: E402

exe, work = sys.argv[1:3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)



scene = os.path.join(work, 'red.json')
json.dump({'version': 1, 'image': {'width': 160, 'height': 120, 'background': [1, 0, 0, 1]},
           'camera': {'eye': [1.5, 1.2, 2.5], 'target': [0, 0, 0]},
           'lights': {'ambient': [0.3, 0.3, 0.3], 'directional': [{'direction': [-0.3, -1, -0.5], 'color': [0.8, 0.8, 0.8]}]},
           'objects': [{'builtin': {'type': 'cube'}, 'material': {'color': [0.2, 0.4, 1, 1]}}]}, open(scene, 'w'))

session = 'softraster_terminal_test_%d' % os.getpid()
tmux = ['tmux', '-L', session, '-f', '/dev/null']
done = os.path.join(work, 'done')
subprocess.run(tmux + ['new-session', '-d', '-s', 't', '-x', '80', '-y', '24',
                       '%s render %s --terminal; echo $? > %s; sleep 60' % (exe, scene, done)], check=True, cwd=work)
for _ in range(600):
    if os.path.exists(done) and open(done).read().strip():
        break
    time.sleep(0.05)
time.sleep(0.2)
plain = subprocess.run(tmux + ['capture-pane', '-t', 't', '-p'], capture_output=True, text=True).stdout
colored = subprocess.run(tmux + ['capture-pane', '-t', 't', '-e', '-p'], capture_output=True, text=True).stdout
subprocess.run(tmux + ['kill-server'], capture_output=True)
check('exit 0', os.path.exists(done) and open(done).read().strip() == '0', open(done).read() if os.path.exists(done) else 'no exit')
rows = [r for r in plain.split('\n') if r.strip()]
check('half blocks', sum(r.count('\u2584') + r.count('\u2580') for r in rows) > 100, plain)
check('at most 23 rows and 80 columns', 10 <= len(rows) <= 23 and max(len(r) for r in rows) <= 80, (len(rows), plain))
import re  # noqa: E402
colors = {tuple(int(v) for v in m) for m in re.findall(r'[34]8;2;(\d+);(\d+);(\d+)', colored)}
check('24-bit color: the red background', (255, 0, 0) in colors, sorted(colors)[:20])
check('24-bit color: the blue cube', any(b > 150 and r < 120 for r, g, b in colors), sorted(colors)[:20])
check('no file without -o', not os.path.exists(os.path.join(work, 'red.png')), os.listdir(work))

# Not a terminal: $COLUMNS x $LINES, and with -o the file as well.
r = subprocess.run([exe, 'render', scene, '--terminal', '-o', os.path.join(work, 'also.png')], capture_output=True, text=True,
                   env=dict(os.environ, COLUMNS='40', LINES='11'))
lines = [l for l in r.stdout.split('\n') if l.strip() and l != '\x1b[0m']
check('piped: sized by COLUMNS and LINES', r.returncode == 0 and 3 <= len(lines) <= 10, (r.returncode, len(lines), r.stderr))
check('piped: -o still written', os.path.exists(os.path.join(work, 'also.png')))


# view --terminal in tmux: it draws, an arrow key turns the model 15 degrees (the frame then
# equals render --turntable 24 --time 1: its screenshot key writes the exact frame), q quits.
def pane(colors=False):
    return subprocess.run(tmux + ['capture-pane', '-t', 'v'] + (['-e'] if colors else []) + ['-p'], capture_output=True, text=True).stdout


def wait_for(what, seconds=60):
    start = time.time()
    while time.time() - start < seconds:
        if what():
            return True
        time.sleep(0.05)
    return False


shots = os.path.join(work, 'shots')
done = os.path.join(work, 'view_done')
subprocess.run(tmux + ['new-session', '-d', '-s', 'v', '-x', '80', '-y', '24',
                       '%s view %s --terminal --screenshots %s; echo $? > %s; sleep 60' % (exe, scene, shots, done)], check=True, cwd=work)
check('view --terminal draws', wait_for(lambda: pane().count('\u2584') + pane().count('\u2580') > 100), pane())
check('view --terminal: a status line', wait_for(lambda: 'tris' in pane()), pane())
check('view --terminal: 24-bit color', '48;2;255;0;0' in pane(True) or '38;2;255;0;0' in pane(True))
os.makedirs(shots, exist_ok=True)
subprocess.run(tmux + ['send-keys', '-t', 'v', 'Right'], check=True)
time.sleep(0.5)
subprocess.run(tmux + ['send-keys', '-t', 'v', 'p'], check=True)
shot = os.path.join(shots, 'softraster-view-000.png')
check('view --terminal: p writes a screenshot', wait_for(lambda: os.path.exists(shot)))
time.sleep(0.3)
r = subprocess.run([exe, 'render', scene, '-o', os.path.join(work, 'turned.png'), '--turntable', '24', '--time', '1'], capture_output=True, text=True)
with open(os.path.join(work, 'turned.png'), 'rb') as a:
    check('view --terminal: Right turns 15 degrees', os.path.exists(shot) and open(shot, 'rb').read() == a.read())
subprocess.run(tmux + ['send-keys', '-t', 'v', 'q'], check=True)
check('view --terminal: q quits with 0', wait_for(lambda: os.path.exists(done) and open(done).read().strip() == '0', 30),
      open(done).read() if os.path.exists(done) else 'no exit')
subprocess.run(tmux + ['kill-server'], capture_output=True)
r = subprocess.run([exe, 'view', scene, '--terminal'], capture_output=True, text=True, stdin=subprocess.DEVNULL)
check('view --terminal without a terminal: exit 2, one line', r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr)

if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('ok')
