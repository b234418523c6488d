// The readers, filters and core calls as the commands run them: with the
// progress line and Ctrl-C, and every failure as one CLI error naming the input.
#ifndef flowrecon_cli_Pipeline_h
#define flowrecon_cli_Pipeline_h

#include "CliError.h"
#include "FlowComplex.h" // core: Point3
#include "Progress.h"    // core: InputError, Aborted
#include "ProgressLine.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <new>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkMultiBlockDataSet;

namespace flowrecon::cli
{

/// What a command asks of the flow complex, and of its progress line.
struct FlowComplexOptions
{
  bool Stable = true;
  vtkIdType MaxCells = 2000000; // -1: all
  bool Unstable = true;
  bool Quiet = false;
  std::string Label; ///< the command, shown on the progress line
};

/// The points of the cloud `file`.
std::vector<Point3> ReadSamples(const std::string& file);

/// A .vtm written by 'complex', or nullptr when `file` is a point cloud. Read in
/// a child process that goes on with the command (ReadThenGoOnInChild): a
/// corrupt file that crashes VTK's reader gets one line, from this process.
vtkSmartPointer<vtkMultiBlockDataSet> LoadStoredFlowComplex(const std::string& file);

/// The CriticalPoints block of a flow complex (it carries the report in its
/// field data), or nullptr if `data` is not one.
vtkDataObject* CriticalPointsBlock(vtkDataObject* data);

/// Whether `complex` is the output of Flow Complex Simplification.
bool IsSimplified(vtkMultiBlockDataSet* complex);

/// Runs `filter` (already connected) with the progress line; a failure names
/// `input` and VTK's first error (or "`what` failed").
void RunFilter(vtkAlgorithm* filter, const std::string& input, const FlowComplexOptions& options,
  const char* what);

/// Reads the point cloud `file` and computes its flow complex.
vtkSmartPointer<vtkMultiBlockDataSet> ComputeFlowComplex(
  const std::string& file, const FlowComplexOptions& options);

/// Runs `work` (a call to the core with `line`'s progress), ends the line and
/// turns the core's exceptions into CLI errors: bad input and other failures
/// name `input` ("INPUT: `what` failed: ..." for the unexpected ones), an abort
/// is Interrupted, and running out of memory says `outOfMemory` (when not
/// empty; else it goes on to main's "out of memory").
template <class Work>
void CallCore(const std::string& input, ProgressLine& line, const char* what,
  const std::string& outOfMemory, Work&& work)
{
  try
  {
    work();
  }
  catch (const InputError& e)
  {
    line.Finish();
    throw Failure(input + ": " + e.what());
  }
  catch (const Aborted&)
  {
    line.Finish();
    throw Interrupted();
  }
  catch (const std::bad_alloc&)
  {
    line.Finish();
    if (outOfMemory.empty())
    {
      throw;
    }
    throw Failure(input + ": " + outOfMemory);
  }
  catch (const std::exception& e)
  {
    line.Finish();
    throw Failure(input + ": " + what + " failed: " + e.what());
  }
  line.Finish();
}

} // namespace flowrecon::cli

#endif
