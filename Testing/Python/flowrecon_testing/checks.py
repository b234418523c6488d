"""Checks that report every failure of a run, not only the first, and end it with
an exit status: Checker (sections, details) for the Python tests, and check() and
finish() over one module-wide list for the pvpython scripts; fail() for a script
that stops at its first failure."""
import sys
import traceback


class Checker:
    """Collects failed checks (so one run reports all of them) and exits non-zero."""

    def __init__(self, title):
        self.title = title
        self.failures = []
        self.passed = 0
        self.section_name = ""

    def section(self, name):
        self.section_name = name
        print("-- %s" % name, flush=True)

    def check(self, condition, message, details=None):
        if condition:
            self.passed += 1
            return True
        text = "[%s] %s" % (self.section_name, message)
        if details:
            text += "\n" + str(details)
        self.failures.append(text)
        print("FAIL " + text, flush=True)
        return False

    def run(self, name, func, *args, **kwargs):
        """Runs func, turning an exception into a failure of this section."""
        self.section(name)
        try:
            func(*args, **kwargs)
        except Exception:  # report and go on with the other sections
            self.check(False, "exception in %s" % name, traceback.format_exc())

    def finish(self):
        print("%s: %d checks passed, %d failed" % (self.title, self.passed, len(self.failures)))
        if self.failures:
            print("FAILURES:")
            for f in self.failures:
                print(" * " + f.replace("\n", "\n   "))
            return 1
        print("PASS")
        return 0


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


def fail(message):
    print("FAIL: " + message, flush=True)
    sys.exit(1)
