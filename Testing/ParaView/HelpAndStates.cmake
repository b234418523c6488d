# ParaView help pages, example states and the preferred reader. Included from Testing/ParaView/CMakeLists.txt.
#   pv.help              the .qch built into the plugin: a page per filter and reader at
#                        the address of ParaView's "?" button, every output name explained,
#                        pictures, embedded in the plugin library (no X server)
#   gui.help             "?" in the Qt GUI shows each proxy's page (QtTesting events)
#   pv.example_states    Data/*.pvsm load from an empty temporary folder as File > Load
#                        State does ("Search files under specified directory"), with the
#                        plugin's reader; torus Betti numbers (no X server)
#   gui.example_states   the same through the GUI's File > Load State dialog
#   gui.example_states_cmdline  paraview --state= from elsewhere, with the user setting
#                        the help recommends
#   pv.preferred_reader  OpenDataFile on .xyz/.pts gives the plugin's reader (no X server)
#   gui.preferred_reader File > Open of an .xyz: the plugin's reader is first and selected;
#                        "Set reader as default" makes the next .xyz open without asking
# The gui.* tests need an X server (run ctest under xvfb-run) and are skipped (77)
# without one; the help tests are skipped when the plugin was built without its help
# (Plugin/CMakeLists.txt says why at configure time).
find_program(FLOWRECON_PVPYTHON pvpython DOC "ParaView's Python interpreter")
find_program(FLOWRECON_PARAVIEW_GUI paraview DOC "ParaView's Qt GUI")
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND FLOWRECON_PVPYTHON)
  get_property(_flowrecon_qch GLOBAL PROPERTY FLOWRECON_HELP_QCH)
  if (NOT _flowrecon_qch)
    set(_flowrecon_qch "NO_HELP")  # pvpython crashes on an empty argument
  endif ()
  set(_need_x "${CMAKE_CURRENT_LIST_DIR}/need_display.sh")
  set(_data "${PROJECT_SOURCE_DIR}/Data")
  set(_plugin_env "PV_PLUGIN_PATH=$<TARGET_FILE_DIR:FlowRecon>;DISPLAY=")

  add_test(NAME pv.help
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_help.py"
            "${_flowrecon_qch}" "$<TARGET_FILE:FlowRecon>"
            "${PROJECT_SOURCE_DIR}/Plugin" "${_data}")
  add_test(NAME pv.example_states
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_states.py" "${_data}")
  add_test(NAME pv.preferred_reader
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_states.py"
            --reader "${_data}")
  set_tests_properties(pv.help pv.example_states pv.preferred_reader PROPERTIES
    ENVIRONMENT "${_plugin_env}"
    PASS_REGULAR_EXPRESSION "PASS"
    FAIL_REGULAR_EXPRESSION "FAIL"
    SKIP_RETURN_CODE 77
    LABELS "paraview"
    TIMEOUT 180)

  if (FLOWRECON_PARAVIEW_GUI)
    add_test(NAME gui.help
      COMMAND sh "${_need_x}" "${FLOWRECON_TEST_PYTHON}"
              "${CMAKE_CURRENT_LIST_DIR}/test_help_gui.py" "${FLOWRECON_PARAVIEW_GUI}"
              "$<TARGET_FILE_DIR:FlowRecon>" "${_data}"
              "${CMAKE_CURRENT_BINARY_DIR}/help_gui" "${_flowrecon_qch}")
    set(_gui_tests gui.help)
    foreach (_mode IN ITEMS load cmdline reader)
      set(_name "gui.example_states")
      if (_mode STREQUAL "cmdline")
        set(_name "gui.example_states_cmdline")
      elseif (_mode STREQUAL "reader")
        set(_name "gui.preferred_reader")
      endif ()
      add_test(NAME ${_name}
        COMMAND sh "${_need_x}" "${FLOWRECON_TEST_PYTHON}"
                "${CMAKE_CURRENT_LIST_DIR}/test_states_gui.py" ${_mode}
                "${FLOWRECON_PARAVIEW_GUI}" "$<TARGET_FILE_DIR:FlowRecon>" "${_data}"
                "${CMAKE_CURRENT_BINARY_DIR}/states_gui_${_mode}")
      list(APPEND _gui_tests ${_name})
    endforeach ()
    set_tests_properties(${_gui_tests} PROPERTIES
      PASS_REGULAR_EXPRESSION "PASS"
      FAIL_REGULAR_EXPRESSION "FAIL"
      SKIP_RETURN_CODE 77
      LABELS "paraview;gui"
      # One GUI window at a time: gui.abort clicks at a screen position, which
      # another test's window opened on the same X server can cover.
      RESOURCE_LOCK flowrecon_x_screen
      TIMEOUT 300)
  endif ()
endif ()
