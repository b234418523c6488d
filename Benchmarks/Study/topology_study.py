#!/usr/bin/python3
"""Topology study of the reconstruction's parameters: how often `flowrecon
reconstruct` gets the Betti numbers right, by class (a class = a sampling x a shape
family), with the old fixed defaults, with the automatic defaults, and whether SOME
(t_p, t_r) gives the truth.

  PYTHONPATH=Apps/Scripts /usr/bin/python3 Benchmarks/Study/topology_study.py OUTDIR [--large] [--only REGEX]
      [--sizes 1000,10000] [--configs fixed,auto,oracle] [--jobs N]
      [--flowrecon build/bin/flowrecon] [--report-only] [--fresh]

For each cloud of the table TABLE below (deterministic: generate_clouds.make with
its fixed seeds; the noise of the noisy samples from a seed of the cloud's name) the
script writes OUTDIR/clouds/ID.xyz, runs the CLI in the configurations asked for,
and writes OUTDIR/results.json (every run; rewritten after each cloud) and the
Markdown report OUTDIR/study.md (also printed). Configurations:

  fixed   reconstruct CLOUD --tp 1.1 --tr 2           (the old defaults, explicit)
  auto    reconstruct CLOUD                           (no --tr / --tp: the defaults)
  oracle  for t_p in 0, 1.02, 1.05, 1.1, 1.2:
          reconstruct CLOUD --tp P --tr 1.05 --tr-max 8 --topology-profile P.csv
          and, from the profile (threshold,b0,b1,b2: row k holds for t_r in
          (threshold_k, threshold_k+1], the last row up to the drawn maximum 8),
          the t_r windows (> 1) where the Betti numbers are the truth.

A fixed or auto run is `right` (its 'Betti numbers: b0 b1 b2' line is the truth),
`flagged` (wrong, or no Betti line, with at least one stderr line starting with
'warning:'), `silent` (wrong without a warning), or `error` (non-zero exit or
timeout: the CLI refused or failed, which it says on stderr). A cloud's truth is
`achievable` when some t_p has a window. The report has one table per class and a
summary. Each run's wall time and peak RSS come from /usr/bin/time -f "%e %M". A
line of the auto run containing '(auto)' (stdout or stderr) is kept verbatim.

Options:
  --flowrecon PATH    the CLI (default build/bin/flowrecon)
  --only REGEX        only the clouds whose id (e.g. torus_pd_n1000, sphere_pd_noise1_n1000)
                      or class (e.g. 'Poisson disk . surfaces', 'x' for the '×') matches (re.search)
  --sizes N,N         only these nominal sizes (1000, 10000, 100000, 1000000)
  --large             add the 10^6 clouds (i.i.d. sphere and torus): each takes tens
                      of minutes and several GB per run, and they run one at a time
                      after the others whatever --jobs says
  --configs LIST      a subset of fixed,auto,oracle (default all three)
  --jobs N            clouds run in parallel (default 1); each cloud's runs are serial
  --threads N         passed to flowrecon as --threads (default 1, so that --jobs
                      measures one core per cloud; 0 leaves it to flowrecon; the
                      output does not depend on it)
  --timeout S         seconds per flowrecon run, then it counts as an error (0: none)
  --oracle-tp LIST    the t_p of the oracle (default 0,1.02,1.05,1.1,1.2)
  --oracle-tr-max T   the oracle's --tr-max (default 8)
  --oracle-betti-max-cells N   passed to the oracle runs (default: flowrecon's, 4e6;
                      above it flowrecon skips the Betti numbers and the profile,
                      and the oracle says 'unknown')
  --keep-vtu          keep the reconstructions OUTDIR/runs/ID.CONFIG[.tpP].vtu (by
                      default each is deleted after its run: 40-200 MB each at 10^5
                      points; rerun one cloud with --only ID --keep-vtu to look at it).
                      The oracle's profiles OUTDIR/runs/ID.oracle.tpP.csv are kept
  --no-snapshot       run the flowrecon given (by default it is copied, with the
                      libraries it loads from its build tree, to OUTDIR/bin/HASH and
                      run from there, so a rebuild during the study changes nothing;
                      HASH, of those files, names the build in the results)
  --regenerate        write the clouds again even when OUTDIR/clouds/ID.xyz exists
                      (by default an existing file is reused: the clouds are
                      deterministic)
  --fresh             forget OUTDIR/results.json (by default the new runs replace
                      those of the same cloud and configuration, the others are kept,
                      so a study can be run in parts)
  --report-only       only write the report from OUTDIR/results.json
  --list              print the clouds that would run (with the options) and exit

Costs, measured on the 2-core development machine (one thread per run, the three
configurations = 7 runs per cloud): 10^3 points about 1-2 s a cloud (47 clouds: 1
min); 10^4 points 3-30 s (evenly spaced trefoil: 100 s; 40 clouds: about 10 min);
10^5 points 60-90 s for a surface, 180 s and 1.6 GB for the Poisson-disk ball (9
clouds: about 13 min); making the clouds about 2 min (Poisson disk at 10^5: 15 s
each). The default table is about 25 min with --jobs 1, 15 min with --jobs 2.
--large adds the 10^6 i.i.d. sphere and torus (expect 10-20 min each and a few GB
per run; above 4e6 cells flowrecon skips the oracle's profile, see
--oracle-betti-max-cells). Curves stop at 10^4 (the trefoil's i.i.d. sample at
10^3): the flow complex of a curve sample is superlinear (EXPERIMENTS.md: the
i.i.d. trefoil at 16 000 points did not finish in 10 min). Farthest points stop at
10^3 (generate_clouds.farthest_points is quadratic).
"""
import argparse
import concurrent.futures
import csv
import datetime
import hashlib
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zlib

