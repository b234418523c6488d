// A container's memory limit (Docker, Kubernetes, Slurm, systemd) is a cgroup
// limit: past it the kernel kills the process, however much memory the machine
// has free, and MemAvailable shows the machine's.
#ifndef flowrecon_CgroupMemory_h
#define flowrecon_CgroupMemory_h

#include <string>

namespace flowrecon
{

/// Bytes the memory cgroups of this process still leave it: the least of
/// limit - usage over its cgroup and every ancestor with a limit, for cgroup v2
/// (memory.max, memory.current) and v1 (memory.limit_in_bytes,
/// memory.usage_in_bytes). Usage leaves out the inactive file pages of
/// memory.stat (inactive_file, v1 total_inactive_file) as docker stats and the
/// kubelet do: the kernel reclaims them before it kills, and counting the page
/// cache of the cloud just read would refuse runs that fit. A cgroup path that is
/// not under the mount (a container sees its own cgroup as the root) falls back
/// to the mount's root. The files are read under `root` ("/" for this process, a
/// fixture tree holding proc/self/... and sys/fs/cgroup/... in tests).
/// HUGE_VAL when no cgroup sets a limit or there are no cgroup files.
double CgroupMemoryRoom(const std::string& root = "/");

} // namespace flowrecon

#endif
