#include "Base/ReadInput.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "Base/Error.h"

namespace soak {

namespace {
std::string sizeText(std::uint64_t bytes) {
  if (bytes >= (1ull << 30) && bytes % (1ull << 30) == 0) return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (1ull << 20) && bytes % (1ull << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}
}  // namespace

std::string readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError("cannot open " + what + ": " + std::strerror(errno), path);
  if (S_ISDIR(st.st_mode)) throw InputError(what + " is a folder, not a file", path);
  if (!S_ISREG(st.st_mode))
    throw InputError(what + " is not a regular file (a device, a pipe or a socket); give a file", path);
  if (std::uint64_t(st.st_size) > maxBytes)
    throw InputError(what + " is " + std::to_string(std::uint64_t(st.st_size)) + " bytes; a " + what +
                         " may be at most " + sizeText(maxBytes),
                     path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open " + what + ": " + std::strerror(errno), path);
  // Read at most one byte past the limit: a file that grew since stat() is
  // refused rather than followed.
  std::string text(std::size_t(st.st_size), '\0');
  in.read(&text[0], std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  char extra = 0;
  while (in.get(extra)) {
    if (text.size() >= maxBytes)
      throw InputError(what + " grew past " + sizeText(maxBytes) + " while it was read", path);
    text.push_back(extra);
  }
  return text;
}

std::string pathBesideScene(const std::string& sceneFile, const std::string& path) {
  if (path.empty() || path[0] == '/') return path;
  const std::size_t slash = sceneFile.find_last_of('/');
  return slash == std::string::npos ? path : sceneFile.substr(0, slash + 1) + path;
}

}  // namespace soak
