# Python scripts that run the command-line tool `flowrecon` and check what it writes
# against independent oracles (labels cli and python; included from
# Testing/CLI/CMakeLists.txt; need python3-gudhi), with FLOWRECON_PYTHONPATH as PYTHONPATH.

# flowrecon_add_cli_python_test(NAME SCRIPT WORKDIR [ARGS...]): SCRIPT (of this folder) run
# as SCRIPT FLOWRECON BUILD/WORKDIR ARGS..., label python, 300 s.
function (flowrecon_add_cli_python_test name script workdir)
  if (TARGET flowrecon)
    add_test(NAME ${name}
      COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/${script}"
              "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/${workdir}" ${ARGN})
    set_tests_properties(${name} PROPERTIES LABELS "python" TIMEOUT 300
      ENVIRONMENT "PYTHONPATH=${FLOWRECON_PYTHONPATH}")
  endif ()
endfunction ()

# `flowrecon diagram` against GUDHI's alpha-complex persistence, and the flow complex
# on any number of threads.
flowrecon_add_cli_python_test(py.diagram_gudhi test_diagram_gudhi.py diagram_gudhi)

# The flow complex is the same on 1, 2 and all threads (the core is parallel).
flowrecon_add_cli_python_test(py.threads_determinism test_threads.py threads)

# The restart with huge pages (Apps/HugePages.h): the tunable reaches the running
# process as documented, the arguments survive, the output does not change.
flowrecon_add_cli_python_test(py.huge_pages test_huge_pages.py huge_pages)

# The output-sensitive reconstruction equals the eager one below every t_r
# (docs/design.md, "Cost follows the output").
flowrecon_add_cli_python_test(py.reconstruction.lazy_equals_eager test_lazy_equals_eager.py lazy_equals_eager)

# Betti numbers of reconstructions: the printed line, the field data
# and the topology profile equal GUDHI's persistence over the written cells
# filtered by Threshold, from a cloud and from a saved flow complex.
flowrecon_add_cli_python_test(py.reconstruction.topology_profile test_topology_profile.py topology_profile)

# Under-sampling warnings: none on clean quasi-uniform samples, and
# inside the thinned region of thinned ones.
flowrecon_add_cli_python_test(py.reconstruction.undersampling test_undersampling.py undersampling)

# The reconstruction does not depend on the order of the input lines (cube,
# sphere, torus, exact grid, duplicates; t_p 1.1 and 0), and 10^6 lines holding
# 5 distinct points give a .vtu of a handful of points.
flowrecon_add_cli_python_test(py.reconstruction.permutation test_permutation.py permutation)
flowrecon_add_cli_python_test(py.reconstruction.million_duplicates test_permutation.py
  million_duplicates --duplicates)

# Without simplification the reconstruction at t_r = inf is contractible (the
# complement of an open cell): the written cones of index-3 cells must not
# enclose voids where a cell meets itself.
flowrecon_add_cli_python_test(py.reconstruction.contractible test_contractible.py contractible)
if (TEST py.reconstruction.contractible)
  set_tests_properties(py.reconstruction.contractible PROPERTIES PASS_REGULAR_EXPRESSION "PASS")
endif ()

# The largest jumps of the profile (the field data of Flow Reconstruction's
# profile) equal what `flowrecon reconstruct --jumps` prints for the same cloud
# through the core, and the largest rises of the profile's Threshold column.
flowrecon_add_cli_python_test(py.reconstruction.profile_jumps test_profile_jumps.py profile_jumps)

# The automatic t_r and t_p give the true Betti numbers on the study's
# generators (surfaces, lattices, a solid, a non-manifold union, a curve).
flowrecon_add_cli_python_test(py.reconstruction.automatic_thresholds test_automatic_thresholds.py automatic_thresholds)

# And on shapes outside that study (sharp edges, open boundaries, a flat
# ellipsoid): right when clean, warned when wrong under noise.
flowrecon_add_cli_python_test(py.reconstruction.held_out_shapes test_held_out_shapes.py held_out_shapes)

# And on closed surfaces apart or joined: isosurface vertices (a segmentation's
# cloud) of seven shapes, two spheres alone and joined by a rod.
flowrecon_add_cli_python_test(py.reconstruction.separate_surfaces test_separate_surfaces.py separate_surfaces)

# And on the vertices of decimated meshes (dense where the surface bends, sparse
# where it is flat), truth from the mesh: right or warned, and a warning that
# closed surfaces were apart below the answer names a range that parts them.
flowrecon_add_cli_python_test(py.reconstruction.mesh_vertices test_mesh_vertices.py mesh_vertices)

# Parts side by side: a sphere scanned along parallels and a knot tube's grid of
# vertices (rows far finer along than across) answer their rows as curves and
# are warned, with the gap a k-d tree finds; far-apart circles and even
# samplings are not.
flowrecon_add_cli_python_test(py.reconstruction.parts_side_by_side test_parts_side_by_side.py parts_side_by_side)

# Too few samples to tell a surface from a volume (under 200): a window with a
# void is taken when there is one (never on a ball's samples), warned either way.
flowrecon_add_cli_python_test(py.reconstruction.few_samples test_few_samples.py few_samples)

# Samples apart from the rest (outliers strewn in a cloud's box): warned, as
# many as an independent Gabriel-edge count (scipy) finds; clean clouds not.
flowrecon_add_cli_python_test(py.reconstruction.far_samples test_far_samples.py far_samples)

# Critical values of perturbed (degenerate) clouds come from the unperturbed
# points: exact on grids and cospherical sets, equal to GUDHI's exact alpha
# persistence within 1e-12 relative, lazy reconstruction equal to eager.
flowrecon_add_cli_python_test(py.exact_perturbed_values test_exact_perturbed_values.py exact_perturbed_values)

# The default output of reconstruct: the Betti numbers of the written Delaunay
# simplices (GUDHI over the file) equal the exact reconstruction's on surfaces,
# a solid, a curve, a mix and two touching spheres; the file is on the input
# points, states the exact file's answer, and --compact writes it too.
flowrecon_add_cli_python_test(py.reconstruction.compact test_compact.py compact)

# The default output's Betti numbers by GUDHI on every cloud of Testing/Data and
# Data, at several thresholds, from the cloud and its stored complex; --exact
# equals the VTK filters' grid, cell for cell.
flowrecon_add_cli_python_test(py.reconstruction.default_output test_default_output.py default_output)

# Every command's help fits 80 columns and describes each of its options.
flowrecon_add_cli_python_test(py.help test_help.py help)
