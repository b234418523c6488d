// flowrecon diagram: the persistence diagram of a cloud (straight through the
// core: nodes and arcs suffice) or of a stored flow complex.
#include "Commands.h"

#include "CliError.h"
#include "DeferredPatches.h"
#include "FlowComplexBuilder.h"
#include "FlowComplexConversion.h"
#include "Interrupt.h"
#include "OutputFiles.h"
#include "PersistenceDiagramConversion.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <algorithm>
#include <iostream>

namespace flowrecon::cli
{

int RunDiagram(const Arguments& args)
{
  const std::string& input = args.Input;
  const std::string output = OutputPath(args.Output, args.Command, { ".csv", ".vtu" });
  const FlowComplexOptions options = FlowComplexOptionsOf(args);
  // Nodes and arcs suffice: a point cloud goes to the core directly (no manifold
  // geometry, no VTK round trip); a stored complex is read back.
  FlowComplex fc;
  if (vtkSmartPointer<vtkMultiBlockDataSet> stored = LoadStoredFlowComplex(input))
  {
    if (IsSimplified(stored))
    {
      throw Failure(input + ": simplified; the diagram needs the flow complex itself");
    }
    std::string error;
    if (!FromMultiBlock(stored, fc, error))
    {
      throw Failure(input + ": " + error);
    }
    // A complex saved from ParaView defers its far patches by default.
    CallCore(input, *ProgressLine::Make(), "walking the deferred patches", "", [&]() {
      WalkEveryDeferredPatch(fc, Progress(), "use the cloud itself, or fewer points");
    });
  }
  else
  {
    const std::vector<Point3> samples = ReadSamples(input);
    vtkSmartPointer<ProgressLine> line = ProgressLine::Make(options.Label, options.Quiet);
    BuildOptions build;
    build.StableManifolds = false;
    build.UnstableManifolds = false;
    CallCore(input, *line, "flow complex construction", "",
      [&]() { fc = BuildFlowComplex(samples, build, line->Core()); });
    ThrowIfInterrupted();
  }
  const std::vector<PersistencePair> pairs = DiagramPairs(fc);
  fc = FlowComplex();
  ThrowIfInterrupted();
  if (ExtensionOf(output) == ".csv")
  {
    WriteDiagramCsv(pairs, output);
  }
  else
  {
    vtkNew<vtkUnstructuredGrid> grid;
    DiagramToVTK(pairs, grid);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    WriteXML(writer, grid, output);
  }
  if (!options.Quiet)
  {
    long count[4] = { 0, 0, 0, 0 };
    for (const auto& p : pairs)
    {
      ++count[std::min(3, std::max(0, p.Dimension))];
    }
    std::cout << output << ": " << pairs.size() << " pairs (" << count[0] << " " << count[1]
              << " " << count[2] << " in dimensions 0 1 2)\n";
  }
  return 0;
}

} // namespace flowrecon::cli
