#pragma once
// What this process may take of the machine it runs on: memory and CPUs.
// Under a scheduler (Slurm, a container, `ulimit`) a run gets less than the
// machine has; budgets and thread counts follow the process's own limits
// (Doc/reliability.md, "Resource limits").
#include <string>
#include <vector>

namespace soak {

// One bound on the memory a run's arrays may take: `bytes` (< 0: no bound)
// and what sets it, in the user's words ("ulimit -v (RLIMIT_AS)").
struct MemoryBound {
  double bytes = -1.0;
  std::string source;
};

// Every bound that applies to host memory: the machine's memory, RLIMIT_AS
// and RLIMIT_DATA less what the process maps already, the cgroup's
// memory.max (v2) or memory.limit_in_bytes (v1) less what the group uses,
// and SOAK_MEMORY_LIMIT.
std::vector<MemoryBound> hostMemoryBounds();
// The smallest of `bounds` that is set ({-1, ""} when none is).
MemoryBound smallestBound(const std::vector<MemoryBound>& bounds);

// SOAK_MEMORY_LIMIT: the most the run's arrays may take on its device (host
// or GPU), in bytes with an optional K, M, G or T (powers of 1024). Lets
// several runs share one GPU or stay under a job's allowance. < 0 when unset;
// InputError when it does not parse.
double memoryLimitFromEnvironment();
// "8G", "512M", "1.5G", "1048576" -> bytes; < 0 when `text` is not a size.
double parseByteSize(const std::string& text);

// The cgroup v2 path of this process from /proc/self/cgroup's text (the
// "0::/path" line); empty when there is none.
std::string cgroupV2Path(const std::string& procSelfCgroup);
// A cgroup limit file's value ("max" or a byte count); < 0 for "max" or
// anything that is not a count.
double parseCgroupLimit(const std::string& text);

// CPUs this process may use: those in its affinity mask, at most
// SLURM_CPUS_PER_TASK where that is set and the cgroup's cpu.max quota
// rounded up. `source` (if given) says which bound decided.
int usableCpuCount(std::string* source = nullptr);

}  // namespace soak