import generate_clouds as gc
import numpy as np

# --------------------------------------------------------------------------- the study

# Shape families (the order of the report).
FAMILIES = {
    "surfaces": "surfaces, genus 0-4",
    "curves": "curves",
    "solids": "solids",
    "thin": "thin parts",
    "nonmanifold": "non-manifold unions",
}

# Samplings: key -> (label, generate_clouds suffix). Lattices and noisy samples are
# rows of their own (their generator is named in the table).
SAMPLINGS = {
    "iid": ("i.i.d.", ""),
    "pd": ("Poisson disk", "_pd"),
    "even": ("evenly spaced", "_qu"),        # curves: even spacing, jitter 0.1 spacing
    "fp": ("farthest points", "_qu"),         # farthest-point subsample of 30x i.i.d.
    "lattice": ("lattice", None),
    "noisy": ("noisy Poisson disk", "_pd"),
    "dv": ("density x10 (i.i.d.)", "_dv"),
    "dvqu": ("density x10 (Poisson disk)", "_dvqu"),
}

# The clouds. One row per (sampling, family, shape); the shape drawn is the shape +
# the sampling's suffix in generate_clouds.SHAPES (lattices: the lattice itself;
# noisy: the Poisson-disk sample plus Gaussian noise, of standard deviation per
# coordinate `noise` x its mean nearest-neighbour spacing). Size columns: nominal
# numbers of points (lattices: the nearest the lattice allows); x = run by default,
# L = only with --large, - = not run.
TABLE = """
sampling  family       shape                10^3 10^4 10^5 10^6  noise
iid       surfaces     sphere                x    x    x    L
iid       surfaces     torus                 x    x    x    L
iid       surfaces     genus2                x    x    -    -
iid       surfaces     genus3                x    x    -    -
iid       surfaces     genus4                x    x    -    -
iid       curves       trefoil               x    -    -    -
iid       curves       circle                x    x    -    -
iid       solids       ball                  x    x    -    -
iid       solids       cube                  x    x    -    -
iid       thin         thin_tube             x    x    -    -
iid       thin         thin_plate            x    x    -    -
iid       nonmanifold  two_spheres           x    x    -    -
iid       nonmanifold  two_hemispheres       x    x    -    -
iid       nonmanifold  sphere_with_segment   x    x    -    -
pd        surfaces     sphere                x    x    x    -
pd        surfaces     torus                 x    x    x    -
pd        surfaces     genus2                x    x    -    -
pd        surfaces     genus3                x    x    -    -
pd        surfaces     genus4                x    x    x    -
even      curves       trefoil               x    x    -    -
even      curves       circle                x    x    -    -
pd        solids       ball                  x    x    x    -
pd        solids       cube                  x    x    -    -
pd        thin         thin_tube             x    x    x    -
pd        thin         thin_plate            x    x    -    -
pd        nonmanifold  two_spheres           x    x    x    -
pd        nonmanifold  two_hemispheres       x    x    -    -
pd        nonmanifold  sphere_with_segment   x    x    -    -
fp        surfaces     torus                 x    -    -    -
fp        surfaces     genus3                x    -    -    -
fp        solids       cube                  x    -    -    -
lattice   surfaces     latlong_sphere        x    x    -    -
lattice   surfaces     lattice_shell         x    x    -    -
lattice   surfaces     fibonacci_sphere      x    x    x    -
noisy     surfaces     sphere                x    x    -    -    0.5
noisy     surfaces     sphere                x    x    -    -    1
noisy     surfaces     sphere                x    x    -    -    2
noisy     surfaces     torus                 x    x    -    -    0.5
noisy     surfaces     torus                 x    x    -    -    1
noisy     surfaces     torus                 x    x    -    -    2
noisy     surfaces     genus2                x    -    -    -    0.5
noisy     surfaces     genus2                x    -    -    -    1
noisy     surfaces     genus2                x    -    -    -    2
dv        surfaces     sphere                x    x    -    -
dv        surfaces     torus                 x    x    -    -
dvqu      surfaces     sphere                x    x    -    -
dvqu      surfaces     torus                 x    x    -    -
"""
SIZES = (10 ** 3, 10 ** 4, 10 ** 5, 10 ** 6)


