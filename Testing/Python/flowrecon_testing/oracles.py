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
