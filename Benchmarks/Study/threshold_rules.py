#!/usr/bin/python3
"""Candidate rules for choosing t_r and t_p, compared on the topology study's
profiles (Benchmarks/Study/topology_study.py OUTDIR: the oracle runs' OUTDIR/runs/ID.oracle.tpP.csv,
threshold,b0,b1,b2 up to t_r 8) against each cloud's truth.

  PYTHONPATH=Apps/Scripts /usr/bin/python3 Benchmarks/Study/threshold_rules.py OUTDIR [--show RULE] [--cap C]

Every rule sees the profiles of t_p 1.1 and 0 cut at the cap C (5: what `flowrecon
reconstruct` computes at its defaults), cuts them into windows of constant Betti
numbers within (1.5, C], and calls a window stable when To/From >= Q:
  fixed      t_p 1.1, t_r 2 (the old defaults), flagged by a change in [2, 2.2)
  longest    the longest window
  earliest   the stable window that starts first (the finest stable shape)
  maxb2      the stable window with the most voids, the longest on ties
  maxb2even  the same, with an even b1 first among windows with voids (a union of
             closed surfaces), then the longest
  maxb2evenparts  the same, then the most separate closed surfaces (b0 when
             b0 <= b2 and b1 is even), then the longest: the rule flowrecon
             uses, with Q = 1.1
and, without a stable window, the longest. A wrong answer counts as flagged when
flowrecon would warn (AutomaticThresholds.h, ChoiceWarnings): no stable window, a
window under 30 %, several changes where it starts, a longer window with other
Betti numbers, or the other t_p's answer differs. "achievable": some window of
t_p 1.1 or 0 below C has the truth.
"""
import argparse
import csv
import glob
import math
import os
import re

import generate_clouds as gc

LOWEST, TPS = 1.5, ("1.1", "0")
CAP = 5.0  # set by --cap


def load(runs, cloud, tp):
    path = os.path.join(runs, "%s.oracle.tp%s.csv" % (cloud, tp))
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return [(float(r["threshold"]), (int(r["b0"]), int(r["b1"]), int(r["b2"])))
                for r in csv.DictReader(f)]


def windows(rows, tp):
    """(From, To, betti, start, changes at start, tp), clipped to (LOWEST, CAP]."""
    merged = []
    for k, (t, b) in enumerate(rows):
        end = rows[k + 1][0] if k + 1 < len(rows) else CAP
        if merged and merged[-1][2] == b:
            merged[-1][1] = end
            continue
        jump = sum(abs(x - y) for x, y in zip(b, rows[k - 1][1])) if k else 0
        merged.append([t, end, b, t, jump])
    out = []
    for a, e, b, start, jump in merged:
        lo, hi = max(a, LOWEST), min(e, CAP)
        if hi > lo:
            out.append((lo, hi, b, start, jump if start > LOWEST else 0, tp))
    return out


def length(w):
    return math.log(w[1] / w[0])


def separate_surfaces(b):
    """The components when each can bound a void of its own and b1 is even, else 1."""
    return b[0] if b[2] > 0 and b[1] % 2 == 0 and b[0] <= b[2] else 1


def pick(ws, rule, q):
    stable = [w for w in ws if w[1] >= w[0] * q]
    if rule == "longest" or not stable:
        return max(ws, key=length), rule == "longest" or bool(stable)
    if rule == "earliest":
        return min(stable, key=lambda w: (round(w[0], 2), -length(w))), True
    if rule == "maxb2even":
        return max(stable, key=lambda w: (w[2][2], w[2][2] == 0 or w[2][1] % 2 == 0,
                                          round(length(w), 6))), True
    if rule == "maxb2evenparts":
        return max(stable, key=lambda w: (w[2][2], w[2][2] == 0 or w[2][1] % 2 == 0,
                                          separate_surfaces(w[2]), round(length(w), 6))), True
    return max(stable, key=lambda w: (w[2][2], round(length(w), 6))), True


def truth(cloud):
    shape = re.sub(r"_noise[\d.]+", "", re.sub(r"_n\d+$", "", cloud))
    return tuple(gc.betti(shape))


def evaluate(runs, clouds, rule, q):
    counts = {"right": 0, "flagged": 0, "silent": 0}
    achievable = right_achievable = 0
    wrong = []
    for cloud in clouds:
        profiles = {tp: load(runs, cloud, tp) for tp in TPS}
        if any(p is None for p in profiles.values()):
            continue
        ach = any(b == truth(cloud) and t < CAP for p in profiles.values() for t, b in p)
        achievable += ach
        if rule == "fixed":
            rows = profiles["1.1"]
            b = [x for t, x in rows if t < 2][-1] if any(t < 2 for t, _ in rows) else None
            flagged = any(2 <= t < 2.2 for t, _ in rows)
        else:
            ws = [w for tp in TPS for w in windows(profiles[tp], tp)]
            if not ws:
                continue
            best, stable = pick(ws, rule, q)
            b = best[2]
            mine = {tp: pick([w for w in ws if w[5] == tp], rule, q)[0]
                    for tp in TPS if any(w[5] == tp for w in ws)}
            longest = max(ws, key=length)
            flagged = (not stable or best[1] / best[0] < 1.3 or best[4] > 1
                       or (length(longest) > length(best) and longest[2] != b)
                       or any(w[2] != b for w in mine.values()))
        if b == truth(cloud):
            counts["right"] += 1
            right_achievable += ach
        else:
            counts["flagged" if flagged else "silent"] += 1
            wrong.append((cloud, b, truth(cloud), "flagged" if flagged else "silent",
                          "achievable" if ach else ""))
    return counts, achievable, right_achievable, wrong


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--show", help="list the wrong answers of this rule")
    ap.add_argument("--cap", type=float, default=5.0, help="the end of the profiles (5)")
    args = ap.parse_args()
    global CAP
    CAP = args.cap
    runs = os.path.join(args.outdir, "runs")
    clouds = sorted(set(os.path.basename(p).split(".oracle")[0]
                        for p in glob.glob(os.path.join(runs, "*.oracle.tp0.csv"))))
    print("| rule | Q | clouds | right | flagged | silent | right where achievable |")
    print("|---|---|---:|---:|---:|---:|---|")
    for rule, qs in (("fixed", (None,)), ("longest", (None,)), ("earliest", (1.1, 1.2)),
                     ("maxb2", (1.05, 1.1, 1.2)), ("maxb2even", (1.1,)),
                     ("maxb2evenparts", (1.1,))):
        for q in qs:
            c, a, ra, wrong = evaluate(runs, clouds, rule, q or 1.1)
            n = sum(c.values())
            print("| %s | %s | %d | %d | %d | %d | %d of %d |" % (
                rule, q or "-", n, c["right"], c["flagged"], c["silent"], ra, a))
            if args.show == rule and (q in (None, 1.1)):
                for w in wrong:
                    print("    ", *w)


if __name__ == "__main__":
    main()
