// The memory guard refuses only what does not fit once the process has handed
// back what it freed: blocks freed but kept by the allocator count in the
// resident size the guard compares against (FLOWRECON_MEMORY_LIMIT here).
#include "Check.h"

#include "Progress.h" // InputError
#include "MemoryGuard.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace flowrecon;

namespace
{

bool Refused(double bytes)
{
  try
  {
    RequireMemory(bytes, "the test", "none");
  }
  catch (const InputError&)
  {
    return true;
  }
  return false;
}

/// VmRSS of this process, in bytes.
double Resident()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  double kb = -1;
  while (status >> key)
  {
    if (key == "VmRSS:")
    {
      status >> kb;
      break;
    }
  }
  return kb * 1024;
}

} // namespace

int main()
{
#if defined(__SANITIZE_ADDRESS__)
  // ASan's allocator keeps freed blocks in quarantine, out of malloc_trim's reach.
  std::cout << "TestMemoryGuard: not run under AddressSanitizer\n";
  return 0;
#else
  // 400 MB in 4 kB blocks, written, then freed below a block that stays: the C
  // heap keeps the pages (it only trims its top by itself).
  std::vector<char*> blocks;
  for (int k = 0; k < 100000; ++k)
  {
    char* b = static_cast<char*>(std::malloc(4000));
    std::memset(b, 1, 4000);
    blocks.push_back(b);
  }
  char* sentinel = static_cast<char*>(std::malloc(4000));
  std::memset(sentinel, 1, 4000);
  for (char* b : blocks)
  {
    std::free(b);
  }
  // The limit: what is resident now (the freed blocks included) plus 100 MB.
  const double resident = Resident();
  CHECK(resident > 4e8);
  setenv("FLOWRECON_MEMORY_LIMIT", std::to_string(resident + 1e8).c_str(), 1);
  CHECK(AvailableMemory() < 1.5e8);
  CHECK(!Refused(2.5e8));           // fits once the 400 MB are handed back
  CHECK(AvailableMemory() > 3e8);
  CHECK(Refused(AvailableMemory() + 1e9)); // still refuses what does not fit
  unsetenv("FLOWRECON_MEMORY_LIMIT");
  std::free(sentinel);
  return check::Finish("TestMemoryGuard");
#endif
}
