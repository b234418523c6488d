# What Flow Complex and the other filters show by default in ParaView:
# Apply's displays in a render view, their colouring, colour legends, blocks and
# camera, the plugin's categorical colour maps and that user settings beat them
# (pv.default_display, no X server needed). Included from
# Testing/ParaView/CMakeLists.txt.
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.default_display
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_default_display.py"
            "$<TARGET_FILE:FlowRecon>" "${CMAKE_CURRENT_BINARY_DIR}/default_display")
  set_tests_properties(pv.default_display PROPERTIES
    PASS_REGULAR_EXPRESSION "PASS"
    FAIL_REGULAR_EXPRESSION "FAIL"
    LABELS "paraview"
    # Nothing is rendered: without DISPLAY no X server can refuse the connection
    # (it aborted once under xvfb-run -j2).
    ENVIRONMENT "DISPLAY="
    TIMEOUT 300)
endif ()
