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
    ${_flowrecon_filters_dir}/vtkPointCloudReconstruction
  PRIVATE_HEADERS
    ${_flowrecon_filters_dir}/PipelinePorts.h
    ${_flowrecon_filters_dir}/CloudReconstruction.h
    ${_flowrecon_filters_dir}/Conversion/CompactConversion.h
    ${_flowrecon_filters_dir}/Conversion/ContractArrays.h
    ${_flowrecon_filters_dir}/Conversion/CoreCall.h
    ${_flowrecon_filters_dir}/Conversion/FlowComplexConversion.h
    ${_flowrecon_filters_dir}/Conversion/FlowComplexFromVTK.h
    ${_flowrecon_filters_dir}/Conversion/FlowComplexToVTK.h
    ${_flowrecon_filters_dir}/FlowReconNames.h
    ${_flowrecon_filters_dir}/Conversion/HugePageArrays.h
    ${_flowrecon_filters_dir}/IO/IsolatedRead.h
    ${_flowrecon_filters_dir}/IO/LasPoints.h
    ${_flowrecon_filters_dir}/IO/PackedPoints.h
    ${_flowrecon_filters_dir}/Conversion/PersistenceDiagramConversion.h
    ${_flowrecon_filters_dir}/IO/PlyPoints.h
    ${_flowrecon_filters_dir}/IO/PointCloudParsing.h
    ${_flowrecon_filters_dir}/IO/PointCloudTextFormats.h
    ${_flowrecon_filters_dir}/Conversion/ReconstructionConversion.h
    ${_flowrecon_filters_dir}/ReconstructionReport.h
    ${_flowrecon_filters_dir}/Conversion/SamplesFromVTK.h
    ${_flowrecon_filters_dir}/Conversion/SimplificationConversion.h
    ${_flowrecon_filters_dir}/IO/StlPoints.h
    ${_flowrecon_filters_dir}/Conversion/SurvivingBlocks.h
    ${_flowrecon_filters_dir}/Conversion/TopologyConversion.h
    ${_flowrecon_filters_dir}/IO/VtkFilePoints.h
    ${_flowrecon_filters_dir}/IO/VtkMessageCapture.h
  SOURCES
    ${_flowrecon_filters_dir}/CloudReconstruction.cxx
    ${_flowrecon_filters_dir}/Conversion/CompactConversion.cxx
    ${_flowrecon_filters_dir}/Conversion/ContractArrays.cxx
    ${_flowrecon_filters_dir}/Conversion/FlowComplexFromVTK.cxx
    ${_flowrecon_filters_dir}/Conversion/FlowComplexToVTK.cxx
    ${_flowrecon_filters_dir}/IO/IsolatedRead.cxx
    ${_flowrecon_filters_dir}/IO/LasPoints.cxx
    ${_flowrecon_filters_dir}/IO/PackedPoints.cxx
    ${_flowrecon_filters_dir}/Conversion/PersistenceDiagramConversion.cxx
    ${_flowrecon_filters_dir}/IO/PlyPoints.cxx
    ${_flowrecon_filters_dir}/IO/PointCloudParsing.cxx
    ${_flowrecon_filters_dir}/IO/PointCloudTextFormats.cxx
    ${_flowrecon_filters_dir}/Conversion/ReconstructionConversion.cxx
    ${_flowrecon_filters_dir}/ReconstructionReport.cxx
    ${_flowrecon_filters_dir}/Conversion/SamplesFromVTK.cxx
    ${_flowrecon_filters_dir}/Conversion/SimplificationConversion.cxx
    ${_flowrecon_filters_dir}/IO/StlPoints.cxx
    ${_flowrecon_filters_dir}/Conversion/SurvivingBlocks.cxx
    ${_flowrecon_filters_dir}/Conversion/TopologyConversion.cxx
    ${_flowrecon_filters_dir}/IO/VtkFilePoints.cxx
    ${_flowrecon_filters_dir}/IO/VtkMessageCapture.cxx)
# The filters (here), the readers' parsers and child processes (IO) and the
# core <-> VTK conversions (Conversion); headers are included by name.
vtk_module_include(FlowRecon::Filters PUBLIC
  "$<BUILD_INTERFACE:${_flowrecon_filters_dir}>"
  "$<BUILD_INTERFACE:${_flowrecon_filters_dir}/IO>"
  "$<BUILD_INTERFACE:${_flowrecon_filters_dir}/Conversion>")
vtk_module_link(FlowRecon::Filters PRIVATE "$<BUILD_INTERFACE:FlowReconCore>")
