"""Helpers the Python tests share, each in one place. CTest puts this folder on
PYTHONPATH (Testing/CMakeLists.txt, FLOWRECON_PYTHONPATH), with the build's
`flowrecon` and Apps/Scripts (the cloud generator); nothing here imports VTK or
ParaView until a module that needs them is imported.

  checks             Checker, check()/finish() of the pvpython scripts, fail()
  clouds             the small clouds the tests draw, write_xyz
  run                the command-line tool run, its files and printed lines read
  flowcomplex_io     vtkFlowComplex on numpy points, its output as numpy, diagrams
  paraview_pipeline  pipelines more than one pvpython test builds
  paraview_gui       the ParaView GUI started from a test, in fresh settings
  gui_qt             Qt and pqCore through ctypes, inside the ParaView GUI
  gui_plugin         the plugin loaded inside the ParaView GUI
"""
