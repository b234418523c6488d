// Refusing work that would not fit (docs/design.md: "Never killed for memory"): the
// kernel's out-of-memory killer ends a process without a word, and an address-
// space limit turns into an uncaught allocation failure deep inside a library.
#ifndef flowrecon_MemoryGuard_h
#define flowrecon_MemoryGuard_h

#include <cstddef>
#include <string>

namespace flowrecon
{

/// Bytes this process can still allocate: the least of the system's
/// MemAvailable, the room its cgroups leave (CgroupMemory.h) and what the
/// address-space limit (ulimit -v) leaves; a test may lower it with the
/// environment variable FLOWRECON_MEMORY_LIMIT (bytes, the total the process may
/// use), which is how the guard is tested without exhausting the machine.
double AvailableMemory();

/// Bytes the system leaves, and whether a cgroup limit is what binds.
struct MemoryRoom
{
  double bytes;
  bool cgroupBinds;
};

/// The smaller of MemAvailable and CgroupMemoryRoom(), from the files under
/// `root` ("/" for this process, a fixture tree in tests); HUGE_VAL bytes when
/// neither is known.
MemoryRoom SystemMemoryRoom(const std::string& root);

/// Throws InputError("<what> needs about X GB of memory, Y GB are available;
/// <advice>") when `bytes` exceeds AvailableMemory(), also after
/// ReleaseFreedMemory(); "are available (cgroup memory limit);" when the cgroup
/// binds, so that a refusal in a container does not look like a full machine.
void RequireMemory(double bytes, const std::string& what, const std::string& advice);

/// Hands the pages of freed blocks back to the system (tbbmalloc's buffers and
/// the C heap): after a phase frees gigabytes, the process's resident size would
/// otherwise keep them, which a long-lived process (ParaView) pays for in every
/// later stage, and the next large mapping cannot reuse.
void ReleaseFreedMemory();

} // namespace flowrecon

#endif
