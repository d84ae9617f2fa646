#pragma once
// A sheet folded in two, for the contact tests on either device: an OBJ of
// (2 n + 1) x (n + 1) vertices, the lower layer at height y0, the upper one
// `gap` above it, the fold at u = size.
#include <string>
#include <vector>

#include "Backend/Device.h"
#include "Base/Vec3.h"

namespace soak::test {

struct FoldedSheet {
  int n = 16;
  float size = 0.4f, gap = 0.03f, y0 = 0.3f;
  // Writes the OBJ to `path`.
  void write(const std::string& path) const;
  // The smallest height of an upper-layer vertex above its partner of the
  // lower layer, over the interior (the free edges and the fold's loop may
  // droop past the other layer's edge onto the floor). x: vertex positions.
  float smallestLayerGap(const std::vector<Vec3>& x) const;
  // Writes the sheet to `obj`, drops it on a floor on `device` with the
  // given <Simulation> and <Cloth> attributes, and returns the smallest
  // layer gap over `steps` steps.
  float smallestGapWhenDropped(Device device, const std::string& obj, const std::string& simulation,
                               const std::string& cloth, int steps = 150) const;
};

}  // namespace soak::test
