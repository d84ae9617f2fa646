#pragma once
// Per-cloth-vertex values that stages of different owners share by name
// (indexed by vertex id, on the simulation's device). The core reads the
// fields named here; a plugin writes them through get(), never through a
// pointer of its own that the core would have to be handed.
#include <map>
#include <memory>
#include <string>

#include "Backend/Buffer.h"

namespace soak {

namespace field {
// kappa_couple of Eq. 22: how strongly the coupling stage (Eq. 21) holds
// water out of the cloth at each vertex; without the field, 1 everywhere
// (dry cloth). WetCloth's wet.volume writes it before the coupling stage.
inline constexpr const char* kCouplingStiffness = "coupling_stiffness";
// Factor on each bend's stiffness (Eq. 9; the mean of its four vertices'
// values), read by both cloth solvers; without the field, 1. WetCloth's
// wet.volume writes it where wetBendSoftening > 0 (wet cloth bends easier).
inline constexpr const char* kBendStiffnessScale = "bend_stiffness_scale";
// Factor on the friction of colliders against a cloth vertex (the
// collider's fraction of tangential motion removed, times this, at most 1);
// without the field, 1. WetCloth writes it where wetFriction > 0.
inline constexpr const char* kFrictionScale = "friction_scale";
}  // namespace field

class VertexFields {
 public:
  explicit VertexFields(Device device) : device_(device) {}
  // The field `name`: made with every vertex at `initial` by the first call,
  // the same array (its values as they are) at later calls.
  float* get(const std::string& name, int vertexCount, float initial);
  // The field, or null where no stage asked for it.
  const float* find(const std::string& name) const;

 private:
  Device device_;
  std::map<std::string, std::unique_ptr<Buffer<float>>> fields_;
};

}  // namespace soak
