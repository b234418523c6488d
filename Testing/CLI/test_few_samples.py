"""Too few samples to tell: under 200 points the flatness test cannot say
whether a cloud lies on a surface or fills a volume, and a sphere of 30-150
i.i.d. points often answers a solid ball (1 0 0). Over i.i.d. sphere clouds of
30, 60, 100 and 150 points (three seeds each), every answer without a void
must carry the too-few warning, and every wrong answer some warning; where the
warning names a window with a void at the chosen t_p (Betti numbers, t_r range),
or, when there is none there, a second line names one at another t_p,
reconstructing at that t_p and the range's middle must give those Betti
numbers. At 200 and 300 points the warning must not appear (the flatness
test runs there), nor on curves (a circle: no solid) or answers with a void.
Usage: test_few_samples.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys

import numpy as np

FLOWRECON, WORK = sys.argv[1:3]
os.makedirs(WORK, exist_ok=True)
TOO_FEW = re.compile(r"^warning: only (\d+) samples, too few to tell whether they lie on a surface or fill a "
                     r"volume \(the flatness test needs 200\), and the answer is solid, without a void: "
                     r"(?:if they lie on a closed surface, the Betti numbers (\d+) (\d+) (\d+) hold for t_r in "
                     r"\(([\d.]+), ([\d.]+)\]|no t_r looked at gives a closed surface at this t_p)$", re.M)
# When the chosen t_p has no such window and another has.
ELSEWHERE = re.compile(r"^warning: with t_p ([\d.]+) a closed surface, Betti numbers (\d+) (\d+) (\d+), holds for "
                       r"t_r in \(([\d.]+), ([\d.]+)\]: with so few samples it may be meant rather than the solid "
                       r"answer$", re.M)
BETTI = re.compile(r"^Betti numbers: (\d+) (\d+) (\d+)$", re.M)
CHOSEN_TP = re.compile(r"t_p ([\d.]+) \(auto\)")


def sphere(n, seed):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1)[:, None]


def run(cloud, *extra):
    out = subprocess.run([FLOWRECON, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu", *extra],
                         capture_output=True, text=True)
    betti = BETTI.search(out.stdout)
    if betti is None:
        raise SystemExit("%s %s: no Betti numbers (exit %d): %s" % (cloud, extra, out.returncode, out.stderr))
    return tuple(map(int, betti.groups())), out


failures = []
named = 0
cases = [("sphere %d, seed %d" % (n, seed), sphere(n, seed), n < 200)
         for n in (30, 60, 100, 150, 200, 300) for seed in (1, 2, 3)]
t = np.linspace(0, 2 * np.pi, 100, endpoint=False)
cases.append(("circle of 100 points", np.c_[np.cos(t), np.sin(t), 0.3 * np.sin(3 * t)], False))
for k, (name, points, small) in enumerate(cases):
    cloud = os.path.join(WORK, "cloud%02d.xyz" % k)
    np.savetxt(cloud, points, fmt="%.17g")
    betti, out = run(cloud)
    warning = TOO_FEW.search(out.stderr)
    print("%s: %s; %s" % (name, betti, warning.group(0)[9:] if warning else "not warned as too few"))
    if small and betti[2] == 0 and not warning:
        failures.append(name + ": a solid answer from %d samples without the too-few warning" % len(points))
    if warning and (not small or betti[2] > 0):
        failures.append(name + ": warned as too few")
    if warning and int(warning.group(1)) != len(points):
        failures.append(name + ": the warning counts %s samples" % warning.group(1))
    if "circle" not in name and betti != (1, 0, 1) and "warning:" not in out.stderr:
        failures.append(name + ": wrong (%s) and not warned" % (betti,))
    elsewhere = ELSEWHERE.search(out.stderr)
    if elsewhere and (not warning or warning.group(2)):
        failures.append(name + ": another t_p's window named beside the chosen one's, or without the warning")
    for tp, said, lo, hi in ([(CHOSEN_TP.search(out.stdout).group(1), warning.group(2, 3, 4), *warning.group(5, 6))]
                             if warning and warning.group(2) else []) + \
            ([(elsewhere.group(1), elsewhere.group(2, 3, 4), *elsewhere.group(5, 6))] if elsewhere else []):
        named += 1
        said = tuple(map(int, said))
        lo, hi = float(lo), float(hi)
        again, _ = run(cloud, "--tp", tp, "--tr", "%.6f" % np.sqrt(lo * hi))
        print("  at t_p %s, t_r %.4f: %s" % (tp, np.sqrt(lo * hi), again))
        if said[2] == 0 or again != said:
            failures.append("%s: named %s over (%s, %s] at t_p %s, which gives %s" % (name, said, lo, hi, tp, again))
if named == 0:
    failures.append("no warning named a window with a void")
if failures:
    raise SystemExit("; ".join(failures))
print("too-few warning on every solid answer under 200 samples, %d of them naming a window that gives its void"
      % named)
