// libFuzzer target: vtkPointCloudReader on arbitrary bytes.
//
// Input layout: byte 0 picks the extension (byte % 9 of .xyz .csv .ply .off
// .obj .vtk .vtp .stl .las: 0-6 pick what they picked before .stl), the remaining
// bytes are the file, written to a temporary directory of this process and
// read. Any outcome is fine (points, or a failed request with one line in
// GetErrorMessage()) except a crash, a sanitizer report, a hang (-timeout) or a
// huge allocation (-rss_limit_mb / -malloc_limit_mb).
// On success the output must be consistent: as many vertices as points and
// finite coordinates.
#include "vtkPointCloudReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkLogger.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
std::string Directory;

const char* const Extensions[] = { ".xyz", ".csv", ".ply", ".off", ".obj", ".vtk", ".vtp", ".stl", ".las" };

void RemoveDirectory()
{
  for (const char* e : Extensions)
  {
    std::remove((Directory + "/input" + e).c_str());
  }
  rmdir(Directory.c_str());
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkObject::GlobalWarningDisplayOff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  // The memory guard answers as on a machine of 1.5 GB: libFuzzer's limit is
  // 2 GB (-rss_limit_mb), and a guard that passes more is a finding.
  setenv("FLOWRECON_MEMORY_LIMIT", "1500000000", 0);
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/fuzz-reader-XXXXXX";
  if (!mkdtemp(&pattern[0]))
  {
    std::perror("mkdtemp");
    std::abort();
  }
  Directory = pattern;
  std::atexit(RemoveDirectory);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const std::string path = Directory + "/input" + Extensions[data[0] % 9];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  vtkSmartPointer<vtkPointCloudReader> reader = vtkSmartPointer<vtkPointCloudReader>::New();
  reader->SetFileName(path.c_str());
  if (reader->GetExecutive()->Update())
  {
    vtkPolyData* output = reader->GetOutput();
    const vtkIdType n = output->GetNumberOfPoints();
    if (n <= 0 || output->GetNumberOfVerts() != n)
    {
      std::fprintf(stderr, "FuzzPointCloudReader: success with %lld points and %lld vertices\n",
        static_cast<long long>(n), static_cast<long long>(output->GetNumberOfVerts()));
      std::abort();
    }
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      output->GetPoint(i, x);
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      {
        std::fprintf(stderr, "FuzzPointCloudReader: success with a non-finite point %lld\n",
          static_cast<long long>(i));
        std::abort();
      }
    }
  }
  else if (reader->GetErrorMessage()[0] == '\0')
  {
    std::fprintf(stderr, "FuzzPointCloudReader: failed without an error message\n");
    std::abort();
  }
  return 0;
}
