#!/usr/bin/env python3
"""completion_test.py SOFTRASTER COMPLETION_FILE: the bash completion the build writes is
the one `softraster completion bash` prints, and it completes commands, options, choices
and files as bash would ask it to."""
import os, re, subprocess, sys, tempfile

exe, script = sys.argv[1:3]
failures = []
printed = subprocess.run([exe, 'completion', 'bash'], capture_output=True, text=True)
if printed.returncode != 0 or printed.stdout != open(script).read():
    failures.append('the installed script is not what `completion bash` prints')
r = subprocess.run([exe, 'completion', 'zsh'], capture_output=True, text=True)
if r.returncode != 2 or len(r.stderr.strip().splitlines()) != 1:
    failures.append('completion zsh: want one line and exit 2, got %d %r' % (r.returncode, r.stderr))

folder = tempfile.mkdtemp()
open(os.path.join(folder, 'duck.glb'), 'w').close()


def complete(*words):
    """What the completion offers with the cursor at the end of `words` (the last may be '')."""
    line = ' '.join(words)
    program = 'source %s\nCOMP_WORDS=(%s)\nCOMP_CWORD=%d\n_softraster\nprintf "%%s\\n" "${COMPREPLY[@]}"\n' % (
        script, ' '.join("'%s'" % w for w in words), len(words) - 1)
    r = subprocess.run(['bash', '-c', program], capture_output=True, text=True, cwd=folder)
    return set(r.stdout.split())


top = subprocess.run([exe, '--help'], capture_output=True, text=True).stdout
commands = re.findall(r'^  ([a-z]+) ', top.split('Subcommands:')[1], re.M)
cases = [
    (('softraster', ''), set(commands) | {'-h', '--help', '--version'}),
    (('softraster', 'thu'), {'thumbnails', 'thumbnail'}),
    (('softraster', 'render', '--sam'), {'--samples'}),
    (('softraster', 'render', '--view', ''), {'three-quarter', 'front', 'back', 'left', 'right', 'top', 'bottom', 'iso'}),
    (('softraster', 'render', '--shading', 'p'), {'phong', 'pbr'}),
    (('softraster', 'render', 'du'), {'duck.glb'}),
    (('softraster', 'render', '-o', 'du'), {'duck.glb'}),
    (('softraster', 'thumbnail', '--max'), {'--max-file-size'}),
    (('softraster', 'bench', '--frames', ''), set()),
    (('softraster', 'completion', ''), {'bash'}),
]
for words, want in cases:
    got = complete(*words)
    if got != want:
        failures.append('%s: want %s, got %s' % (' '.join(words), sorted(want), sorted(got)))
for c in commands:  # every command's every option
    text = subprocess.run([exe, c, '--help'], capture_output=True, text=True).stdout
    options = set(re.findall(r'^  (?:-\w,)?(--[a-zA-Z][\w-]*)', text.split('Options:')[1], re.M))
    got = complete('softraster', c, '--')
    if not options <= got:
        failures.append('%s --: lacks %s' % (c, sorted(options - got)))

for f in failures:
    print('FAIL:', f)
print('%d passed, %d failed' % (0 if failures else 1, len(failures)))
sys.exit(1 if failures else 0)
