# `flowrecon diagram` against GUDHI's alpha-complex persistence (included from
# Testing/Python/CMakeLists.txt; needs the flowrecon tool and python3-gudhi).
if (TARGET flowrecon)
  add_test(NAME py.diagram_gudhi
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_diagram_gudhi.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/diagram_gudhi")
  set_tests_properties(py.diagram_gudhi PROPERTIES LABELS "python" TIMEOUT 300)
endif ()
