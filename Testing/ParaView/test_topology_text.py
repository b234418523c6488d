"""The answer in words: Flow Reconstruction's field data Topology (one line, what the
Information panel shows) and its Topology Text port (the same line, one clause per
line), against the other outputs and the command line, in pvpython:

  * Data/torus.xyz at the defaults (automatic t_r and t_p) and at a given t_r (2.0,
    automatic t_p), Data/two_hemispheres.xyz at the defaults: the Betti numbers of the
    line are the field data BettiNumbers and the topology profile's row at t_r; its
    t_r is ReconstructionThreshold to 3 decimals, "(auto)" after t_r and t_p exactly
    when ThresholdsChosen says so, its t_p is PersistenceThreshold; its range of t_r
    is StableWindow when there is one, else the profile's range of the same Betti
    numbers around t_r (merged here from the rows); its number of warnings is the
    lines of ThresholdWarnings plus the distinct places of the Under Sampling port
    (t_r, node, dimension, direction); the panel's array information carries the line;
    port 5 is the line broken after the Betti numbers and at each "; ";
  * Compute Topology off: the line says there are no Betti numbers;
  * `flowrecon reconstruct` of the same clouds at the defaults prints the same Betti
    numbers, thresholds, range and number of warning lines as the filter's line, and
    writes the same line into its .vtu.
Usage: pvpython test_topology_text.py PLUGIN FLOWRECON DATA_DIR WORKDIR
"""
import os
import re
import subprocess
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, OutputPort  # noqa: F401

from flowrecon_testing.checks import check, finish

PLUGIN, FLOWRECON, DATA, WORK = sys.argv[1:5]
LoadPlugin(PLUGIN, remote=False, ns=globals())
os.makedirs(WORK, exist_ok=True)

LINE = re.compile(
    r"^Betti numbers (\d+) (\d+) (\d+) at t_r ([0-9.]+)( \(auto\))?, t_p ([0-9.e+-]+)( \(auto\))?"
    r"; unchanged for ([0-9.]+) < t_r <= ([0-9.]+)( \(as far as computed\))?; (\d+) warnings?$")


def values(field, name):
    a = field.GetAbstractArray(name)
    if a is None:
        return None
    return [a.GetVariantValue(k).ToString() if a.IsA("vtkStringArray") else a.GetComponent(k, 0)
            for k in range(a.GetNumberOfValues())]


def profile_rows(table):
    cols = [table.GetColumnByName(n) for n in ("Threshold", "b0", "b1", "b2")]
    return [(cols[0].GetValue(r),) + tuple(int(c.GetValue(r)) for c in cols[1:])
            for r in range(table.GetNumberOfRows())]


def range_around(rows, t, limit):
    """(from, to, betti) of the maximal run of rows with the Betti numbers at t."""
    k = max(i for i, row in enumerate(rows) if i == 0 or row[0] < t)
    betti = rows[k][1:]
    lo = k
    while lo > 0 and rows[lo - 1][1:] == betti:
        lo -= 1
    hi = k
    while hi + 1 < len(rows) and rows[hi + 1][1:] == betti:
        hi += 1
    end = rows[hi + 1][0] if hi + 1 < len(rows) else limit
    return max(rows[lo][0], 1.0), min(end, limit), betti


def places(undersampling):
    pd = undersampling.GetPointData()
    arrays = [pd.GetArray(n) for n in ("Threshold", "NodeId", "Dimension", "Change")]
    if undersampling.GetNumberOfPoints() == 0:
        return 0
    return len({(a[0].GetValue(i), a[1].GetValue(i), a[2].GetValue(i), a[3].GetValue(i) > 0)
                for i in range(undersampling.GetNumberOfPoints()) for a in [arrays]})