def table_rows():
    """TABLE as (sampling, family, shape, {size: 'x' or 'L'}, noise or None)."""
    lines = [l.split() for l in TABLE.strip().splitlines()[1:] if l.strip()]
    rows = []
    for f in lines:
        marks = {n: m for n, m in zip(SIZES, f[3:7]) if m != "-"}
        rows.append((f[0], f[1], f[2], marks, float(f[7]) if len(f) > 7 else None))
    return rows


CONFIGS = ("fixed", "auto", "oracle")
FIXED_OPTIONS = ["--tp", "1.1", "--tr", "2"]
ORACLE_TP = ("0", "1.02", "1.05", "1.1", "1.2")
ORACLE_TR = "1.05"
ORACLE_TR_MAX = "8"


def lattice_size(name, n):
    """The size parameter of a lattice of generate_clouds with about n points."""
    if name == "latlong_sphere":        # k latitudes x 2k longitudes
        return max(2, int(round(math.sqrt(n / 2.0))))
    if name == "lattice_shell":         # integer points within 0.5 of the sphere of radius k:
        return max(2, int(round(math.sqrt(n / 11.65))))   # about 11.65 k^2 (2 622 at k 15)
    return n                            # fibonacci_sphere: n points


def clouds(large=False):
    """The clouds of TABLE, as dicts (in the table's order)."""
    out = []
    for order, (kind, family, base, marks, noise) in enumerate(table_rows()):
        label, suffix = SAMPLINGS[kind]
        shape = base if suffix is None else base + suffix
        if shape not in gc.SHAPES:
            raise SystemExit("topology_study: no shape %r in generate_clouds.SHAPES" % shape)
        for n, mark in marks.items():
            if mark == "L" and not large:
                continue
            cid = "%s%s_n%d" % (shape, "" if noise is None else "_noise%g" % noise, n)
            out.append({
                "id": cid, "order": [order, n], "sampling": label, "family": family,
                "class": "%s × %s" % (label, FAMILIES[family]),
                "shape": shape, "base": base, "nominal": n, "noise": noise,
                "size_param": lattice_size(shape, n) if kind == "lattice" else n,
                "truth": list(gc.betti(shape)), "heavy": mark == "L",
            })
    return out


# --------------------------------------------------------------------------- clouds


def mean_spacing(points):
    """Mean distance from each point to its nearest other point."""
    from scipy.spatial import cKDTree
    d, _ = cKDTree(points).query(points, k=2)
    return float(np.mean(d[:, 1]))


def make_cloud(cloud, path, regenerate):
    """Write the cloud to `path` (or reuse it, with its notes PATH.json); (points,
    notes: seconds to make it, the noise's spacing and standard deviation)."""
    side = path + ".json"
    if os.path.exists(path) and os.path.exists(side) and not regenerate:
        with open(side) as f:
            return gc.read_xyz(path), json.load(f)
    start = time.time()
    points = gc.make(cloud["shape"], cloud["size_param"])
    notes = {}
    if cloud["noise"] is not None:
        spacing = mean_spacing(points)
        rng = np.random.default_rng(zlib.crc32(cloud["id"].encode()))
        points = points + rng.normal(0.0, cloud["noise"] * spacing, points.shape)
        notes = {"spacing": spacing, "sigma": cloud["noise"] * spacing}
    notes["generated_s"] = round(time.time() - start, 2)
    for name, text in ((path, gc.to_xyz_text(points)), (side, json.dumps(notes))):
        with open(name + ".tmp", "w") as f:
            f.write(text)
        os.replace(name + ".tmp", name)
    return points, notes


