#include "Sweep/SweepRecord.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "Base/Error.h"

namespace soak {

namespace {
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}
}  // namespace

PointRecord readPointRecord(const std::string& path) {
  PointRecord r;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    if (key == "status") r.status = value;
    else if (key == "exit_code") r.exitCode = std::atoi(value.c_str());
    else if (key == "wall_s") r.wallSeconds = std::atof(value.c_str());
    else if (key == "attempts") r.attempts = std::atoi(value.c_str());
    else if (key == "error") r.error = value;
    else if (key == "host") r.host = value;
    else if (key == "pid") r.pid = std::atoll(value.c_str());
  }
  return r;
}

void writePointRecord(const std::string& path, const PointRecord& r) {
  std::ostringstream o;
  char wall[32];
  std::snprintf(wall, sizeof(wall), "%.3f", r.wallSeconds);
  o << "status=" << r.status << "\nexit_code=" << r.exitCode << "\nwall_s=" << wall << "\nattempts=" << r.attempts
    << "\nerror=" << oneLine(r.error) << "\nhost=" << oneLine(r.host) << "\npid=" << r.pid << "\n";
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << o.str();
    out.flush();
    if (!out) throw StorageError(tmp, errno, std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw StorageError(path, errno, std::strerror(errno));
}

std::string thisHostName() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown";
  std::string h(name);
  return h.substr(0, h.find('.'));
}

}  // namespace soak
