# Deferred patches through the ParaView filters: Flow Complex with
# Defer Patches Above against the eager pipeline, cell by cell, and the errors
# of settings that do not fit (pv.deferred_pipeline, no X server needed).
# Included from Testing/ParaView/CMakeLists.txt.
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.deferred_pipeline
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_deferred_pipeline.py"
            "$<TARGET_FILE:FlowRecon>" "${CMAKE_CURRENT_BINARY_DIR}/deferred_pipeline"
            "$<TARGET_FILE:flowrecon>")
  set_tests_properties(pv.deferred_pipeline PROPERTIES
    PASS_REGULAR_EXPRESSION "PASS"
    FAIL_REGULAR_EXPRESSION "FAIL"
    LABELS "paraview"
    ENVIRONMENT "DISPLAY="
    TIMEOUT 300)
endif ()
