#include "HugePages.h"

#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace flowrecon::cli
{

namespace
{

bool KernelAdvisesOnly()
{
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  return std::getline(mode, line) && line.find("[madvise]") != std::string::npos;
}

} // namespace

void RestartWithHugePages(char* argv[])
{
  const char* now = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = now ? now : "";
  // Also what keeps the restarted process from starting again.
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos || !KernelAdvisesOnly())
  {
    return;
  }
  const std::string wanted =
    (tunables.empty() ? "" : tunables + ":") + "glibc.malloc.hugetlb=1";
  if (setenv("GLIBC_TUNABLES", wanted.c_str(), 1) != 0)
  {
    return;
  }
  execv("/proc/self/exe", argv);
  // Not restarted (no /proc): 4 KB pages, and nothing else changes.
  if (now)
  {
    setenv("GLIBC_TUNABLES", now, 1);
  }
  else
  {
    unsetenv("GLIBC_TUNABLES");
  }
}

} // namespace flowrecon::cli
