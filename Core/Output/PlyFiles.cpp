#include "Output/PlyFiles.h"

#include <vtkPLY.h>

#include <algorithm>
#include <cstddef>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace soak {

std::array<unsigned char, 3> wetnessColour(float value) {
  const float t = std::clamp(value, 0.f, 1.f);
  // Linear from white (255, 255, 255) to a deep blue (20, 60, 160).
  auto mix = [t](float dry, float wet) { return static_cast<unsigned char>(dry + t * (wet - dry) + 0.5f); };
  return {mix(255.f, 20.f), mix(255.f, 60.f), mix(255.f, 160.f)};
}

std::string clothPlyBytes(const ClothPlyFrame& f) {
  const std::size_t n = f.position.size();
  if (f.velocity.size() != n) throw std::logic_error("PLY: velocity count differs from position count");
  for (const PointArray& c : f.channels)
    if (c.components != 1 || c.values.size() != n)
      throw std::logic_error("PLY: channel '" + c.name + "' has the wrong size");
  const bool colour = f.colourChannel >= 0 && f.colourChannel < int(f.channels.size());

  // A vertex record: floats x y z vx vy vz and one per channel, then the
  // three colour bytes. vtkPLY reads each property at its offset.
  const std::size_t floats = 6 + f.channels.size();
  const std::size_t colourOffset = floats * sizeof(float);
  std::vector<std::string> names{"x", "y", "z", "vx", "vy", "vz"};
  for (const PointArray& c : f.channels) names.push_back(c.name);
  std::vector<PlyProperty> vertexProps;
  for (std::size_t k = 0; k < floats; ++k)
    vertexProps.push_back({names[k].c_str(), PLY_FLOAT, PLY_FLOAT, int(k * sizeof(float)), 0, 0, 0, 0});
  if (colour) {
    const char* rgb[3] = {"red", "green", "blue"};
    for (int k = 0; k < 3; ++k) vertexProps.push_back({rgb[k], PLY_UCHAR, PLY_UCHAR, int(colourOffset) + k, 0, 0, 0, 0});
  }
  struct Face {
    unsigned char count;
    int* vertices;
  };
  PlyProperty faceProp{"vertex_indices", PLY_INT,   PLY_INT,  int(offsetof(Face, vertices)),
                       1,                PLY_UCHAR, PLY_UCHAR, int(offsetof(Face, count))};

  // vtkPLY keeps its allocations in one global heap that ply_close frees:
  // one file at a time, whichever writer thread asks.
  static std::mutex plyLibrary;
  std::lock_guard<std::mutex> lock(plyLibrary);
  std::string empty;
  const char* elements[2] = {"vertex", "face"};
  PlyFile* ply = vtkPLY::ply_open_for_writing_to_string(empty, 2, elements, PLY_BINARY_LE);
  if (!ply) throw std::runtime_error("PLY: cannot start a file");
  vtkPLY::ply_element_count(ply, "vertex", int(n));
  for (PlyProperty& p : vertexProps) vtkPLY::ply_describe_property(ply, "vertex", &p);
  vtkPLY::ply_element_count(ply, "face", int(f.triangles.size()));
  vtkPLY::ply_describe_property(ply, "face", &faceProp);
  // ply_close frees the comment and object-information lists, which
  // ply_write leaves uninitialised until a first entry: one of each.
  vtkPLY::ply_put_comment(ply, "Soak cloth frame (Doc/output.md)");
  vtkPLY::ply_put_obj_info(ply, "soak cloth mesh");
  vtkPLY::ply_header_complete(ply);
  vtkPLY::ply_put_element_setup(ply, "vertex");
  std::vector<float> record(floats + 1);  // the last float's bytes hold the colour
  unsigned char* colourBytes = reinterpret_cast<unsigned char*>(record.data()) + colourOffset;
  for (std::size_t i = 0; i < n; ++i) {
    float* v = record.data();
    v[0] = f.position[i].x, v[1] = f.position[i].y, v[2] = f.position[i].z;
    v[3] = f.velocity[i].x, v[4] = f.velocity[i].y, v[5] = f.velocity[i].z;
    for (std::size_t c = 0; c < f.channels.size(); ++c) v[6 + c] = f.channels[c].values[i];
    if (colour) {
      const auto rgb = wetnessColour(f.channels[std::size_t(f.colourChannel)].values[i]);
      std::copy(rgb.begin(), rgb.end(), colourBytes);
    }
    vtkPLY::ply_put_element(ply, record.data());
  }
  vtkPLY::ply_put_element_setup(ply, "face");
  for (const auto& t : f.triangles) {
    int vertices[3] = {t[0], t[1], t[2]};
    Face face{3, vertices};
    vtkPLY::ply_put_element(ply, &face);
  }
  // The library writes to a string stream of its own, which ply_close deletes.
  std::string bytes = static_cast<std::ostringstream*>(ply->os)->str();
  vtkPLY::ply_close(ply);
  return bytes;
}

void writeClothPly(const std::string& path, const ClothPlyFrame& frame) {
  writeFileAtomically(path, clothPlyBytes(frame), false);
}

}  // namespace soak
