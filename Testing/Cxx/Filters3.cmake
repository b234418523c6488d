# Tests of the simplification and reconstruction filters (included from
# Testing/Cxx/CMakeLists.txt, which defines flowrecon_add_cxx_test).
flowrecon_add_cxx_test(TestReconstructionFilters FlowRecon::Filters VTK::CommonCore
  VTK::CommonDataModel VTK::IOXML)
