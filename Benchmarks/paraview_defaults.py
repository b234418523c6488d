"""pvbatch benchmark: the three FlowRecon filters at their defaults on a cloud
(t_p and t_r chosen from the data), as a ParaView user runs them, then t_r
set by hand below T_max (Automatic Reconstruction Threshold off; t_r 3, or each
T_R given in turn).

  /usr/bin/time -v pvbatch Benchmarks/paraview_defaults.py PLUGIN CLOUD.xyz [T_R ...]

Prints the seconds of the first update of each filter, of each t_r change,
the process's resident and peak memory after each (so the stage that sets the
peak is named), and the number of cells shown; the whole process's peak is
/usr/bin/time's.
"""
import sys
import time

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile

LoadPlugin(sys.argv[1], ns=globals())  # defines FlowComplex, ... in this module
source = OpenDataFile(sys.argv[2])
stages = []


def memory():
    """(resident, peak) GB of this process, from /proc (Linux)."""
    fields = dict(line.split(":", 1) for line in open("/proc/self/status"))
    return tuple(int(fields[k].split()[0]) / 2**20 for k in ("VmRSS", "VmHWM"))


def done(name, t0):
    stages.append((name, time.time() - t0) + memory())


t0 = time.time()
complex_ = FlowComplex(Input=source)
complex_.UpdatePipeline()
done("Flow Complex", t0)
t0 = time.time()
simplified = FlowComplexSimplification(Input=complex_)
simplified.UpdatePipeline()
done("Flow Complex Simplification", t0)
t0 = time.time()
recon = FlowReconstruction(Input=simplified)
recon.UpdatePipeline()
done("Flow Reconstruction", t0)
cells = recon.GetDataInformation().GetNumberOfCells()
fd = servermanager.Fetch(recon).GetFieldData()


def values(name, count):
    """The first `count` values of a field array, or None when the filter wrote
    none (no Betti numbers: the cells exceeded MaximumTopologyCells)."""
    a = fd.GetArray(name)
    if a is None or a.GetNumberOfTuples() * a.GetNumberOfComponents() < count:
        return None
    return [a.GetValue(k) for k in range(count)]


tr = values("ReconstructionThreshold", 1)
tp = values("PersistenceThreshold", 1)
betti = values("BettiNumbers", 3)
recon.AutomaticReconstructionThreshold = 0
typed = [float(a) for a in sys.argv[3:]] or [3.0]
for value in typed:
    t0 = time.time()
    recon.ReconstructionThreshold = value
    recon.UpdatePipeline()
    done("t_r -> %g" % value, t0)
cells3 = recon.GetDataInformation().GetNumberOfCells()
for stage in stages:
    print("%s: %.2f s, resident %.2f GB, peak so far %.2f GB" % stage)
print("automatic: t_r %s, t_p %s, Betti numbers %s, %d cells; at t_r %g: %d cells"
      % ("%.3f" % tr[0] if tr else "none", "%g" % tp[0] if tp else "none",
         " ".join("%d" % b for b in betti) if betti else "none", cells, typed[-1], cells3))
