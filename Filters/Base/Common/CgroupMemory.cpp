#include "CgroupMemory.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace flowrecon
{

namespace
{

/// The files of one cgroup version.
struct Version
{
  const char* limit;
  const char* usage;
  const char* inactiveFile; // key in memory.stat
};
const Version V2{ "memory.max", "memory.current", "inactive_file" };
const Version V1{ "memory.limit_in_bytes", "memory.usage_in_bytes", "total_inactive_file" };

/// v1 writes "no limit" as the largest page-aligned long (9223372036854771712
/// with 4 kB pages); nothing real comes near 2^62 bytes.
const double Unlimited = 4.6e18;

/// The number a file starts with, -1 if absent or not a number ("max").
double ReadNumber(const std::string& file)
{
  std::ifstream in(file);
  double value = -1;
  return in >> value ? value : -1;
}

/// A key's value in memory.stat, 0 if absent.
double StatField(const std::string& file, const std::string& key)
{
  std::ifstream in(file);
  std::string name;
  double value = 0;
  while (in >> name >> value)
  {
    if (name == key)
    {
      return value;
    }
  }
  return 0;
}

bool IsDirectory(const std::string& path)
{
  struct stat info{};
  return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

/// Whether a comma-separated list holds `item`.
bool Lists(const std::string& list, const std::string& item)
{
  std::istringstream items(list);
  std::string one;
  while (std::getline(items, one, ','))
  {
    if (one == item)
    {
      return true;
    }
  }
  return false;
}

/// Where a hierarchy is mounted, and which of its cgroups the mount shows as
/// its root (not "/" when a container bind-mounts its own cgroup).
struct Mount
{
  std::string point;
  std::string cgroup = "/";
};

/// The mount of the v2 hierarchy, or of the v1 hierarchy holding the memory
/// controller, from mountinfo ("id parent dev root point options... - type
/// source superoptions"); the usual place if mountinfo does not say.
Mount FindMount(const std::string& root, bool v2)
{
  Mount mount;
  mount.point = root + (v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory");
  std::ifstream in(root + "/proc/self/mountinfo");
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string id, parent, device, cgroup, point, word, type, source, options;
    fields >> id >> parent >> device >> cgroup >> point;
    while (fields >> word && word != "-")
    {
    }
    fields >> type >> source >> options;
    if (v2 ? type == "cgroup2" : type == "cgroup" && Lists(options, "memory"))
    {
      mount.point = root + point;
      mount.cgroup = cgroup;
      break;
    }
  }
  return mount;
}

/// limit - (usage - inactive file pages) of one cgroup, HUGE_VAL if it has no limit.
double Room(const std::string& directory, const Version& version)
{
  const double limit = ReadNumber(directory + "/" + version.limit);
  if (limit < 0 || limit >= Unlimited)
  {
    return HUGE_VAL;
  }
  const double usage = std::max(0.0, ReadNumber(directory + "/" + version.usage));
  const double inactive = StatField(directory + "/memory.stat", version.inactiveFile);
  return std::max(0.0, limit - std::max(0.0, usage - inactive));
}

/// The least room over the cgroup `path` (as /proc/self/cgroup names it) and its
/// ancestors up to the mount's root: a parent's limit binds its children too.
double HierarchyRoom(const Mount& mount, std::string path, const Version& version)
{
  if (mount.cgroup != "/" && path.compare(0, mount.cgroup.size(), mount.cgroup) == 0 &&
    (path.size() == mount.cgroup.size() || path[mount.cgroup.size()] == '/'))
  {
    path.erase(0, mount.cgroup.size());
  }
  while (!path.empty() && path.back() == '/')
  {
    path.pop_back();
  }
  if (path.find("/..") != std::string::npos || !IsDirectory(mount.point + path))
  {
    path.clear(); // a namespaced path: the mount's root is this cgroup or an ancestor
  }
  double room = HUGE_VAL;
  for (;;)
  {
    room = std::min(room, Room(mount.point + path, version));
    if (path.empty())
    {
      return room;
    }
    const size_t slash = path.rfind('/');
    path.erase(slash == std::string::npos ? 0 : slash);
  }
}

} // namespace

double CgroupMemoryRoom(const std::string& root)
{
  std::string prefix = root;
  while (!prefix.empty() && prefix.back() == '/')
  {
    prefix.pop_back();
  }
  // "hierarchy:controllers:path"; v2 is "0::path", v1 lists its controllers.
  std::ifstream in(prefix + "/proc/self/cgroup");
  std::string line;
  double room = HUGE_VAL;
  while (std::getline(in, line))
  {
    const size_t first = line.find(':');
    const size_t second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos)
    {
      continue;
    }
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    if (line.compare(0, first, "0") == 0 && controllers.empty())
    {
      room = std::min(room, HierarchyRoom(FindMount(prefix, true), path, V2));
    }
    else if (Lists(controllers, "memory"))
    {
      room = std::min(room, HierarchyRoom(FindMount(prefix, false), path, V1));
    }
  }
  return room;
}

} // namespace flowrecon
