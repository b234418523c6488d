# ParaView shows the CLI's Betti numbers, topology profile and under-sampling
# places (ports 0, 3 and 4 of Flow Reconstruction), in pvpython. Included from
# Testing/ParaView/CMakeLists.txt.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.reconstruction.topology_ports
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_topology_ports.py"
            "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>"
            "${CMAKE_CURRENT_BINARY_DIR}/topology_ports")
  set_tests_properties(pv.reconstruction.topology_ports PROPERTIES LABELS "paraview" TIMEOUT 300
    PASS_REGULAR_EXPRESSION "PASS")
endif ()

# The pipeline at its defaults chooses t_p and t_r as the command line does,
# and gets a 10^5-point i.i.d. torus right (1 2 1).
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.reconstruction.automatic_pipeline
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_automatic_pipeline.py"
            "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>"
            "${CMAKE_CURRENT_BINARY_DIR}/automatic_pipeline")
  set_tests_properties(pv.reconstruction.automatic_pipeline PROPERTIES LABELS "paraview" TIMEOUT 600
    PASS_REGULAR_EXPRESSION "PASS")
endif ()
