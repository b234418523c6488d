# The charts Flow Reconstruction's profiles open in: the preferred
# views and chart settings of ports 1 and 3, their t_r marks and their contents
# against `flowrecon reconstruct --profile/--topology-profile`
# (pv.profile_charts, no X server needed); and both charts rendered
# (render.profile_charts, needs X: run ctest under xvfb-run). Included from
# Testing/ParaView/CMakeLists.txt.
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND
    FLOWRECON_PVPYTHON)
  add_test(NAME pv.profile_charts
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_profile_charts.py"
            "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>"
            "${CMAKE_CURRENT_BINARY_DIR}/profile_charts")
  set_tests_properties(pv.profile_charts PROPERTIES
    PASS_REGULAR_EXPRESSION "PASS"
    FAIL_REGULAR_EXPRESSION "FAIL"
    LABELS "paraview"
    # Nothing is rendered: without DISPLAY no X server can refuse the
    # connection (it aborted once under xvfb-run -j2).
    ENVIRONMENT "DISPLAY="
    TIMEOUT 300)
  flowrecon_add_render_test(render.profile_charts test_profile_charts_views.py 180
    "${CMAKE_CURRENT_BINARY_DIR}/profile_charts_views")
endif ()
