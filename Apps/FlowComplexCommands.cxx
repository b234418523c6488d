// flowrecon complex and flowrecon info: the flow complex of a cloud, written
// or summarised.
#include "Commands.h"

#include "CliError.h"
#include "FlowReconNames.h"
#include "OutputFiles.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkXMLMultiBlockDataWriter.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace flowrecon::cli
{

Id CountOption(const Arguments& args, const NumberArg& arg, Id fallback, const char* what)
{
  const double k = Number(arg, 0, args.Command);
  if (!arg.Given)
  {
    return fallback;
  }
  if (!(k >= 0) || (k != std::floor(k) && !std::isinf(k)))
  {
    throw Usage(std::string("option '") + arg.Name + "' needs " + what, args.Command);
  }
  return std::isinf(k) || k >= 9e18 ? -1 : static_cast<Id>(k);
}

FlowComplexOptions FlowComplexOptionsOf(const Arguments& args)
{
  FlowComplexOptions options;
  options.Stable = !args.NoStable;
  options.MaxCells = CountOption(args, args.MaxCells, 2000000, "a whole number >= 0 or 'inf'");
  options.Unstable = !args.NoUnstable;
  options.Quiet = args.Quiet;
  options.Label = args.Command;
  return options;
}

int RunComplex(const Arguments& args)
{
  const std::string output = OutputPath(args.Output, args.Command, { ".vtm" });
  if (LoadStoredFlowComplex(args.Input))
  {
    throw Failure(args.Input + ": already a flow complex (use 'flowrecon info' to inspect it)");
  }
  const FlowComplexOptions options = FlowComplexOptionsOf(args);
  vtkSmartPointer<vtkMultiBlockDataSet> complex = ComputeFlowComplex(args.Input, options);
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  WriteXML(writer, complex, output);
  if (!options.Quiet)
  {
    vtkFieldData* fd = CriticalPointsBlock(complex)->GetFieldData();
    vtkDataArray* counts = fd->GetArray(names::NodeCountByIndex);
    vtkDataArray* arcs = fd->GetArray("ArcCount");
    std::cout << output << ": nodes by index";
    for (int k = 0; k < 4; ++k)
    {
      std::cout << " " << static_cast<long long>(counts->GetComponent(0, k));
    }
    std::cout << ", " << static_cast<long long>(arcs ? arcs->GetComponent(0, 0) : 0) << " arcs\n";
  }
  return 0;
}

namespace
{

// One value of a field data array as text (`decimals` >= 0: fixed notation);
// "unknown" if the array is absent.
std::string Field(vtkFieldData* fd, const char* name, int component = 0, int decimals = -1)
{
  vtkDataArray* array = fd->GetArray(name);
  if (!array || array->GetNumberOfTuples() < 1 || component >= array->GetNumberOfComponents())
  {
    return "unknown";
  }
  std::ostringstream os;
  const double value = array->GetComponent(0, component);
  if (decimals >= 0)
  {
    os << std::fixed << std::setprecision(decimals) << value;
  }
  else if (value == std::floor(value) && std::fabs(value) < 1e15)
  {
    os << static_cast<long long>(value); // counts: 1000000, not 1e+06
  }
  else
  {
    os << value;
  }
  return os.str();
}

} // namespace

int RunInfo(const Arguments& args)
{
  vtkSmartPointer<vtkMultiBlockDataSet> complex = LoadStoredFlowComplex(args.Input);
  const bool stored = complex != nullptr;
  if (!stored)
  {
    FlowComplexOptions options = FlowComplexOptionsOf(args);
    options.Stable = false; // info prints no geometry
    options.Unstable = false;
    complex = ComputeFlowComplex(args.Input, options);
  }
  vtkFieldData* fd = CriticalPointsBlock(complex)->GetFieldData();
  const std::string attempts = Field(fd, "PerturbationAttempts");
  const char* counts = names::NodeCountByIndex;
  std::ostringstream out;
  out << "input:                 " << args.Input
      << (stored ? " (flow complex file)" : " (point cloud)") << "\n"
      << "input points:          " << Field(fd, "InputPointCount") << "\n"
      << "duplicates merged:     " << Field(fd, "DuplicatePointCount") << "\n"
      << "perturbed:             "
      << (attempts == "1" ? std::string("no")
                          : "yes (" + attempts + " attempts, magnitude " +
               Field(fd, "PerturbationMagnitude") + "; critical values from the input, " +
               Field(fd, "PerturbedValueCount") + " left perturbed)")
      << "\n"
      << "nodes by index:        " << Field(fd, counts, 0) << " " << Field(fd, counts, 1) << " "
      << Field(fd, counts, 2) << " " << Field(fd, counts, 3)
      << " (n0 n1 n2 n3; finite nodes, the maximum at infinity is not counted)\n"
      << "Euler characteristic:  " << Field(fd, "EulerCharacteristic") << " (n0 - n1 + n2 - n3)\n"
      << "arcs:                  " << Field(fd, "ArcCount") << "\n"
      << "degeneracies:          " << Field(fd, "RightAngleCount") << " right angles, "
      << Field(fd, "ApexOnSphereCount") << " apex on sphere, " << Field(fd, "WalkTieCount")
      << " walk ties, " << Field(fd, "ExactFallbackCount") << " exact fallbacks\n"
      << "timings (s):          ";
  static const char* const phases[6] = { "Delaunay", names::CriticalPoints,
    names::StableManifolds, names::UnstableManifolds, "Assembly", "Total" };
  for (int k = 0; k < 6; ++k)
  {
    out << " " << phases[k] << " " << Field(fd, "Timings", k, 6);
  }
  std::cout << out.str() << "\n";
  return 0;
}

} // namespace flowrecon::cli