# --------------------------------------------------------------------------- running


def run_cli(cmd, timeout, env=None):
    """Run cmd under /usr/bin/time; a dict with the exit code, Betti numbers (or None),
    warning lines, '(auto)' lines, wall seconds and peak RSS (MB)."""
    with tempfile.NamedTemporaryFile("r", suffix=".time", delete=False) as tf:
        timefile = tf.name
    full = ["/usr/bin/time", "-f", "%e %M", "-o", timefile] + cmd
    start = time.time()
    # a session of its own, so that a timeout ends flowrecon too, not only /usr/bin/time
    proc = subprocess.Popen(full, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            env=env, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout if timeout else None)
        code = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        code = "timeout"
    wall = time.time() - start
    peak = None
    try:
        with open(timefile) as f:
            fields = f.read().split()
        if len(fields) >= 2 and code != "timeout":
            wall, peak = float(fields[-2]), int(fields[-1]) / 1024.0
    except (OSError, ValueError):
        pass
    finally:
        os.remove(timefile)
    betti = None
    for line in out.splitlines():
        if line.startswith("Betti numbers: "):
            try:
                betti = [int(x) for x in line[len("Betti numbers: "):].split()]
            except ValueError:
                betti = None
    warnings = [l for l in err.splitlines() if l.startswith("warning:")]
    auto = [l for l in out.splitlines() + err.splitlines() if "(auto)" in l]
    errors = [l for l in err.splitlines() if l.strip() and not l.startswith("warning:")]
    return {"cmd": cmd, "exit": code, "betti": betti, "warnings": warnings,
            "warning_count": len(warnings), "auto_lines": auto,
            "error": errors[-1] if code != 0 and errors else ("timeout" if code == "timeout" else None),
            "wall_s": round(wall, 3), "peak_mb": None if peak is None else round(peak, 1)}


def classify(run, truth):
    if run["exit"] != 0:
        return "error"
    if run["betti"] == list(truth):
        return "right"
    return "flagged" if run["warning_count"] else "silent"


def read_profile(path):
    with open(path) as f:
        return [(float(r["threshold"]), [int(r["b0"]), int(r["b1"]), int(r["b2"])])
                for r in csv.DictReader(f)]


def windows(rows, truth, limit):
    """The (from, to] of t_r > 1 where the profile's Betti numbers are the truth;
    consecutive rows with the same numbers are merged."""
    out = []
    for k, (t, b) in enumerate(rows):
        end = rows[k + 1][0] if k + 1 < len(rows) else limit
        if b == list(truth) and end > 1.0:
            start = max(t, 1.0)
            if out and out[-1][1] == t:
                out[-1][1] = end
            else:
                out.append([start, end])
    return out


def betti_at(rows, tr):
    """The profile's Betti numbers at t_r (the last row whose threshold is < t_r)."""
    found = None
    for t, b in rows:
        if t < tr:
            found = b
    return found


