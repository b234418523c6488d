"""Pipelines that more than one pvpython test builds, written once. `ns` holds
the plugin's filters: the namespace LoadPlugin(..., ns=ns) filled."""
import os

import generate_clouds as gc
import numpy as np

from flowrecon_testing.clouds import write_xyz


def torus_profiles(ns, work, maximum):
    """(the cloud's path, Flow Reconstruction, updated) of 600 i.i.d. points on a
    torus (seed 4), at given thresholds as the command line's --tp 1.1 (automatic
    t_r off) and capped at maximum, without stable manifolds in Flow Complex."""
    from paraview import simple
    xyz = write_xyz(os.path.join(work, "torus.xyz"), gc.torus(600, np.random.default_rng(4)))
    flow_complex = ns["FlowComplex"](Input=simple.OpenDataFile(xyz), ComputeStableManifolds=0)
    simplified = ns["FlowComplexSimplification"](Input=flow_complex,
                                                 AutomaticPersistenceThreshold=0)
    recon = ns["FlowReconstruction"](Input=simplified, MaximumThreshold=maximum,
                                     AutomaticReconstructionThreshold=0)
    recon.UpdatePipeline()
    return xyz, recon
