#!/usr/bin/env python3
"""pictures_test.py BUILD_COURSE_DIR COURSE_DIR WORKDIR LESSON...: every lesson's program,
run again, makes exactly the pictures its folder holds (byte for byte), and no others, so
the pages never show stale pictures. BUILD_COURSE_DIR holds the programs (lesson_NN)."""
import filecmp, os, re, shutil, subprocess, sys

build, course, work = sys.argv[1:4]
lessons = sys.argv[4:]
failures = []
for lesson in lessons:
    number = re.match(r'(\d+)-', lesson).group(1)
    out = os.path.join(work, lesson)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    r = subprocess.run([os.path.join(build, 'lesson_' + number), out], capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        failures.append('%s: exit %d: %s' % (lesson, r.returncode, r.stderr[-500:]))
        continue
    made = sorted(f for f in os.listdir(out) if f.endswith('.png'))
    committed = sorted(f for f in os.listdir(os.path.join(course, lesson)) if f.endswith('.png'))
    if made != committed:
        failures.append('%s: the program makes %s, the folder holds %s' % (lesson, made, committed))
    if not made:
        failures.append('%s: no pictures' % lesson)
    for name in set(made) & set(committed):
        if not filecmp.cmp(os.path.join(out, name), os.path.join(course, lesson, name), shallow=False):
            failures.append('%s/%s differs from what the program makes now (run: cmake --build BUILD --target course)' % (lesson, name))
if failures:
    print('FAILED:\n  ' + '\n  '.join(failures))
    sys.exit(1)
print('ok: %d lessons' % len(lessons))
