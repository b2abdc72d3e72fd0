"""The checks of the test scripts: a check that fails is remembered with its detail and the
script goes on, so one run lists every failure; finish() prints them and exits 1 if any."""
import sys

failures = []


def check(name, ok, detail=''):
    if not ok:
        failures.append('%s %s' % (name, str(detail)[:2000]))


def finish():
    for f in failures:
        print('FAIL:', f)
    print('%d passed, %d failed' % (0 if failures else 1, len(failures)))
    sys.exit(1 if failures else 0)
