# Install test (included from Testing/CMakeLists.txt): `cmake --install` this build
# into <build>/Testing/install, then from a clean environment (env -i, no
# LD_LIBRARY_PATH) (a) pvbatch loads the installed plugin by path, (b) pvpython
# auto-loads it through PV_PLUGIN_PATH, (c) /usr/bin/python3 imports the installed
# `flowrecon` package, (d) the installed `flowrecon` runs. Also checks that no
# installed RUNPATH names the build tree. Needs a built tree: run after the build.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND FLOWRECON_WRAP_PYTHON)
  add_test(NAME install.tree
    COMMAND sh "${CMAKE_CURRENT_LIST_DIR}/RunInstall.sh"
            "${CMAKE_COMMAND}" "${CMAKE_BINARY_DIR}" "${CMAKE_CURRENT_BINARY_DIR}/install"
            "${CMAKE_INSTALL_LIBDIR}" "${PARAVIEW_PLUGIN_SUBDIR}"
            "${FLOWRECON_PYTHON_DESTINATION}" "${CMAKE_INSTALL_BINDIR}"
            "${FLOWRECON_TEST_PYTHON}" "${PROJECT_SOURCE_DIR}/Data/torus.xyz")
  set_tests_properties(install.tree PROPERTIES
    PASS_REGULAR_EXPRESSION "install: PASS"
    FAIL_REGULAR_EXPRESSION "install: FAIL"
    LABELS "install"
    # the install step rewrites <build>/install_manifest.txt: not alongside itself
    RUN_SERIAL ON
    TIMEOUT 300)
endif ()
