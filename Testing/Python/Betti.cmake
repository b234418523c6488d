# Homotopy type of reconstructions (DESIGN.md §3): Betti numbers over Z/2 of the
# output of vtkFlowReconstruction at the default parameters (t_p = 1.1, t_r = 2) on
# quasi-uniform samples of shapes of known topology made by Data/generate_clouds.py
# (sphere, torus, genus 2, trefoil, ball, two spheres, two hemispheres, sphere with
# a segment). Needs GUDHI (python3-gudhi). Included from Testing/Python/CMakeLists.txt.
if (FLOWRECON_WRAP_PYTHON)
  add_test(NAME py.reconstruction.betti
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_betti.py" --scan)
  set_tests_properties(py.reconstruction.betti PROPERTIES
    ENVIRONMENT "PYTHONPATH=${FLOWRECON_PYTHONPATH}"
    LABELS "python"
    TIMEOUT 300)
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

# ParaView shows the CLI's Betti numbers, topology profile and under-sampling
# places (ports 0, 3 and 4 of Flow Reconstruction), in pvpython.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.reconstruction.topology_ports
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_topology_ports.py"
            "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>"
            "${CMAKE_CURRENT_BINARY_DIR}/topology_ports")
  set_tests_properties(pv.reconstruction.topology_ports PROPERTIES LABELS "paraview" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "PASS")
endif ()
