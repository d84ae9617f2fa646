#include "Backend/ProcessLimits.h"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "Base/Error.h"

namespace soak {

namespace {

std::string readSmallFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A field of /proc/self/status in bytes ("VmSize:   3896 kB"); < 0 if absent.
double procStatusBytes(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) return std::atof(line.c_str() + key.size()) * 1024.0;
  return -1.0;
}

// Limits at or past 2^60 bytes are "unlimited" written as a number (cgroup
// v1 writes 9223372036854771712, RLIM_INFINITY is 2^64 - 1).
constexpr double kNoLimit = 1152921504606846976.0;

// A resource limit less what the process already uses of it.
void addRlimit(std::vector<MemoryBound>& out, int resource, const char* field, const char* name) {
  rlimit r{};
  if (::getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY || double(r.rlim_cur) >= kNoLimit) return;
  const double used = std::max(procStatusBytes(field), 0.0);
  out.push_back({std::max(double(r.rlim_cur) - used, 0.0), name});
}

// The cgroup v1 memory controller's path ("4:memory:/path"); empty if none.
std::string cgroupV1MemoryPath(const std::string& procSelfCgroup) {
  std::istringstream in(procSelfCgroup);
  std::string line;
  while (std::getline(in, line)) {
    const auto a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    std::istringstream controllers(line.substr(a + 1, b - a - 1));
    std::string c;
    while (std::getline(controllers, c, ','))
      if (c == "memory") return line.substr(b + 1);
  }
  return {};
}

// The smallest limit on `path` and its ancestors under `root` (a limit on
// a parent group binds its children too).
double cgroupLimit(const std::string& root, std::string path, const char* file) {
  double smallest = -1.0;
  while (true) {
    const double v = parseCgroupLimit(readSmallFile(root + path + "/" + file));
    if (v >= 0.0 && (smallest < 0.0 || v < smallest)) smallest = v;
    if (path.empty() || path == "/") break;
    const auto slash = path.find_last_of('/');
    path = slash == std::string::npos || slash == 0 ? std::string() : path.substr(0, slash);
  }
  return smallest;
}

}  // namespace

double parseByteSize(const std::string& text) {
  const char* s = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (end == s || !std::isfinite(v) || v < 0.0) return -1.0;
  double unit = 1.0;
  std::string suffix(end);
  if (!suffix.empty() && (suffix.back() == 'B' || suffix.back() == 'b')) suffix.pop_back();
  if (!suffix.empty() && (suffix.back() == 'i')) suffix.pop_back();
  if (suffix.size() > 1) return -1.0;
  if (suffix.size() == 1) {
    switch (suffix[0]) {
      case 'k': case 'K': unit = 1024.0; break;
      case 'm': case 'M': unit = 1024.0 * 1024.0; break;
      case 'g': case 'G': unit = 1024.0 * 1024.0 * 1024.0; break;
      case 't': case 'T': unit = 1024.0 * 1024.0 * 1024.0 * 1024.0; break;
      default: return -1.0;
    }
  }
  return std::floor(v * unit);
}

double memoryLimitFromEnvironment() {
  const char* v = std::getenv("SOAK_MEMORY_LIMIT");
  if (!v || !*v) return -1.0;
  const double bytes = parseByteSize(v);
  if (bytes <= 0.0)
    throw InputError(std::string("SOAK_MEMORY_LIMIT='") + v +
                     "' is not a size in bytes (a number with an optional K, M, G or T, e.g. 8G)");
  return bytes;
}

std::string cgroupV2Path(const std::string& procSelfCgroup) {
  std::istringstream in(procSelfCgroup);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, 3, "0::") == 0) return line.substr(3);
  return {};
}

double parseCgroupLimit(const std::string& text) {
  std::istringstream in(text);
  std::string word;
  if (!(in >> word) || word == "max") return -1.0;
  char* end = nullptr;
  const double v = std::strtod(word.c_str(), &end);
  if (*end != '\0' || !(v >= 0.0) || v >= kNoLimit) return -1.0;
  return v;
}

std::vector<MemoryBound> hostMemoryBounds() {
  std::vector<MemoryBound> out;
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && pageSize > 0) out.push_back({double(pages) * double(pageSize), "the machine's memory"});
  addRlimit(out, RLIMIT_AS, "VmSize", "ulimit -v (RLIMIT_AS)");
  addRlimit(out, RLIMIT_DATA, "VmData", "ulimit -d (RLIMIT_DATA)");
  const std::string cgroups = readSmallFile("/proc/self/cgroup");
  const std::string v2 = cgroupV2Path(cgroups);
  if (!v2.empty()) {
    const double max = cgroupLimit("/sys/fs/cgroup", v2 == "/" ? std::string() : v2, "memory.max");
    if (max >= 0.0) out.push_back({max, "the cgroup's memory.max"});
  }
  const std::string v1 = cgroupV1MemoryPath(cgroups);
  if (!v1.empty()) {
    const double max = cgroupLimit("/sys/fs/cgroup/memory", v1 == "/" ? std::string() : v1, "memory.limit_in_bytes");
    if (max >= 0.0) out.push_back({max, "the cgroup's memory.limit_in_bytes"});
  }
  const double env = memoryLimitFromEnvironment();
  if (env >= 0.0) out.push_back({env, "SOAK_MEMORY_LIMIT"});
  return out;
}

MemoryBound smallestBound(const std::vector<MemoryBound>& bounds) {
  MemoryBound best;
  for (const MemoryBound& b : bounds)
    if (b.bytes >= 0.0 && (best.bytes < 0.0 || b.bytes < best.bytes)) best = b;
  return best;
}

int usableCpuCount(std::string* source) {
  int n = 0;
  std::string why;
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof(set), &set) == 0) {
    n = CPU_COUNT(&set);
    why = "the CPUs this process may run on (affinity)";
  }
  if (n <= 0) {
    n = int(std::max(::sysconf(_SC_NPROCESSORS_ONLN), 1L));
    why = "the machine's CPUs";
  }
  if (const char* slurm = std::getenv("SLURM_CPUS_PER_TASK")) {
    const int s = std::atoi(slurm);
    if (s > 0 && s < n) {
      n = s;
      why = "SLURM_CPUS_PER_TASK";
    }
  }
  // cgroup v2 cpu.max: "quota period" or "max period".
  const std::string v2 = cgroupV2Path(readSmallFile("/proc/self/cgroup"));
  if (!v2.empty()) {
    std::istringstream in(readSmallFile("/sys/fs/cgroup" + (v2 == "/" ? std::string() : v2) + "/cpu.max"));
    std::string quota;
    double period = 0.0;
    if (in >> quota >> period && quota != "max" && period > 0.0) {
      const int q = int(std::ceil(std::atof(quota.c_str()) / period));
      if (q > 0 && q < n) {
        n = q;
        why = "the cgroup's cpu.max";
      }
    }
  }
  if (source) *source = why;
  return n;
}

}  // namespace soak
