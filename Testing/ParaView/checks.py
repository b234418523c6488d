"""Soft assertions for the pvpython tests: every failed check is printed and
counted, so one run reports all of them; the script ends with finish()."""
import sys

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL " + message, flush=True)
    return condition


def finish():
    if failures:
        print("FAIL: %d checks failed" % len(failures))
        sys.exit(1)
    print("PASS")
