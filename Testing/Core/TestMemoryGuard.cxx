// The memory guard refuses only what does not fit once the process has handed
// back what it freed: blocks freed but kept by the allocator count in the
// resident size the guard compares against (FLOWRECON_MEMORY_LIMIT here). It
// reads a container's limit from the cgroup files: fixture trees of both cgroup
// versions, whose expected rooms are worked out by hand in the comments.
#include "Check.h"

#include "CgroupMemory.h"
#include "Progress.h" // InputError
#include "MemoryGuard.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
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

/// Writes `text` to `root`/`path`, making the folders.
void Write(const std::string& root, const std::string& path, const std::string& text)
{
  const std::filesystem::path file = std::filesystem::path(root) / path;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// The largest page-aligned long: cgroup v1's "no limit".
const char* const V1Unlimited = "9223372036854771712\n";
// MemAvailable of every fixture: 8000000 kB = 8192000000 bytes.
const char* const MemInfo = "MemTotal:       16000000 kB\nMemFree:         1000000 kB\n"
                            "MemAvailable:    8000000 kB\n";
const double MemAvailable = 8192000000.0;

void CheckCgroupFixtures(const std::string& base)
{
  std::filesystem::remove_all(base);

  // v2, a limit on the process's cgroup: 1000000000 - 300000000 = 700000000.
  std::string root = base + "/v2-limit";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/cgroup", "0::/system.slice/job.service\n");
  Write(root, "sys/fs/cgroup/system.slice/job.service/memory.max", "1000000000\n");
  Write(root, "sys/fs/cgroup/system.slice/job.service/memory.current", "300000000\n");
  Write(root, "sys/fs/cgroup/system.slice/memory.max", "max\n");
  Write(root, "sys/fs/cgroup/system.slice/memory.current", "900000000\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 7e8, 0.5);
  CHECK_NEAR(SystemMemoryRoom(root).bytes, 7e8, 0.5);
  CHECK(SystemMemoryRoom(root).cgroupBinds);
  CHECK_NEAR(CgroupMemoryRoom(root + "/"), 7e8, 0.5); // a root given with its slash

  // v2, "max" at the leaf, limits on two ancestors: a/b leaves
  // 2000000000 - 1500000000 = 500000000, a leaves 4000000000 - 1600000000 =
  // 2400000000; the tighter, a/b's, binds.
  root = base + "/v2-parent";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/cgroup", "0::/a/b/c\n");
  Write(root, "sys/fs/cgroup/a/b/c/memory.max", "max\n");
  Write(root, "sys/fs/cgroup/a/b/c/memory.current", "100000000\n");
  Write(root, "sys/fs/cgroup/a/b/memory.max", "2000000000\n");
  Write(root, "sys/fs/cgroup/a/b/memory.current", "1500000000\n");
  Write(root, "sys/fs/cgroup/a/memory.max", "4000000000\n");
  Write(root, "sys/fs/cgroup/a/memory.current", "1600000000\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 5e8, 0.5);

  // v2 with page cache: usage 900000000 of which inactive_file 300000000 is
  // reclaimable, so 1000000000 - (900000000 - 300000000) = 400000000
  // (active_file, listed first, must not be taken for inactive_file).
  root = base + "/v2-inactive";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/cgroup", "0::/job\n");
  Write(root, "sys/fs/cgroup/job/memory.max", "1000000000\n");
  Write(root, "sys/fs/cgroup/job/memory.current", "900000000\n");
  Write(root, "sys/fs/cgroup/job/memory.stat",
    "anon 500000000\nfile 400000000\nactive_file 100000000\ninactive_file 300000000\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 4e8, 0.5);

  // v1 (Slurm-like, hybrid with an empty v2): 2147483648 - (1073741824 -
  // 73741824 total_inactive_file) = 1147483648; the parents have no limit.
  root = base + "/v1-limit";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/cgroup",
    "12:cpu,cpuacct:/slurm/uid_0/job_7\n11:memory:/slurm/uid_0/job_7\n0::/\n");
  const std::string job = "sys/fs/cgroup/memory/slurm/uid_0/job_7/";
  Write(root, job + "memory.limit_in_bytes", "2147483648\n");
  Write(root, job + "memory.usage_in_bytes", "1073741824\n");
  Write(root, job + "memory.stat", "inactive_file 999\ntotal_inactive_file 73741824\n");
  Write(root, "sys/fs/cgroup/memory/slurm/uid_0/memory.limit_in_bytes", V1Unlimited);
  Write(root, "sys/fs/cgroup/memory/slurm/uid_0/memory.usage_in_bytes", "3000000000\n");
  Write(root, "sys/fs/cgroup/memory/memory.limit_in_bytes", V1Unlimited);
  Write(root, "sys/fs/cgroup/memory/memory.usage_in_bytes", "9000000000\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 1147483648.0, 0.5);
  CHECK(SystemMemoryRoom(root).cgroupBinds);

  // v1 without a limit anywhere: MemAvailable is the room.
  root = base + "/v1-unlimited";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/cgroup", "4:memory:/user/1000\n");
  Write(root, "sys/fs/cgroup/memory/user/1000/memory.limit_in_bytes", V1Unlimited);
  Write(root, "sys/fs/cgroup/memory/user/1000/memory.usage_in_bytes", "123456789\n");
  Write(root, "sys/fs/cgroup/memory/memory.limit_in_bytes", V1Unlimited);
  CHECK(std::isinf(CgroupMemoryRoom(root)));
  CHECK_NEAR(SystemMemoryRoom(root).bytes, MemAvailable, 0.5);
  CHECK(!SystemMemoryRoom(root).cgroupBinds);

  // No cgroup files at all: MemAvailable; nothing at all: no bound.
  root = base + "/no-cgroup";
  Write(root, "proc/meminfo", MemInfo);
  CHECK(std::isinf(CgroupMemoryRoom(root)));
  CHECK_NEAR(SystemMemoryRoom(root).bytes, MemAvailable, 0.5);
  CHECK(!SystemMemoryRoom(root).cgroupBinds);
  CHECK(std::isinf(SystemMemoryRoom(base + "/nothing").bytes));
  // The cgroup named but its files absent (cgroup fs not mounted).
  Write(root, "proc/self/cgroup", "0::/job\n4:memory:/job\n");
  CHECK(std::isinf(CgroupMemoryRoom(root)));

  // A container's namespaced paths, absent under the mounts: the mounts' roots
  // are its cgroups. v2 536870912 - 136870912 = 400000000; v1 1000000000 -
  // 250000000 = 750000000 (hybrid: both count, the tighter binds).
  root = base + "/v2-namespaced";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/cgroup", "0::/kubepods/pod1/ctr\n");
  Write(root, "sys/fs/cgroup/memory.max", "536870912\n");
  Write(root, "sys/fs/cgroup/memory.current", "136870912\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 4e8, 0.5);
  root = base + "/v1-namespaced";
  Write(root, "proc/self/cgroup", "5:memory:/docker/abc\n");
  Write(root, "sys/fs/cgroup/memory/memory.limit_in_bytes", "1000000000\n");
  Write(root, "sys/fs/cgroup/memory/memory.usage_in_bytes", "250000000\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 7.5e8, 0.5);
  Write(root, "proc/self/cgroup", "5:memory:/docker/abc\n0::/docker/abc\n");
  Write(root, "sys/fs/cgroup/memory.max", "536870912\n");
  Write(root, "sys/fs/cgroup/memory.current", "136870912\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 4e8, 0.5);

  // The mounts from mountinfo: v1 memory bind-mounted from /docker/abc, so the
  // process's /docker/abc/sub is memory/sub, which leaves 600000000 - 300000000
  // = 300000000 (its parent, the mount, 800000000 - 400000000 = 400000000). v2
  // is at unified/ and has no limit; the decoy memory.max at the usual v2 place
  // (1 byte) must not be read.
  root = base + "/mountinfo";
  Write(root, "proc/meminfo", MemInfo);
  Write(root, "proc/self/mountinfo",
    "30 22 0:27 / /sys/fs/cgroup rw,relatime - tmpfs tmpfs rw,mode=755\n"
    "31 30 0:28 /docker/abc /sys/fs/cgroup/cpu rw,relatime - cgroup cgroup rw,cpu\n"
    "34 30 0:31 /docker/abc /sys/fs/cgroup/memory rw,nosuid shared:5 - cgroup cgroup rw,memory\n"
    "40 30 0:37 / /sys/fs/cgroup/unified rw,relatime - cgroup2 cgroup2 rw\n");
  Write(root, "proc/self/cgroup", "4:memory:/docker/abc/sub\n1:cpu:/docker/abc\n0::/docker/abc\n");
  Write(root, "sys/fs/cgroup/memory/sub/memory.limit_in_bytes", "600000000\n");
  Write(root, "sys/fs/cgroup/memory/sub/memory.usage_in_bytes", "300000000\n");
  Write(root, "sys/fs/cgroup/memory/memory.limit_in_bytes", "800000000\n");
  Write(root, "sys/fs/cgroup/memory/memory.usage_in_bytes", "400000000\n");
  Write(root, "sys/fs/cgroup/unified/cgroup.procs", "");
  Write(root, "sys/fs/cgroup/memory.max", "1\n");
  CHECK_NEAR(CgroupMemoryRoom(root), 3e8, 0.5);

  std::filesystem::remove_all(base);
}

} // namespace

int main(int argc, char* argv[])
{
  CheckCgroupFixtures(std::string(argc > 1 ? argv[1] : ".") + "/cgroup_fixtures");
#if defined(__SANITIZE_ADDRESS__)
  // ASan's allocator keeps freed blocks in quarantine, out of malloc_trim's reach.
  std::cout << "TestMemoryGuard: the allocator part not run under AddressSanitizer\n";
  return check::Finish("TestMemoryGuard");
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
