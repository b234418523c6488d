# Tests of the simplification and reconstruction core (included from
# Testing/Cxx/CMakeLists.txt, which defines flowrecon_add_cxx_test).
flowrecon_add_cxx_test(TestSimplification FlowReconCore)
flowrecon_add_cxx_test(TestCancellationReplay FlowReconCore)
flowrecon_add_cxx_test(TestReconstruction FlowReconCore)
flowrecon_add_cxx_test(TestStableManifoldGeometry FlowReconCore)
