# Python scripts that run the command-line tool `flowrecon` and check what it writes
# against independent oracles (labels cli and python; included from
# Testing/CLI/CMakeLists.txt; need python3-gudhi). They import flowcomplex_io.py from
# Testing/Filters/Python.
# `flowrecon diagram` against GUDHI's alpha-complex persistence, and the flow complex
# on any number of threads.
if (TARGET flowrecon)
  add_test(NAME py.diagram_gudhi
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_diagram_gudhi.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/diagram_gudhi")
  set_tests_properties(py.diagram_gudhi PROPERTIES LABELS "python" TIMEOUT 300)
endif ()

# The flow complex is the same on 1, 2 and all threads (the core is parallel).
if (TARGET flowrecon)
  add_test(NAME py.threads_determinism
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_threads.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/threads")
  set_tests_properties(py.threads_determinism PROPERTIES
    ENVIRONMENT "PYTHONPATH=${FLOWRECON_PYTHONPATH}" LABELS "python" TIMEOUT 300)
endif ()

# The output-sensitive reconstruction equals the eager one below every t_r
# (DESIGN.md, "Cost follows the output").
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.lazy_equals_eager
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_lazy_equals_eager.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/lazy_equals_eager")
  set_tests_properties(py.reconstruction.lazy_equals_eager PROPERTIES LABELS "python" TIMEOUT 300)
endif ()

# Betti numbers of reconstructions (issue #9): the printed line, the field data
# and the topology profile equal GUDHI's persistence over the written cells
# filtered by Threshold, from a cloud and from a saved flow complex.
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.topology_profile
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_topology_profile.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/topology_profile")
  set_tests_properties(py.reconstruction.topology_profile PROPERTIES LABELS "python" TIMEOUT 300)
endif ()

# Under-sampling warnings (issue #9): none on clean quasi-uniform samples, and
# inside the thinned region of thinned ones.
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.undersampling
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_undersampling.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/undersampling")
  set_tests_properties(py.reconstruction.undersampling PROPERTIES LABELS "python" TIMEOUT 300)
endif ()

# The reconstruction does not depend on the order of the input lines (cube,
# sphere, torus, exact grid, duplicates; t_p 1.1 and 0), and 10^6 lines holding
# 5 distinct points give a .vtu of a handful of points (issue #12).
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
if (TARGET flowrecon)
  add_test(NAME py.reconstruction.automatic_thresholds
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_automatic_thresholds.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/automatic_thresholds")
  set_tests_properties(py.reconstruction.automatic_thresholds PROPERTIES LABELS "python" TIMEOUT 300)
endif ()