def check_line(label, recon, limit):
    recon.UpdatePipeline()
    grid = servermanager.Fetch(recon, idx=0)
    table = servermanager.Fetch(recon, idx=3)
    under = servermanager.Fetch(recon, idx=4)
    text = servermanager.Fetch(recon, idx=5)
    field = grid.GetFieldData()
    line = values(field, "Topology")
    if not check(line is not None and len(line) == 1, "%s: no one-value field data Topology" % label):
        return None
    line = line[0]
    print("%s: %s" % (label, line))
    m = LINE.match(line)
    if not check(m is not None, "%s: the line does not read as expected: %r" % (label, line)):
        return None
    g = m.groups()
    betti = tuple(int(x) for x in g[0:3])
    t = values(field, "ReconstructionThreshold")[0]
    chosen = values(field, "ThresholdsChosen")
    rows = profile_rows(table)
    at_t = [row for row in rows if row[0] < t] or rows[:1]
    check(betti == tuple(int(v) for v in values(field, "BettiNumbers")),
          "%s: Betti numbers %s, field data %s" % (label, betti, values(field, "BettiNumbers")))
    check(betti == at_t[-1][1:], "%s: Betti numbers %s, profile at t_r %s" % (label, betti, at_t[-1]))
    check(g[3] == "%.3f" % t, "%s: t_r %s, field data %r" % (label, g[3], t))
    check(bool(g[4]) == (chosen[0] == 1) and bool(g[6]) == (chosen[1] == 1),
          "%s: (auto) marks %s, ThresholdsChosen %s" % (label, (g[4], g[6]), chosen))
    check(float(g[5]) == values(field, "PersistenceThreshold")[0],
          "%s: t_p %s, field data %s" % (label, g[5], values(field, "PersistenceThreshold")))
    window = values(field, "StableWindow")
    lo, hi, run_betti = range_around(rows, t, limit)
    if window:
        expected = (window[0], window[1])
    else:
        check(run_betti == betti, "%s: the profile's run at t_r has %s" % (label, run_betti))
        expected = (lo, hi)
    check((g[7], g[8]) == ("%.2f" % expected[0], "%.2f" % expected[1]),
          "%s: range %s < t_r <= %s, expected %s" % (label, g[7], g[8], expected))
    check(bool(g[9]) == (expected[1] >= limit),
          "%s: 'as far as computed' %s with the range ending at %s (limit %s)"
          % (label, bool(g[9]), expected[1], limit))
    warnings = len(values(field, "ThresholdWarnings") or []) + places(under)
    check(int(g[10]) == warnings, "%s: %s warnings, expected %d (ThresholdWarnings %s, places %d)"
          % (label, g[10], warnings, values(field, "ThresholdWarnings"), places(under)))
    # what the Information panel lists for the array
    info = recon.GetDataInformation().DataInformation.GetFieldDataInformation()
    ai = info.GetArrayInformation("Topology")
    shown = [ai.GetStringValue(k) for k in range(ai.GetNumberOfStringValues())] if ai else []
    check(shown == [line], "%s: the panel's information of Topology is %s" % (label, shown))
    check(text.GetNumberOfRows() == 1 and text.GetNumberOfColumns() == 1
          and text.GetColumn(0).GetName() == "Topology",
          "%s: port 5 is not one row of a column Topology" % label)
    if text.GetNumberOfRows() == 1:
        check(text.GetValue(0, 0).ToString() == line.replace(" at t_r", "\nat t_r", 1).replace("; ", "\n"),
              "%s: port 5 says %r" % (label, text.GetValue(0, 0).ToString()))
    return betti, g, line


def pipeline(cloud, **recon_args):
    reader = OpenDataFile(os.path.join(DATA, cloud))
    fc = FlowComplex(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    simp = FlowComplexSimplification(Input=fc)  # noqa: F821
    return FlowReconstruction(Input=simp, **recon_args)  # noqa: F821


def cli(cloud):
    out = os.path.join(WORK, cloud + ".vtu")
    p = subprocess.run([FLOWRECON, "reconstruct", os.path.join(DATA, cloud), "-o", out],
                       capture_output=True, text=True)
    check(p.returncode == 0, "flowrecon reconstruct %s: %s" % (cloud, p.stderr))
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(out)
    r.Update()
    a = r.GetOutput().GetFieldData().GetAbstractArray("Topology")
    return p.stdout, p.stderr, a.GetValue(0) if a is not None else None


def main():
    for cloud in ("torus.xyz", "two_hemispheres.xyz"):
        recon = pipeline(cloud)
        result = check_line(cloud + " defaults", recon, recon.MaximumThreshold)
        if result is None:
            continue
        betti, g, line = result
        stdout, stderr, written = cli(cloud)
        m = re.search(r"Betti numbers: (\d+) (\d+) (\d+)", stdout)
        check(m is not None and tuple(int(x) for x in m.groups()) == betti,
              "%s: the CLI prints %s" % (cloud, m.group(0) if m else stdout))
        m = re.search(r"t_r ([0-9.]+) \(auto\), t_p ([0-9.]+) \(auto\): .*unchanged for t_r in "
                      r"\(([0-9.]+), ([0-9.]+)\]", stdout)
        check(m is not None and m.groups() == (g[3], g[5], g[7], g[8]),
              "%s: the CLI's choice %s, the filter's t_r %s t_p %s range %s-%s"
              % (cloud, m.groups() if m else stdout, g[3], g[5], g[7], g[8]))
        cli_warnings = stderr.count("warning: ")
        check(cli_warnings == int(g[10]), "%s: the CLI warns %d times, the line says %s"
              % (cloud, cli_warnings, g[10]))
        check(written == line, "%s: the CLI's .vtu says %r" % (cloud, written))

    recon = pipeline("torus.xyz", AutomaticReconstructionThreshold=0, ReconstructionThreshold=2.0)
    check_line("torus.xyz t_r 2", recon, recon.MaximumThreshold)

    recon.ComputeTopology = 0
    recon.UpdatePipeline()
    field = servermanager.Fetch(recon, idx=0).GetFieldData()
    line = values(field, "Topology")
    print("torus.xyz without topology: %s" % line)
    check(line == ["t_r 2.000: no Betti numbers (Compute Topology is off)"],
          "Compute Topology off: the line is %s" % line)
    finish()


main()
