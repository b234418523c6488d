# The Persistence Diagram filter: equal to `flowrecon diagram` and to
# GUDHI's alpha persistence, its persistence curve, bad input, the preferred views
# (pv.persistence_diagram, no X server needed); and the views ParaView opens for
# its ports, rendered (render.persistence_diagram, needs X: run ctest under
# xvfb-run). Included from Testing/ParaView/CMakeLists.txt.
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND
    FLOWRECON_WRAP_PYTHON AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.persistence_diagram
    COMMAND "${FLOWRECON_PVPYTHON}"
            "${CMAKE_CURRENT_LIST_DIR}/test_persistence_diagram_filter.py"
            "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>"
            "${CMAKE_CURRENT_BINARY_DIR}/persistence_diagram")
  set_tests_properties(pv.persistence_diagram PROPERTIES
    # Nothing is rendered: without DISPLAY no X server can refuse the
    # connection (pv.profile_charts aborted once under xvfb-run -j2).
    ENVIRONMENT "DISPLAY="
    PASS_REGULAR_EXPRESSION "PASS"
    FAIL_REGULAR_EXPRESSION "FAIL"
    LABELS "paraview"
    TIMEOUT 300)
  flowrecon_add_render_test(render.persistence_diagram test_persistence_diagram_views.py 180
    "${CMAKE_CURRENT_BINARY_DIR}/persistence_diagram_views")
endif ()
