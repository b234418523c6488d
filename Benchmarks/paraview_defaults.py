"""pvbatch benchmark: the three FlowRecon filters at their defaults on a cloud,
as a ParaView user runs them, then a change of t_r below T_max.

  /usr/bin/time -v pvbatch Benchmarks/paraview_defaults.py PLUGIN CLOUD.xyz

Prints the seconds of the first update of each filter, of a t_r change (2 -> 3)
and the number of cells shown; peak memory is the process's (use /usr/bin/time).
"""
import sys
import time

from paraview.simple import LoadPlugin, OpenDataFile

LoadPlugin(sys.argv[1], ns=globals())  # defines FlowComplex, ... in this module
source = OpenDataFile(sys.argv[2])
stages = []
t0 = time.time()
complex_ = FlowComplex(Input=source)
complex_.UpdatePipeline()
stages.append(("Flow Complex", time.time() - t0))
t0 = time.time()
simplified = FlowComplexSimplification(Input=complex_)
simplified.UpdatePipeline()
stages.append(("Flow Complex Simplification", time.time() - t0))
t0 = time.time()
recon = FlowReconstruction(Input=simplified)
recon.UpdatePipeline()
stages.append(("Flow Reconstruction", time.time() - t0))
cells2 = recon.GetDataInformation().GetNumberOfCells()
t0 = time.time()
recon.ReconstructionThreshold = 3.0
recon.UpdatePipeline()
stages.append(("t_r 2 -> 3", time.time() - t0))
cells3 = recon.GetDataInformation().GetNumberOfCells()
print("; ".join("%s %.2f s" % s for s in stages))
print("cells at t_r 2: %d, at t_r 3: %d" % (cells2, cells3))
