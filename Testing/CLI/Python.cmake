# Python scripts that run the command-line tool `flowrecon` and check what it writes
# against independent oracles (labels cli and python; included from
# Testing/CLI/CMakeLists.txt; need python3-gudhi). They import flowcomplex_io.py from
# Testing/Filters/Python.

# flowrecon_add_cli_python_test(NAME SCRIPT WORKDIR): SCRIPT (of this folder) run
# as SCRIPT FLOWRECON BUILD/WORKDIR, label python, 300 s.
function (flowrecon_add_cli_python_test name script workdir)
  if (TARGET flowrecon)
    add_test(NAME ${name}
      COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/${script}"
              "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/${workdir}")
    set_tests_properties(${name} PROPERTIES LABELS "python" TIMEOUT 300)
  endif ()
endfunction ()

# `flowrecon diagram` against GUDHI's alpha-complex persistence, and the flow complex
# on any number of threads.
flowrecon_add_cli_python_test(py.diagram_gudhi test_diagram_gudhi.py diagram_gudhi)

# The flow complex is the same on 1, 2 and all threads (the core is parallel).
if (TARGET flowrecon)
  add_test(NAME py.threads_determinism
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_threads.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/threads")
  set_tests_properties(py.threads_determinism PROPERTIES
    ENVIRONMENT "PYTHONPATH=${FLOWRECON_PYTHONPATH}" LABELS "python" TIMEOUT 300)
endif ()

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
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.permutation
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_permutation.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/permutation")
  add_test(NAME py.reconstruction.million_duplicates
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_permutation.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/million_duplicates" --duplicates)
  set_tests_properties(py.reconstruction.permutation py.reconstruction.million_duplicates
    PROPERTIES LABELS "python" TIMEOUT 300)
endif ()

# Without simplification the reconstruction at t_r = inf is contractible (the
# complement of an open cell): the written cones of index-3 cells must not
# enclose voids where a cell meets itself.
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.contractible
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_contractible.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/contractible")
  set_tests_properties(py.reconstruction.contractible PROPERTIES LABELS "python" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "PASS")
endif ()

# The largest jumps of the profile (the field data of Flow Reconstruction's
# profile) equal what `flowrecon reconstruct --jumps` prints for the same cloud
# through the core, and the largest rises of the profile's Threshold column.
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.profile_jumps
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_profile_jumps.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/profile_jumps")
  set_tests_properties(py.reconstruction.profile_jumps PROPERTIES
    ENVIRONMENT "PYTHONPATH=${FLOWRECON_PYTHONPATH}" LABELS "python" TIMEOUT 300)
endif ()

# The automatic t_r and t_p give the true Betti numbers on the study's
# generators (surfaces, lattices, a solid, a non-manifold union, a curve).
flowrecon_add_cli_python_test(py.reconstruction.automatic_thresholds test_automatic_thresholds.py automatic_thresholds)

# Critical values of perturbed (degenerate) clouds come from the unperturbed
# points: exact on grids and cospherical sets, equal to GUDHI's exact alpha
# persistence within 1e-12 relative, lazy reconstruction equal to eager.
flowrecon_add_cli_python_test(py.exact_perturbed_values test_exact_perturbed_values.py exact_perturbed_values)
