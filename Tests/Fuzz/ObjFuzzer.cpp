// libFuzzer target: the OBJ mesh loader (our line checks, tinyobjloader,
// the cloth-mesh checks) on arbitrary bytes. Anything may be refused with
// InputError; nothing may crash, leak or hit undefined behaviour.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "Base/Error.h"
#include "Scene/TriangleMesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // loadObjMesh reads a file: one per process, rewritten for every input.
  static const std::string path = "/tmp/soak_obj_fuzz_" + std::to_string(::getpid()) + ".obj";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    soak::TriangleMesh mesh = soak::loadObjMesh(path);
    soak::validateClothMesh(mesh, path);
  } catch (const soak::InputError&) {
  }
  return 0;
}
