# pvpython scripts that run the pipeline beside `flowrecon reconstruct` (the
# plugin and the CLI as arguments) and print PASS. Included from
# Testing/ParaView/CMakeLists.txt.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND FLOWRECON_PVPYTHON)
  function (flowrecon_add_pipeline_vs_cli_test name script timeout)
    add_test(NAME pv.reconstruction.${name}
      COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/${script}"
              "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>"
              "${CMAKE_CURRENT_BINARY_DIR}/${name}")
    set_tests_properties(pv.reconstruction.${name} PROPERTIES LABELS "paraview"
      TIMEOUT ${timeout} PASS_REGULAR_EXPRESSION "PASS")
  endfunction ()
  # ParaView shows the CLI's Betti numbers, topology profile and under-sampling
  # places (ports 0, 3 and 4 of Flow Reconstruction).
  flowrecon_add_pipeline_vs_cli_test(topology_ports test_topology_ports.py 300)
  # The pipeline at its defaults chooses t_p and t_r as the command line does,
  # and gets a 10^5-point i.i.d. torus right (1 2 1).
  flowrecon_add_pipeline_vs_cli_test(automatic_pipeline test_automatic_pipeline.py 600)
  # The answer in words (field data Topology, the Topology Text port) agrees with
  # the other outputs and with what the command line prints and writes.
  add_test(NAME pv.reconstruction.topology_text
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_topology_text.py"
            "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>" "${PROJECT_SOURCE_DIR}/Data"
            "${CMAKE_CURRENT_BINARY_DIR}/topology_text")
  set_tests_properties(pv.reconstruction.topology_text PROPERTIES LABELS "paraview"
    ENVIRONMENT "DISPLAY=" TIMEOUT 300 PASS_REGULAR_EXPRESSION "PASS" FAIL_REGULAR_EXPRESSION "FAIL")
endif ()
