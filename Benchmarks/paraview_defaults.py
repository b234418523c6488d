"""pvbatch benchmark: the three FlowRecon filters at their defaults on a cloud,
as a ParaView user runs them, then a change of t_r below T_max.

  /usr/bin/time -v pvbatch Benchmarks/paraview_defaults.py PLUGIN CLOUD.xyz

Prints the seconds of the first update of each filter, of a t_r change (2 -> 3),
the process's resident and peak memory after each (so the stage that sets the
peak is named), and the number of cells shown; the whole process's peak is
/usr/bin/time's.
"""
import sys
import time

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
cells2 = recon.GetDataInformation().GetNumberOfCells()
t0 = time.time()
recon.ReconstructionThreshold = 3.0
recon.UpdatePipeline()
done("t_r 2 -> 3", t0)
cells3 = recon.GetDataInformation().GetNumberOfCells()
for stage in stages:
    print("%s: %.2f s, resident %.2f GB, peak so far %.2f GB" % stage)
print("cells at t_r 2: %d, at t_r 3: %d" % (cells2, cells3))
