#include "MemoryGuard.h"

#include "CgroupMemory.h"
#include "Progress.h"

#include <sys/resource.h>
#include <tbb/scalable_allocator.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace flowrecon
{

namespace
{

/// A field of /proc/meminfo or /proc/self/status in bytes (-1 if absent).
double ProcField(const std::string& file, const std::string& key)
{
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, key.size(), key) == 0 && line.size() > key.size() && line[key.size()] == ':')
    {
      std::istringstream fields(line.substr(key.size() + 1));
      double kb = -1;
      fields >> kb;
      return kb * 1024;
    }
  }
  return -1;
}

std::string Gigabytes(double bytes)
{
  char text[32];
  std::snprintf(text, sizeof(text), bytes < 1e9 ? "%.2g GB" : "%.1f GB", bytes / 1e9);
  return text;
}

/// AvailableMemory(), and whether the cgroup is what binds.
MemoryRoom Available()
{
  MemoryRoom room = SystemMemoryRoom("/");
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
  {
    const double used = ProcField("/proc/self/status", "VmSize");
    const double left = static_cast<double>(limit.rlim_cur) - std::max(0.0, used);
    if (left < room.bytes)
    {
      room = { left, false };
    }
  }
  if (const char* text = std::getenv("FLOWRECON_MEMORY_LIMIT"))
  {
    const double cap = std::strtod(text, nullptr);
    const double used = ProcField("/proc/self/status", "VmRSS");
    if (cap > 0 && cap - std::max(0.0, used) < room.bytes)
    {
      room = { cap - std::max(0.0, used), false };
    }
  }
  room.bytes = std::max(0.0, room.bytes);
  return room;
}

} // namespace

MemoryRoom SystemMemoryRoom(const std::string& root)
{
  std::string prefix = root;
  while (!prefix.empty() && prefix.back() == '/')
  {
    prefix.pop_back();
  }
  double available = ProcField(prefix + "/proc/meminfo", "MemAvailable");
  if (available < 0)
  {
    available = HUGE_VAL; // not Linux: no estimate, no refusal
  }
  const double cgroup = CgroupMemoryRoom(root);
  return cgroup < available ? MemoryRoom{ cgroup, true } : MemoryRoom{ available, false };
}

double AvailableMemory()
{
  return Available().bytes;
}

void RequireMemory(double bytes, const std::string& what, const std::string& advice)
{
  MemoryRoom available = Available();
  if (bytes > available.bytes)
  {
    // Blocks the process freed but its allocators still hold count as used:
    // hand them back before refusing (measured: 10^7 points were refused a
    // drawing while the simplification's lists sat in tbbmalloc's pools).
    ReleaseFreedMemory();
    available = Available();
  }
  if (bytes > available.bytes)
  {
    throw InputError(what + " needs about " + Gigabytes(bytes) + " of memory, " +
      Gigabytes(available.bytes) + " are available" +
      (available.cgroupBinds ? " (cgroup memory limit); " : "; ") + advice);
  }
}

void ReleaseFreedMemory()
{
  // tbbmalloc (2021.8) crashes cleaning buffers before its first allocation
  // (seen under ASan: a filter that fails before any parallel work); one small
  // allocation initialises it.
  scalable_free(scalable_malloc(16));
  scalable_allocation_command(TBBMALLOC_CLEAN_ALL_BUFFERS, nullptr);
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

} // namespace flowrecon
