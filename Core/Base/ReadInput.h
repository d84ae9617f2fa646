#pragma once
// Reading a file the user gave (a scene, a mesh, a checkpoint) with a size
// limit: only regular files are read (a path to /dev/zero, a FIFO or a
// folder is refused), and a file larger than the limit is refused before a
// byte of it is read, so no input can make the reader allocate without end.
#include <cstdint>
#include <string>

namespace soak {

// Limits on what one input file may hold (Doc/reliability.md).
constexpr std::uint64_t kMaxSceneBytes = 16ull << 20;        // 16 MiB of XML
constexpr std::uint64_t kMaxMeshBytes = 1ull << 30;          // 1 GiB of OBJ
constexpr std::uint64_t kMaxCheckpointBytes = 64ull << 30;   // 64 GiB of state

// Returns the whole file. Throws InputError naming `path` and `what` (e.g.
// "scene file") when it is missing, not a regular file, larger than
// `maxBytes` or unreadable.
std::string readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what);

// A path written in a scene (a mesh, a plugin library): relative ones are
// taken from the folder of `sceneFile`, absolute ones as they are.
std::string pathBesideScene(const std::string& sceneFile, const std::string& path);

}  // namespace soak
