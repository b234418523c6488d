# What Flow Complex Simplification's display shows beside Flow Complex's: the
# critical points and Gabriel edges that survive t_p and no other, as drawn and
# on screen, and the reconstruction downstream unchanged by the blocks added
# for it (render.simplification_display, needs X: run ctest under xvfb-run).
# Included from Testing/ParaView/CMakeLists.txt.
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND TARGET flowrecon AND
    FLOWRECON_PVPYTHON)
  flowrecon_add_render_test(render.simplification_display test_simplification_display.py 180
    "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/simplification_display")
endif ()
