// How a FlowRecon filter calls the core: progress and abort are forwarded to the
// VTK algorithm, and the core's exceptions become VTK's conventions (an error
// message and a failed request, or an empty output for an abort).
#ifndef CoreCall_h
#define CoreCall_h

#include "MemoryGuard.h" // core: ReleaseFreedMemory
#include "Progress.h"    // core progress and exceptions

#include "vtkAlgorithm.h"
#include "vtkSetGet.h"

#include <exception>
#include <new>
#include <string>

namespace flowrecon
{

/// Progress forwarded to `algorithm` (progress text, UpdateProgress scaled by
/// `scale`, and its abort flag).
inline Progress AlgorithmProgress(vtkAlgorithm* algorithm, double scale = 1.0)
{
  Progress progress;
  progress.Report = [algorithm, scale](double fraction, const char* phase) {
    algorithm->SetProgressText(phase);
    algorithm->UpdateProgress(scale * fraction);
  };
  progress.ShouldAbort = [algorithm]() { return algorithm->GetAbortExecute() != 0; };
  return progress;
}

/// Runs `work()`. Returns 1 if it succeeds; on an abort calls `onAbort()` (which
/// empties the outputs), warns "`what` aborted: the output is empty ..." (so that
/// an empty output in ParaView is explained) and returns 1, since an abort is not an
/// error; on any other exception reports it (prefixed by `what` unless it is bad
/// input) and returns 0.
/// Whatever the outcome, the memory the core freed is handed back to the system
/// (ReleaseFreedMemory): ParaView holds every stage's output for the session.
template <class Work, class OnAbort>
int CallCore(vtkAlgorithm* algorithm, const char* what, Work&& work, OnAbort&& onAbort)
{
  struct Release
  {
    ~Release() { ReleaseFreedMemory(); }
  } release;
  try
  {
    work();
  }
  catch (const InputError& e)
  {
    vtkErrorWithObjectMacro(algorithm, << e.what());
    return 0;
  }
  catch (const Aborted&)
  {
    onAbort();
    algorithm->SetProgressText(nullptr);
    // VTK 9.2.20230111 (ParaView 5.11) no longer clears AbortExecute when a run
    // starts: until the caller clears it, every run ends here at once.
    vtkWarningWithObjectMacro(algorithm,
      << what << " aborted: the output is empty (AbortExecute stays set until cleared)");
    return 1;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(algorithm, << what << " ran out of memory");
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorWithObjectMacro(algorithm, << what << " failed: " << e.what());
    return 0;
  }
  algorithm->SetProgressText(nullptr);
  return 1;
}

} // namespace flowrecon

#endif
