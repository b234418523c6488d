# Abort of a long Flow Complex run from ParaView's GUI. Included from Testing/ParaView/CMakeLists.txt.
#   pv.abort   SetAbortExecute(1) from a progress observer (the only way an abort reaches
#              a filter in ParaView 5.11) at five points of a run on 5e4 random points:
#              the run returns within 3 s, empty output, a warning; the flag stays set
#              (VTK 9.2.20230111) until cleared, then a full re-run (no X server)
#   gui.abort  the real ParaView GUI: the status bar's Abort button, clicked (XTest and
#              QAbstractButton::click) with pqProgressManager::triggerAbort() during a
#              run, does not reach the filter in ParaView 5.11 (button disabled,
#              abort() unconnected; pinned) -- or, in a ParaView that delivers it, must
#              end the run within 3 s with an empty output; plus the observer abort in
#              the GUI and a control click on the enabled button
# gui.abort needs an X server (run ctest under xvfb-run) and is skipped (77) without one.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon)
  find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
  find_program(FLOWRECON_PARAVIEW_GUI paraview DOC "ParaView's Qt GUI")
  if (FLOWRECON_PVPYTHON)
    add_test(NAME pv.abort
      COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_abort.py"
              "$<TARGET_FILE:FlowRecon>" 50000)
    set_tests_properties(pv.abort PROPERTIES
      ENVIRONMENT "DISPLAY="
      PASS_REGULAR_EXPRESSION "PASS"
      FAIL_REGULAR_EXPRESSION "FAIL"
      LABELS "paraview"
      TIMEOUT 240)
  endif ()
  if (FLOWRECON_PARAVIEW_GUI)
    flowrecon_add_gui_script_test(gui.abort test_abort_gui.py 300 "FLOWRECON_ABORT_POINTS=50000")
  endif ()
endif ()
