"""A whole process, measured: what the benchmark scripts here time (imported by them)."""

import os
import subprocess
import time


def run_measured(cmd, log_path):
    """Runs cmd with its output (stdout and stderr) to log_path; returns (exit code,
    wall seconds, CPU seconds of the process and its children, peak RSS in MB)."""
    with open(log_path, "w") as out:
        t0 = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t0
    return os.waitstatus_to_exitcode(status), wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0
