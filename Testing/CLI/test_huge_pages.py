"""flowrecon restarts itself with glibc.malloc.hugetlb=1 (Apps/HugePages.h), and
nothing else changes.

- Where the kernel gives huge pages on request only ("[madvise]"), most of the
  running process's memory is in huge pages (/proc/PID/smaps_rollup, sampled
  while it runs), also when the caller gives other tunables, and only a few per
  cent with the caller's own glibc.malloc.hugetlb=0, which is kept. (Not read
  from /proc/PID/environ: glibc rewrites the tunables' string in place.)
- The restarted process gets the same arguments: a cloud under a path with a space
  and non-ASCII letters, written to another such path.
- The output does not depend on it: the .vtu, the profile and the printed lines
  (but the timings) of `reconstruct` with and without huge pages are identical.

usage: test_huge_pages.py FLOWRECON WORKDIR
"""

import os
import subprocess
import sys
import time

import numpy as np

from flowrecon_testing import clouds as cl

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
failures = []

try:
    with open("/sys/kernel/mm/transparent_hugepage/enabled") as f:
        MADVISE = "[madvise]" in f.read()
except OSError:  # no transparent huge pages: flowrecon does not restart
    MADVISE = False


def huge_share_while_running(args, tunables):
    """The mean share of the running process's resident memory held in huge
    pages (AnonHugePages / Rss of /proc/PID/smaps_rollup, sampled every 50 ms)."""
    env = dict(os.environ)
    env.pop("GLIBC_TUNABLES", None)
    if tunables is not None:
        env["GLIBC_TUNABLES"] = tunables
    p = subprocess.Popen([FLOWRECON, *args], env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL)
    shares = []
    try:
        while p.poll() is None:
            time.sleep(0.05)
            try:
                with open("/proc/%d/smaps_rollup" % p.pid) as f:
                    fields = dict(line.split(":", 1) for line in f if ":" in line)
                rss = int(fields["Rss"].split()[0])
                huge = int(fields["AnonHugePages"].split()[0])
            except (OSError, KeyError, ValueError):
                continue
            if rss > 0:
                shares.append(huge / rss)
    finally:
        p.kill()
        p.wait()
    return sum(shares) / max(1, len(shares))


rng = np.random.default_rng(20261205)
folder = os.path.join(WORK, "a folder é")
os.makedirs(folder, exist_ok=True)
cloud = os.path.join(folder, "sphère cloud.xyz")
cl.write_xyz(cloud, cl.sphere(100000, rng))  # a run of a few seconds: long enough to look at
long_run = ["reconstruct", cloud, "-o", os.path.join(WORK, "long.vtu"), "--quiet"]

shares = {given: huge_share_while_running(long_run, given)
          for given in (None, "glibc.malloc.tcache_count=8", "glibc.malloc.hugetlb=0")}
for given, share in shares.items():
    print("GLIBC_TUNABLES %r: on average %.0f %% of the resident memory in huge pages"
          % (given, 100 * share), flush=True)
if MADVISE:
    # Without the tunable only the arrays the core advises itself (HugePages.h
    # of the core) get huge pages: a few per cent.
    for given in (None, "glibc.malloc.tcache_count=8"):
        if not shares[given] > max(0.2, 2 * shares["glibc.malloc.hugetlb=0"]):
            failures.append("GLIBC_TUNABLES %r: %.0f %% in huge pages, against %.0f %% with "
                            "glibc.malloc.hugetlb=0: not restarted with the tunable"
                            % (given, 100 * shares[given], 100 * shares["glibc.malloc.hugetlb=0"]))
else:
    print("the kernel's huge pages are not in [madvise] mode: the restart does not apply")

small = os.path.join(folder, "tore é.xyz")
cl.write_xyz(small, cl.chart_torus(6000, rng))


def reconstruct(tag, tunables):
    env = dict(os.environ)
    env.pop("GLIBC_TUNABLES", None)
    if tunables is not None:
        env["GLIBC_TUNABLES"] = tunables
    out = os.path.join(folder, "recon %s.vtu" % tag)
    profile = os.path.join(folder, "profile %s.csv" % tag)
    p = subprocess.run([FLOWRECON, "reconstruct", small, "-o", out, "--profile", profile],
                       env=env, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("reconstruct (%s) failed: %s" % (tag, p.stderr))
    with open(out, "rb") as f, open(profile, "rb") as g:
        return p.stdout.replace("recon %s.vtu" % tag, "recon TAG.vtu"), f.read(), g.read()


huge = reconstruct("huge", None)
plain = reconstruct("plain", "glibc.malloc.hugetlb=0")
for name, a, b in zip(("printed lines", "the .vtu", "the profile"), huge, plain):
    print("%s: %s" % (name, "identical" if a == b else "DIFFERENT"))
    if a != b:
        failures.append("%s differ with and without huge pages" % name)
        if isinstance(a, str):
            print("\n".join("  %s | %s" % d for d in zip(a.splitlines(), b.splitlines())
                            if d[0] != d[1]))
if "Betti numbers: 1 2 1" not in huge[0]:
    failures.append("the torus is not 1 2 1 (the run did not read its arguments?):\n" + huge[0])

for f in failures:
    print("FAIL " + f)
sys.exit(1 if failures else 0)
