"""Helpers the Python tests share, each in one place. CTest puts this folder on
PYTHONPATH (Testing/CMakeLists.txt, FLOWRECON_PYTHONPATH); nothing here imports
VTK or ParaView until a module that needs them is imported.

  checks          Checker, and check()/finish() of the pvpython scripts
  flowcomplex_io  vtkFlowComplex on numpy points, its output as numpy, diagrams
  gui_qt          Qt and pqCore through ctypes, inside the ParaView GUI
  gui_plugin      the plugin loaded inside the ParaView GUI
  paraview_gui    the ParaView GUI started from a test, in fresh settings
"""
