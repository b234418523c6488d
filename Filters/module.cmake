# Recipe of the FlowRecon::Filters VTK module (included from the staged module
# folder, see the root CMakeLists.txt): sources are named by absolute path.
set(_flowrecon_filters_dir "${CMAKE_CURRENT_LIST_DIR}")
vtk_module_add_module(FlowRecon::Filters
  CLASSES
    ${_flowrecon_filters_dir}/vtkFlowComplex
    ${_flowrecon_filters_dir}/vtkFlowComplexSimplification
    ${_flowrecon_filters_dir}/vtkFlowReconstruction
    ${_flowrecon_filters_dir}/vtkPersistenceDiagram
    ${_flowrecon_filters_dir}/vtkPointCloudReader
  PRIVATE_HEADERS
    ${_flowrecon_filters_dir}/CloudReconstruction.h
    ${_flowrecon_filters_dir}/ContractArrays.h
    ${_flowrecon_filters_dir}/CoreCall.h
    ${_flowrecon_filters_dir}/FlowComplexConversion.h
    ${_flowrecon_filters_dir}/FlowComplexFromVTK.h
    ${_flowrecon_filters_dir}/FlowComplexToVTK.h
    ${_flowrecon_filters_dir}/FlowReconNames.h
    ${_flowrecon_filters_dir}/LegacyVtkGuard.h
    ${_flowrecon_filters_dir}/PersistenceDiagramConversion.h
    ${_flowrecon_filters_dir}/PlyPoints.h
    ${_flowrecon_filters_dir}/PointCloudParsing.h
    ${_flowrecon_filters_dir}/PointCloudTextFormats.h
    ${_flowrecon_filters_dir}/ReconstructionConversion.h
    ${_flowrecon_filters_dir}/ReconstructionReport.h
    ${_flowrecon_filters_dir}/SamplesFromVTK.h
    ${_flowrecon_filters_dir}/SimplificationConversion.h
    ${_flowrecon_filters_dir}/TopologyConversion.h
    ${_flowrecon_filters_dir}/VtkFilePoints.h
    ${_flowrecon_filters_dir}/VtkMessageCapture.h
    ${_flowrecon_filters_dir}/XmlBlockHeaders.h
    ${_flowrecon_filters_dir}/XmlVtkGuard.h
  SOURCES
    ${_flowrecon_filters_dir}/CloudReconstruction.cxx
    ${_flowrecon_filters_dir}/ContractArrays.cxx
    ${_flowrecon_filters_dir}/FlowComplexFromVTK.cxx
    ${_flowrecon_filters_dir}/FlowComplexToVTK.cxx
    ${_flowrecon_filters_dir}/LegacyVtkGuard.cxx
    ${_flowrecon_filters_dir}/PersistenceDiagramConversion.cxx
    ${_flowrecon_filters_dir}/PlyPoints.cxx
    ${_flowrecon_filters_dir}/PointCloudParsing.cxx
    ${_flowrecon_filters_dir}/PointCloudTextFormats.cxx
    ${_flowrecon_filters_dir}/ReconstructionConversion.cxx
    ${_flowrecon_filters_dir}/ReconstructionReport.cxx
    ${_flowrecon_filters_dir}/SamplesFromVTK.cxx
    ${_flowrecon_filters_dir}/SimplificationConversion.cxx
    ${_flowrecon_filters_dir}/TopologyConversion.cxx
    ${_flowrecon_filters_dir}/VtkFilePoints.cxx
    ${_flowrecon_filters_dir}/VtkMessageCapture.cxx
    ${_flowrecon_filters_dir}/XmlBlockHeaders.cxx
    ${_flowrecon_filters_dir}/XmlVtkGuard.cxx)
vtk_module_include(FlowRecon::Filters PUBLIC "$<BUILD_INTERFACE:${_flowrecon_filters_dir}>")
vtk_module_link(FlowRecon::Filters PRIVATE "$<BUILD_INTERFACE:FlowReconCore>")
