#!/usr/bin/env python3
"""man_pages_test.py SOFTRASTER MAN_DIR: every command has a man page, and each page says
what its command's --help says (every option and the description)."""
import os, re, subprocess, sys

exe, man = sys.argv[1:3]
failures = []


def help_of(*command):
    r = subprocess.run([exe, *command, '--help'], capture_output=True, text=True)
    return r.stdout


def page(name):
    path = os.path.join(man, name + '.1')
    if not os.path.exists(path):
        failures.append('no man page ' + path)
        return ''
    text = open(path).read()
    # roff to plain words: \- is a hyphen; \fB, \fR, \fI, \(aq... are fonts and glyphs.
    text = text.replace('\\-', '-').replace('\\(aq', "'")
    return re.sub(r'\\f[BRIP]', '', text)


top = help_of()
commands = re.findall(r'^  ([a-z]+) ', top.split('Subcommands:')[1], re.M)
if len(commands) < 8:
    failures.append('too few commands in --help: %s' % commands)
pages = sorted(f[len('softraster-'):-2] for f in os.listdir(man) if f.startswith('softraster-') and f.endswith('.1'))
if sorted(commands) != pages:
    failures.append('commands %s but pages %s' % (sorted(commands), pages))
main = page('softraster')
for c in commands:
    if c not in main:
        failures.append('softraster.1 does not list %s' % c)

for c in commands:
    text = help_of(c)
    p = page('softraster-' + c)
    if not p:
        continue
    options = set(re.findall(r'^  (-\w)?,?(--[a-zA-Z][\w-]*)', text.split('Options:')[1], re.M))
    options = {o for pair in options for o in pair if o}
    if not options:
        failures.append('%s: no options found in its --help' % c)
    for option in sorted(options):
        if option not in p:
            failures.append('softraster-%s.1 lacks %s' % (c, option))
    description = text.splitlines()[0]
    if description[1:] not in ' '.join(p.split()):
        failures.append('softraster-%s.1 lacks its description %r' % (c, description))

for f in failures:
    print('FAIL:', f)
print('%d passed, %d failed' % (0 if failures else 1, len(failures)))
sys.exit(1 if failures else 0)
