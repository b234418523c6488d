# ParaView's parallel settings: MPI (mpiexec -n 2 pvbatch) and client/server
# (pvpython connected to a local pvserver) give the serial reconstruction.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon)
  find_program(FLOWRECON_MPIEXEC mpiexec)
  find_program(FLOWRECON_PVSERVER pvserver)
  set(_cloud "${PROJECT_SOURCE_DIR}/Data/two_hemispheres.xyz")
  if (FLOWRECON_MPIEXEC AND FLOWRECON_PVBATCH)
    add_test(NAME pv.parallel.mpi
      COMMAND "${FLOWRECON_MPIEXEC}" --allow-run-as-root --oversubscribe -n 2
              "${FLOWRECON_PVBATCH}" "${CMAKE_CURRENT_SOURCE_DIR}/test_parallel.py"
              "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>" "${_cloud}"
              "${CMAKE_CURRENT_BINARY_DIR}/parallel_mpi")
    set_tests_properties(pv.parallel.mpi PROPERTIES LABELS "paraview" TIMEOUT 300
      PASS_REGULAR_EXPRESSION "PASS")
  endif ()
  if (FLOWRECON_PVSERVER AND FLOWRECON_PVPYTHON)
    add_test(NAME pv.parallel.client_server
      COMMAND sh "${CMAKE_CURRENT_SOURCE_DIR}/RunClientServer.sh"
              "${FLOWRECON_PVSERVER}" "${FLOWRECON_PVPYTHON}"
              "${CMAKE_CURRENT_SOURCE_DIR}/test_parallel.py"
              "$<TARGET_FILE:FlowRecon>" "$<TARGET_FILE:flowrecon>" "${_cloud}"
              "${CMAKE_CURRENT_BINARY_DIR}/parallel_cs")
    set_tests_properties(pv.parallel.client_server PROPERTIES LABELS "paraview" TIMEOUT 300
      PASS_REGULAR_EXPRESSION "PASS")
  endif ()
endif ()

# Point clouds open directly in ParaView (the plugin's reader), CSV tables feed
# the filters without a Table To Points step.
if (FLOWRECON_BUILD_PARAVIEW_PLUGIN AND TARGET FlowRecon AND FLOWRECON_PVPYTHON)
  add_test(NAME pv.reader_proxy
    COMMAND "${FLOWRECON_PVPYTHON}" "${CMAKE_CURRENT_SOURCE_DIR}/test_reader_proxy.py"
            "$<TARGET_FILE:FlowRecon>" "${PROJECT_SOURCE_DIR}/Data/torus.xyz"
            "${CMAKE_CURRENT_BINARY_DIR}/reader_proxy")
  set_tests_properties(pv.reader_proxy PROPERTIES LABELS "paraview" TIMEOUT 120
    PASS_REGULAR_EXPRESSION "PASS")
endif ()