def study_cloud(cloud, opts):
    """Make one cloud and run its configurations; the cloud's record."""
    outdir = opts["outdir"]
    cdir = os.path.join(outdir, "clouds")
    rdir = os.path.join(outdir, "runs")
    xyz = os.path.join(cdir, cloud["id"] + ".xyz")
    points, notes = make_cloud(cloud, xyz, opts["regenerate"])
    rec = dict(cloud)
    rec.update(notes)
    rec["n"] = int(len(points))
    rec["runs"] = {}
    base = [opts["flowrecon"], "reconstruct", xyz]
    threads = ["--threads", str(opts["threads"])] if opts["threads"] else []
    truth = cloud["truth"]
    for config in opts["configs"]:
        stem = os.path.join(rdir, "%s.%s" % (cloud["id"], config))
        if config in ("fixed", "auto"):
            extra = FIXED_OPTIONS if config == "fixed" else []
            r = run_cli(base + ["-o", stem + ".vtu"] + extra + threads, opts["timeout"], opts["env"])
            r["result"] = classify(r, truth)
            if not opts["keep_vtu"] and os.path.exists(stem + ".vtu"):
                os.remove(stem + ".vtu")
            rec["runs"][config] = r
        else:
            per_tp = {}
            for tp in opts["oracle_tp"]:
                s = "%s.tp%s" % (stem, tp)
                prof = s + ".csv"
                if os.path.exists(prof):
                    os.remove(prof)
                cmd = base + ["--tp", tp, "--tr", ORACLE_TR, "--tr-max", opts["oracle_tr_max"],
                              "--topology-profile", prof, "-o", s + ".vtu"] + threads
                if opts["oracle_betti_max_cells"]:
                    cmd += ["--betti-max-cells", opts["oracle_betti_max_cells"]]
                r = run_cli(cmd, opts["timeout"], opts["env"])
                r.pop("warnings")  # hundreds of lines at t_r 1.05: only their count is kept
                if r["exit"] == 0 and os.path.exists(prof):
                    rows = read_profile(prof)
                    r["profile_rows"] = len(rows)
                    r["windows"] = windows(rows, truth, float(opts["oracle_tr_max"]))
                    r["betti_at_2"] = betti_at(rows, 2.0)
                    r["profile_tail"] = [[t, b] for t, b in rows[-5:]]
                else:
                    r["windows"] = None  # unknown: error, timeout or Betti numbers skipped
                if not opts["keep_vtu"] and os.path.exists(s + ".vtu"):
                    os.remove(s + ".vtu")
                per_tp[tp] = r
            known = [r for r in per_tp.values() if r["windows"] is not None]
            achievable = any(r["windows"] for r in known)
            rec["runs"]["oracle"] = {
                "tr": ORACLE_TR, "tr_max": opts["oracle_tr_max"], "tp": per_tp,
                "achievable": True if achievable else (False if len(known) == len(per_tp) else None),
                "wall_s": round(sum(r["wall_s"] for r in per_tp.values()), 3),
                "peak_mb": max((r["peak_mb"] for r in per_tp.values() if r["peak_mb"]), default=None),
            }
    return rec


def build_files(flowrecon):
    """flowrecon and the shared libraries it loads from its own build tree (the
    folder above its bin/, e.g. build/lib/libFlowReconFilters.so), from ldd."""
    tree = os.path.dirname(os.path.dirname(os.path.realpath(flowrecon)))
    files = [os.path.realpath(flowrecon)]
    try:
        out = subprocess.run(["ldd", flowrecon], capture_output=True, text=True).stdout
    except OSError:
        out = ""
    for m in re.finditer(r"=>\s*(\S+)\s*\(", out):
        lib = os.path.realpath(m.group(1))
        if lib.startswith(tree + os.sep):
            files.append(lib)
    return files


