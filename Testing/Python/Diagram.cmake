# `flowrecon diagram` against GUDHI's alpha-complex persistence, and the flow complex
# on any number of threads (included from
# Testing/Python/CMakeLists.txt; needs the flowrecon tool and python3-gudhi).
if (TARGET flowrecon)
  add_test(NAME py.diagram_gudhi
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_diagram_gudhi.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/diagram_gudhi")
  set_tests_properties(py.diagram_gudhi PROPERTIES LABELS "python" TIMEOUT 300)
endif ()

# The flow complex is the same on 1, 2 and all threads (the core is parallel).
if (TARGET flowrecon)
  add_test(NAME py.threads_determinism
    COMMAND "${FLOWRECON_TEST_PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_threads.py"
            "$<TARGET_FILE:flowrecon>" "${CMAKE_CURRENT_BINARY_DIR}/threads")
  set_tests_properties(py.threads_determinism PROPERTIES
    ENVIRONMENT "PYTHONPATH=${FLOWRECON_PYTHONPATH}" LABELS "python" TIMEOUT 300)
endif ()
