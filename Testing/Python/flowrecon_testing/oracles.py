"""Independent oracles the tests compare FlowRecon's answers with."""
import numpy as np


def gudhi_betti(grid):
    """b0, b1, b2 over Z/2 of the simplicial complex a vtkUnstructuredGrid's vertex,
    line, triangle and tetrahedron cells span (all their faces), by GUDHI."""
    import gudhi
    from vtkmodules.util.numpy_support import vtk_to_numpy
    types = vtk_to_numpy(grid.GetCellTypesArray())
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    off = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    st = gudhi.SimplexTree()
    for vtk_type, k in ((10, 4), (5, 3), (3, 2), (1, 1)):
        idx = np.nonzero(types == vtk_type)[0]
        if len(idx):
            st.insert_batch(np.stack([conn[off[idx] + j] for j in range(k)]), np.zeros(len(idx)))
    st.compute_persistence(persistence_dim_max=True)
    return tuple((st.betti_numbers() + [0, 0, 0])[:3])


def filtered_intervals(grid, array="Threshold"):
    """GUDHI's persistence intervals over Z/2, per dimension 0-2, of the cells of a
    vtkUnstructuredGrid filtered by a cell array (faces take their least value)."""
    import gudhi
    from vtkmodules.util.numpy_support import vtk_to_numpy
    off = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    thr = vtk_to_numpy(grid.GetCellData().GetArray(array))
    st = gudhi.SimplexTree()
    for c in range(len(off) - 1):
        st.insert(conn[off[c]:off[c + 1]].tolist(), float(thr[c]))
    st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
    return [st.persistence_intervals_in_dimension(d) for d in range(3)]


def betti_at(intervals, t):
    """The Betti numbers at t of filtered_intervals: the classes born before t
    that die at t or later."""
    return tuple(int(sum(1 for b, d in intervals[k] if b < t <= d)) for k in range(3))


def default_output_problems(vtu, stdout, stderr):
    """What is wrong with the default output of `flowrecon reconstruct` (Delaunay
    simplices on the samples) written to `vtu`, whose run printed `stdout` and
    `stderr`: GUDHI's Betti numbers of its cells must be the reconstruction's
    ('Betti numbers: b0 b1 b2', from the Hasse diagram) and the compact output's
    printed ones, with no warning that they differ. ([] when right; the Betti
    numbers by GUDHI are the last item's subject when not.)"""
    import re
    from flowrecon_testing.run import read_grid
    exact = re.findall(r"^Betti numbers: (\d+) (\d+) (\d+)$", stdout, re.M)
    compact = re.findall(r"^compact output's Betti numbers (\d+) (\d+) (\d+)$", stdout, re.M)
    if len(exact) != 1 or len(compact) != 1:
        return ["expected one 'Betti numbers:' and one compact Betti line in %r" % stdout]
    exact, compact = (tuple(int(x) for x in b[0]) for b in (exact, compact))
    oracle = gudhi_betti(read_grid(vtu))
    problems = []
    if "compact output's Betti numbers" in stderr:
        problems.append("warned of a difference")
    if compact != oracle:
        problems.append("compact Betti numbers printed %s, GUDHI %s" % (compact, oracle))
    if exact != oracle:
        problems.append("the file's Betti numbers by GUDHI %s, the reconstruction's %s"
                        % (oracle, exact))
    return problems