def build_hash(files):
    """A short hash of the files (the binary and its build-tree libraries)."""
    h = hashlib.sha256()
    for path in files:
        with open(path, "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                h.update(chunk)
    return h.hexdigest()[:16]


def snapshot(flowrecon, outdir):
    """Copy flowrecon and its build-tree libraries to OUTDIR/bin, so that a rebuild
    during the study changes nothing (LD_LIBRARY_PATH is searched before the
    binary's RUNPATH); (the copy's path, its environment, the build hash)."""
    files = build_files(flowrecon)
    digest = build_hash(files)
    bindir = os.path.join(outdir, "bin", digest)
    os.makedirs(bindir, exist_ok=True)
    for path in files:
        dest = os.path.join(bindir, os.path.basename(path))
        if not os.path.exists(dest):
            shutil.copy2(path, dest + ".tmp")
            os.replace(dest + ".tmp", dest)
    if build_hash([os.path.join(bindir, os.path.basename(p)) for p in files]) != digest:
        raise SystemExit("topology_study: %s changed while it was copied (a build is "
                         "running?): try again" % flowrecon)
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = bindir + (":" + env["LD_LIBRARY_PATH"]
                                       if env.get("LD_LIBRARY_PATH") else "")
    copy = os.path.abspath(os.path.join(bindir, os.path.basename(flowrecon)))
    probe = subprocess.run([copy, "reconstruct", "--help"], capture_output=True, text=True, env=env)
    if probe.returncode != 0:
        raise SystemExit("topology_study: the copy %s does not run (%s)"
                         % (copy, (probe.stderr.strip().splitlines() or ["exit %d" % probe.returncode])[-1]))
    return copy, env, digest


# --------------------------------------------------------------------------- report


def btext(b):
    return " ".join(map(str, b)) if b else "-"


def run_cell(r):
    if r is None:
        return "not run"
    res = r["result"]
    if res == "error":
        return "**error**: %s" % (r["error"] or "exit %s" % r["exit"]).replace("|", "/")
    got = btext(r["betti"]) if r["betti"] is not None else "no Betti"
    if res == "right":
        return "right %s" % got
    if res == "flagged":
        return "flagged %s (%d warning%s)" % (got, r["warning_count"],
                                             "" if r["warning_count"] == 1 else "s")
    return "**silent** %s" % got


def fmt_window(w):
    return "(%.3f, %g]" % (w[0], w[1]) if w[1] == int(w[1]) else "(%.3f, %.3f]" % (w[0], w[1])


def oracle_cell(o):
    if o is None:
        return "not run"
    groups, unknown = {}, []   # the t_p with the same windows on one line
    for tp, r in o["tp"].items():
        if r["windows"] is None:
            unknown.append("t_p %s: %s" % (tp, r["error"] or "no profile"))
        elif r["windows"]:
            groups.setdefault(" ∪ ".join(fmt_window(w) for w in r["windows"]), []).append(tp)
    parts = ["t_p %s: %s" % (", ".join(tps), text) for text, tps in groups.items()]
    head = {True: "yes", False: "no", None: "unknown"}[o["achievable"]]
    text = head + (" — " + "; ".join(parts) if parts else "")
    if unknown:
        text += " (" + "; ".join(unknown).replace("|", "/") + ")"
    return text


def seconds(rec):
    parts = []
    for c in CONFIGS:
        r = rec["runs"].get(c)
        parts.append("-" if r is None else "%.1f" % r["wall_s"])
    return "/".join(parts)


def peak(rec):
    vals = [r.get("peak_mb") for r in rec["runs"].values() if r.get("peak_mb")]
    return "%.0f" % max(vals) if vals else "-"


def auto_line(rec):
    r = rec["runs"].get("auto")
    if r is None or not r["auto_lines"]:
        return ""
    return " / ".join(r["auto_lines"]).replace("|", "/")


def report(results):
    recs = sorted(results["clouds"].values(), key=lambda r: (r["order"][0], r["order"][1]))
    classes = []
    for r in recs:
        if r["class"] not in classes:
            classes.append(r["class"])
    # classes in the order: family, then the first row of the class
    fam_order = list(FAMILIES)
    classes.sort(key=lambda c: (fam_order.index(next(r["family"] for r in recs if r["class"] == c)),
                                min(r["order"][0] for r in recs if r["class"] == c)))
    meta = results.get("meta", {})
    out = ["# Topology study: right / flagged / silent by class", ""]
    tps = meta.get("oracle_tp", list(ORACLE_TP))
    out.append(
        "Made by `Benchmarks/Study/topology_study.py` (%s). Truth = the Betti numbers of the sampled set; "
        "a fixed (`--tp 1.1 --tr 2`) or auto (no `--tr`/`--tp`) answer is *right*, "
        "*flagged* (wrong, with a `warning:` line), *silent* (wrong, no warning) or an "
        "*error*. Auto better / worse / other change: right only with auto / right only "
        "with fixed / both wrong with different Betti numbers. Oracle: the t_r windows with "
        "the truth, from the topology profile of `--tp P --tr %s --tr-max %s`, for P in {%s}. "
        "Time: seconds of fixed / auto / the oracle's %d runs; peak: the largest RSS of a run "
        "(MB). Noisy clouds: Poisson-disk samples plus Gaussian noise of standard deviation "
        "f x their mean nearest-neighbour spacing on each coordinate." % (
            ", ".join("%s: %s" % (k, meta[k]) for k in ("flowrecon_build", "updated") if k in meta),
            ORACLE_TR, meta.get("oracle_tr_max", ORACLE_TR_MAX), ", ".join(tps), len(tps)))
    binaries = sorted({x.get("build") for r in recs for x in r["runs"].values() if x.get("build")})
    if len(binaries) > 1:
        out.append("")
        out.append("**Note:** the runs come from %d different flowrecon binaries (%s): "
                   "rerun with `--fresh` to compare like with like." % (len(binaries), ", ".join(binaries)))
    notes = []
    for cls in classes:
        rows = [r for r in recs if r["class"] == cls]
        out += ["", "## %s" % cls, "",
                "| cloud | n | truth | fixed | auto | oracle achievable | auto chose | s | peak MB |",
                "|---|---:|---|---|---|---|---|---:|---:|"]
        for r in rows:
            name = r["base"] + ("" if r["noise"] is None else ", noise %g x spacing" % r["noise"])
            if r["shape"] != r["base"]:
                name += " (`%s`)" % r["shape"]
            out.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s |" % (
                name, r["n"], btext(r["truth"]), run_cell(r["runs"].get("fixed")),
                run_cell(r["runs"].get("auto")), oracle_cell(r["runs"].get("oracle")),
                auto_line(r), seconds(r), peak(r)))
            o, f = r["runs"].get("oracle"), r["runs"].get("fixed")
            if o and f and f["betti"] is not None and "1.1" in o["tp"]:
                at2 = o["tp"]["1.1"].get("betti_at_2")
                if at2 is not None and at2 != f["betti"]:
                    notes.append("%s: fixed gives %s but the t_p 1.1 profile gives %s at t_r 2"
                                 % (r["id"], btext(f["betti"]), btext(at2)))
    out += ["", "## Summary", "",
            "| class | clouds | fixed right | fixed flagged | fixed silent | fixed error "
            "| auto right | auto flagged | auto silent | auto error | auto better / worse / other change "
            "| truth achievable |",
            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for cls in classes + [None]:
        rows = recs if cls is None else [r for r in recs if r["class"] == cls]
        cells = [len(rows)]
        for c in ("fixed", "auto"):
            ran = [r["runs"][c] for r in rows if c in r["runs"]]
            cells += [sum(1 for x in ran if x["result"] == k) if ran else "-"
                      for k in ("right", "flagged", "silent", "error")]
        both = [(r["runs"]["fixed"], r["runs"]["auto"]) for r in rows
                if "fixed" in r["runs"] and "auto" in r["runs"]]
        if both:
            better = sum(1 for f, a in both if a["result"] == "right" and f["result"] != "right")
            worse = sum(1 for f, a in both if f["result"] == "right" and a["result"] != "right")
            other = sum(1 for f, a in both if f["result"] != "right" and a["result"] != "right"
                        and f["betti"] != a["betti"])
            cells.append("%d / %d / %d" % (better, worse, other))
        else:
            cells.append("-")
        orc = [r["runs"]["oracle"] for r in rows if "oracle" in r["runs"]]
        if orc:
            yes = sum(1 for o in orc if o["achievable"])
            unk = sum(1 for o in orc if o["achievable"] is None)
            cells.append("%d / %d%s" % (yes, len(orc), " (%d unknown)" % unk if unk else ""))
        else:
            cells.append("-")
        label = "**all**" if cls is None else cls
        out.append("| %s | %s |" % (label, " | ".join(map(str, cells))))
    if notes:
        out += ["", "Consistency notes (the fixed run against the oracle's t_p 1.1 profile at t_r 2):", ""]
        out += ["- " + n for n in notes]
    wall = sum(r["runs"][c]["wall_s"] for r in recs for c in r["runs"])
    out += ["", "%d clouds, %.0f s of flowrecon wall time in all (%.0f s making clouds)." % (
        len(recs), wall, sum(r.get("generated_s", 0) for r in recs))]
    return "\n".join(out) + "\n"


# --------------------------------------------------------------------------- main


def write_json(path, results):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(results, f, indent=1, sort_keys=True)
    os.replace(tmp, path)


def write_report(outdir, results):
    text = report(results)
    with open(os.path.join(outdir, "study.md"), "w") as f:
        f.write(text)
    return text


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--flowrecon", default="build/bin/flowrecon")
    ap.add_argument("--large", action="store_true")
    ap.add_argument("--only", default=None, metavar="REGEX")
    ap.add_argument("--sizes", default=None, help="comma-separated nominal sizes")
    ap.add_argument("--configs", default=",".join(CONFIGS))
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=0)
    ap.add_argument("--oracle-tp", default=",".join(ORACLE_TP))
    ap.add_argument("--oracle-tr-max", default=ORACLE_TR_MAX)
    ap.add_argument("--oracle-betti-max-cells", default=None)
    ap.add_argument("--keep-vtu", action="store_true")
    ap.add_argument("--regenerate", action="store_true")
    ap.add_argument("--no-snapshot", action="store_true")
    ap.add_argument("--fresh", action="store_true")
    ap.add_argument("--report-only", action="store_true")
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args(argv)

    outdir = args.outdir
    json_path = os.path.join(outdir, "results.json")
    if args.report_only:
        with open(json_path) as f:
            results = json.load(f)
        print(write_report(outdir, results), end="")
        return 0

    configs = [c for c in args.configs.split(",") if c]
    bad = [c for c in configs if c not in CONFIGS]
    if bad:
        ap.error("unknown configuration(s) %s (known: %s)" % (", ".join(bad), ", ".join(CONFIGS)))
    selected = clouds(args.large)
    if args.sizes:
        sizes = {int(float(s)) for s in args.sizes.split(",") if s}
        selected = [c for c in selected if c["nominal"] in sizes]
    if args.only:
        rx = re.compile(args.only)
        selected = [c for c in selected if rx.search(c["id"]) or rx.search(c["class"])
                    or rx.search(c["class"].replace("×", "x"))]
    if args.list:
        for c in selected:
            print("%-34s %-48s truth %s" % (c["id"], c["class"], btext(c["truth"])))
        print("%d clouds" % len(selected))
        return 0
    if not os.access(args.flowrecon, os.X_OK):
        ap.error("no executable %s (--flowrecon)" % args.flowrecon)

    os.makedirs(os.path.join(outdir, "clouds"), exist_ok=True)
    os.makedirs(os.path.join(outdir, "runs"), exist_ok=True)
    results = {"clouds": {}}
    if os.path.exists(json_path) and not args.fresh:
        with open(json_path) as f:
            results = json.load(f)
    if args.no_snapshot:
        flowrecon, env = os.path.abspath(args.flowrecon), None
        binary = build_hash(build_files(args.flowrecon))
    else:
        flowrecon, env, binary = snapshot(args.flowrecon, outdir)
    opts = {"outdir": outdir, "flowrecon": flowrecon, "env": env,
            "configs": configs, "threads": args.threads, "timeout": args.timeout,
            "oracle_tp": [t for t in args.oracle_tp.split(",") if t],
            "oracle_tr_max": args.oracle_tr_max,
            "oracle_betti_max_cells": args.oracle_betti_max_cells,
            "keep_vtu": args.keep_vtu, "regenerate": args.regenerate}
    results["meta"] = {"flowrecon": args.flowrecon, "flowrecon_build": binary,
                       "oracle_tp": opts["oracle_tp"], "oracle_tr_max": args.oracle_tr_max,
                       "threads": args.threads, "jobs": args.jobs,
                       "updated": datetime.datetime.now().isoformat(timespec="seconds")}

    def store(rec):
        old = results["clouds"].get(rec["id"], {})
        for r in rec["runs"].values():
            r["build"] = binary
        runs = dict(old.get("runs", {}))
        runs.update(rec["runs"])          # configurations not run now are kept
        rec["runs"] = runs
        results["clouds"][rec["id"]] = rec
        write_json(json_path, results)
        line = "  ".join("%s %s" % (c, rec["runs"][c]["result"] if c != "oracle" else
                                    {True: "achievable", False: "not achievable",
                                     None: "unknown"}[rec["runs"][c]["achievable"]])
                         for c in configs)
        print("%-34s n %7d truth %-7s %s  (%.1f s)" % (
            rec["id"], rec["n"], btext(rec["truth"]), line,
            sum(rec["runs"][c]["wall_s"] for c in configs)), file=sys.stderr, flush=True)

    # the largest first, so that the pool ends together; the 10^6 ones alone at the end
    light = sorted([c for c in selected if not c["heavy"]], key=lambda c: -c["nominal"])
    heavy = [c for c in selected if c["heavy"]]
    start = time.time()
    if args.jobs > 1 and len(light) > 1:
        with concurrent.futures.ProcessPoolExecutor(max_workers=args.jobs) as pool:
            futures = [pool.submit(study_cloud, c, opts) for c in light]
            for fut in concurrent.futures.as_completed(futures):
                store(fut.result())
    else:
        for c in light:
            store(study_cloud(c, opts))
    for c in heavy:
        store(study_cloud(c, opts))
    print("%d clouds in %.0f s" % (len(selected), time.time() - start), file=sys.stderr)
    print(write_report(outdir, results), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
