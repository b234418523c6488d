# Reconstruct Point Cloud (the whole pipeline in one filter): in pvpython against
# the step-by-step pipeline on a torus, with its diagram and its abort
# (pv.point_cloud_reconstruction, no X server needed), and the layout one click
# opens in the real GUI (gui.point_cloud_reconstruction, needs X: run ctest under
# xvfb-run). Included from Testing/ParaView/CMakeLists.txt (needs _data_dir).
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon)
  if (FLOWRECON_PVPYTHON)
    add_test(NAME pv.point_cloud_reconstruction
      COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_point_cloud_reconstruction.py"
              "$<TARGET_FILE:FlowRecon>" "${CMAKE_CURRENT_BINARY_DIR}/point_cloud_reconstruction")
    set_tests_properties(pv.point_cloud_reconstruction PROPERTIES
      PASS_REGULAR_EXPRESSION "PASS"
      FAIL_REGULAR_EXPRESSION "FAIL"
      LABELS "paraview"
      # Nothing is rendered (see pv.profile_charts).
      ENVIRONMENT "DISPLAY="
      TIMEOUT 600)
  endif ()
  if (FLOWRECON_PARAVIEW_GUI)
    flowrecon_add_gui_script_test(gui.point_cloud_reconstruction
      test_point_cloud_reconstruction_gui.py 300 "FLOWRECON_DATA=${_data_dir}/torus.xyz"
      "FLOWRECON_OUT=${CMAKE_CURRENT_BINARY_DIR}/point_cloud_reconstruction_gui")
  endif ()
endif ()
