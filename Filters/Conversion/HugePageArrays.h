// VTK arrays whose storage is advised for 2 MB pages before first touch. An
// output made again on every parameter change (a t_r typed in ParaView) is
// fresh memory each time, and ParaView, unlike the command line, cannot be
// started with glibc's huge-page tunable: faulting such arrays in 4 KB at a
// time was most of a t_r change (docs/benchmarks.md, "ParaView (pvbatch)").
#ifndef flowrecon_HugePageArrays_h
#define flowrecon_HugePageArrays_h

#include "HugePages.h" // the core's page size and madvise, for std::vector

#include "vtkAOSDataArrayTemplate.h"

#include <cstddef>
#include <cstdlib>

namespace flowrecon
{

/// Sizes `a` to `tuples` tuples (contents undefined, as SetNumberOfTuples
/// leaves them) on storage advised for transparent huge pages when it spans
/// one or more; a hint only: elsewhere, or for small arrays, plain VTK storage.
template <class T>
void SetNumberOfTuplesOnHugePages(vtkAOSDataArrayTemplate<T>* a, vtkIdType tuples)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::size_t page = detail::HugePage;
  const vtkIdType values = tuples * a->GetNumberOfComponents();
  const std::size_t bytes = static_cast<std::size_t>(values) * sizeof(T);
  if (values > 0 && bytes >= page)
  {
    const std::size_t rounded = (bytes + page - 1) & ~(page - 1);
    if (void* storage = std::aligned_alloc(page, rounded))
    {
      madvise(storage, rounded, MADV_HUGEPAGE);
      // ALIGNED_FREE is free() on Linux, which takes aligned_alloc's blocks.
      a->SetArray(static_cast<T*>(storage), values, 0,
        vtkAOSDataArrayTemplate<T>::VTK_DATA_ARRAY_ALIGNED_FREE);
      return;
    }
  }
#endif
  a->SetNumberOfTuples(tuples);
}

} // namespace flowrecon

#endif
