// What FlowRecon's outputs look like by default in ParaView; run when
// the plugin is loaded (paraview_add_plugin's INITIALIZERS).
#ifndef FlowReconDisplayDefaults_h
#define FlowReconDisplayDefaults_h

/**
 * Adds the colour maps of the arrays Index and Extension (categorical, with the
 * names of their values) to ParaView's settings at priority 0, below site and
 * user settings, and registers vtkFlowReconDisplayInitializationHelper with the
 * ClientServer interpreter so that the displays of Flow Complex (Simplification)
 * can name it. Safe to call more than once.
 */
void FlowReconDisplayDefaults();

#endif
