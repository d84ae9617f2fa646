#include "Output/PlyFiles.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

// The records are written in the host's byte order.
#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "PlyFiles.cpp writes little-endian PLY and assumes a little-endian host"
#endif

namespace soak {

std::array<unsigned char, 3> wetnessColour(float value) {
  const float t = std::clamp(value, 0.f, 1.f);
  // Linear from white (255, 255, 255) to a deep blue (20, 60, 160).
  auto mix = [t](float dry, float wet) { return static_cast<unsigned char>(dry + t * (wet - dry) + 0.5f); };
  return {mix(255.f, 20.f), mix(255.f, 60.f), mix(255.f, 160.f)};
}

namespace {
template <class T>
void append(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}
}  // namespace

// The header names the properties in record order; each vertex is one
// packed little-endian record (floats, then the colour bytes) and each face
// a count byte and three int32s. The same bytes as vtkPLY's writer makes,
// without its global state, so writer threads write PLY files at once.
std::string clothPlyBytes(const ClothPlyFrame& f) {
  const std::size_t n = f.position.size();
  if (f.velocity.size() != n) throw std::logic_error("PLY: velocity count differs from position count");
  for (const PointArray& c : f.channels)
    if (c.components != 1 || c.values.size() != n)
      throw std::logic_error("PLY: channel '" + c.name + "' has the wrong size");
  const bool colour = f.colourChannel >= 0 && f.colourChannel < int(f.channels.size());

  std::string out = "ply\nformat binary_little_endian 1.0\ncomment Soak cloth frame (Doc/output.md)\n"
                    "obj_info soak cloth mesh\nelement vertex " + std::to_string(n) + "\n";
  for (const char* name : {"x", "y", "z", "vx", "vy", "vz"}) out += std::string("property float ") + name + "\n";
  for (const PointArray& c : f.channels) out += "property float " + c.name + "\n";
  if (colour) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "element face " + std::to_string(f.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";

  const std::size_t record = (6 + f.channels.size()) * sizeof(float) + (colour ? 3 : 0);
  out.reserve(out.size() + n * record + f.triangles.size() * (1 + 3 * sizeof(std::int32_t)));
  for (std::size_t i = 0; i < n; ++i) {
    for (float v : {f.position[i].x, f.position[i].y, f.position[i].z, f.velocity[i].x, f.velocity[i].y,
                    f.velocity[i].z})
      append(out, v);
    for (const PointArray& c : f.channels) append(out, c.values[i]);
    if (colour) {
      const auto rgb = wetnessColour(f.channels[std::size_t(f.colourChannel)].values[i]);
      out.append(reinterpret_cast<const char*>(rgb.data()), rgb.size());
    }
  }
  for (const auto& t : f.triangles) {
    append(out, static_cast<unsigned char>(3));
    for (int v : t) append(out, static_cast<std::int32_t>(v));
  }
  return out;
}

void writeClothPly(const std::string& path, const ClothPlyFrame& frame) {
  writeFileAtomically(path, clothPlyBytes(frame), false);
}

}  // namespace soak
