# Tests of vtkPointCloudReader (included from Testing/Cxx/CMakeLists.txt, which
# defines flowrecon_add_cxx_test). The test writes its files to
# <build>/Testing/Cxx/PointCloudReader.
flowrecon_add_cxx_test(TestPointCloudReader FlowRecon::Filters VTK::CommonCore
  VTK::CommonDataModel VTK::CommonExecutionModel VTK::IOXML VTK::IOLegacy VTK::IOPLY
  VTK::IOGeometry)
