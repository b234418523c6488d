# Tests that need an X server: the ParaView Qt GUI running the plugin's pipeline
# (gui.pipeline) and the demo's pictures (render.demo). Debian's ParaView renders
# through X11/GLX only, so run the suite under ONE X server,
#     xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure
# (one xvfb-run per test is flaky: several X servers starting at once collide). Without $DISPLAY these tests
# exit 77 through need_display.sh and are reported as skipped.
# Included from Testing/ParaView/CMakeLists.txt (needs _data_dir).
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon)
  set(_need_x "${CMAKE_CURRENT_LIST_DIR}/need_display.sh")
  find_program(FLOWRECON_PARAVIEW_GUI paraview DOC "ParaView's Qt GUI")
  find_program(FLOWRECON_PVBATCH pvbatch DOC "ParaView's batch Python interpreter")
  if (FLOWRECON_PARAVIEW_GUI)
    flowrecon_add_gui_script_test(gui.pipeline gui_pipeline.py 180
      "FLOWRECON_DATA=${_data_dir}/two_hemispheres.xyz"
      "FLOWRECON_OUT=${CMAKE_CURRENT_BINARY_DIR}/gui_pipeline")
    # The defaults a user gets from the Filters menu and the Apply button, and the
    # sponsor arrows drawn as arrows.
    flowrecon_add_gui_script_test(gui.apply_defaults test_apply_gui.py 240
      "FLOWRECON_DATA=${_data_dir}/torus.xyz" "FLOWRECON_OUT=${CMAKE_CURRENT_BINARY_DIR}/apply_gui")
    # No warning (no Output Messages window) on Apply of each filter from the menu
    # and on loading each example state: e.g. a view hint whose type has no
    # Pipeline Browser icon in 5.11.
    add_test(NAME gui.no_messages
      COMMAND sh "${_need_x}" "${FLOWRECON_TEST_PYTHON}"
              "${CMAKE_CURRENT_LIST_DIR}/test_quiet_gui.py" "${FLOWRECON_PARAVIEW_GUI}"
              "$<TARGET_FILE:FlowRecon>" "${PROJECT_SOURCE_DIR}"
              "${CMAKE_CURRENT_BINARY_DIR}/quiet_gui")
    set_tests_properties(gui.no_messages PROPERTIES
      PASS_REGULAR_EXPRESSION "PASS"
      FAIL_REGULAR_EXPRESSION "FAIL"
      SKIP_RETURN_CODE 77
      LABELS "paraview;gui"
      RESOURCE_LOCK flowrecon_x_screen
      TIMEOUT 600)
  endif ()
  if (FLOWRECON_PVBATCH)
    # the demo script of .ci/demo on the hemispheres: pipeline, .vtu, pictures, profile
    add_test(NAME render.demo
      COMMAND sh "${_need_x}" "${FLOWRECON_PVBATCH}"
              "${PROJECT_SOURCE_DIR}/Apps/demo/render.py" "$<TARGET_FILE:FlowRecon>"
              "${_data_dir}/two_hemispheres.xyz" "${CMAKE_CURRENT_BINARY_DIR}/render_demo")
    set_tests_properties(render.demo PROPERTIES
      PASS_REGULAR_EXPRESSION "render.py done"
      SKIP_RETURN_CODE 77
      LABELS "paraview;render"
      TIMEOUT 300)
  endif ()
endif ()

# Data/demo.pvsm (written by Apps/Scripts/make_states.py) loads from the repository root
# with the plugin from PV_PLUGIN_PATH. No rendering: no X server needed.
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.demo_state
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_demo_state.py")
  set_tests_properties(pv.demo_state PROPERTIES
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
    # Loading a state needs no X server; without one it cannot be refused a
    # connection (which happens now and then under Xvfb in sandboxed machines).
    ENVIRONMENT "PV_PLUGIN_PATH=$<TARGET_FILE_DIR:FlowRecon>;DISPLAY="
    PASS_REGULAR_EXPRESSION "PASS"
    FAIL_REGULAR_EXPRESSION "FAIL"
    LABELS "paraview"
    TIMEOUT 120)
endif ()
