#pragma once
// The names of the core's stages, in the order of a step (Algorithm 1 of
// the paper, dry part). A plugin anchors its stages on these (or on another
// plugin's stage names, which that plugin publishes the same way), so that
// a renamed stage is a compile error, not a scene that fails to load.
namespace soak::stage {

inline constexpr const char* kPredict = "predict";        // external forces, predicted positions
inline constexpr const char* kDrain = "drain";            // sinks, domain, wholly absorbed water
inline constexpr const char* kNeighbours = "neighbours";  // the grid, cloth slots and boundary volumes
inline constexpr const char* kFluidSolve = "fluid.solve";  // the density constraints (PBF)
inline constexpr const char* kClothSolve = "cloth.solve";  // the cloth constraints and contacts
inline constexpr const char* kCollide = "collide";        // the water out of the colliders (the cloth solve did the cloth's)
inline constexpr const char* kCoupling = "coupling";      // water-triangle constraint (Eq. 21), reads kappa_couple
inline constexpr const char* kFinalize = "finalize";      // velocities, XSPH, vorticity

}  // namespace soak::stage
