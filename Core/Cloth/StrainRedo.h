#pragma once
// The strain redo: a step whose cloth solve leaves more than 1 % of the
// strain edges past clothStrainRedo times clothStrainTarget (the 99th
// percentile of edge strain past that bound: 3 % by default) runs its
// cloth sub-steps again from the step's start, half as many again.
//
// Why: the strain rule (AdaptiveSubsteps.h) sets a step's count from the
// strain the step before left, so a load that grows within a few steps
// (a water block landing on a sheet, a ball starting to lift a soaked
// sheet) meets the count of a lighter step. Raising the count after such a
// step lowers the strain only in the next ones, and the vertices jump to
// the new equilibrium within a step. Solving the step again from its start
// with more sub-steps leaves the strain the larger count gives, with no
// jump (Doc/model.md, "The default cloth solver"). Strain grows with the
// square of the sub-step (Doc/model.md, "Cloth sub-steps"), so half as
// many again takes a step from the bound to under half of it.
//
// On the device: the check runs after every sub-step, inside the sub-step
// loop (Backend/DeviceLoop.h), and acts after the last; a redo sets the
// clock back to the loop's start with the new count, so the loop goes on
// without a host wait. The sub-steps' first kernel restores the step's
// start (ClothSolve.cpp, the restart in "cloth.substep.predict").
#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/ClothSystem.h"
#include "Cloth/SubstepClock.h"

namespace soak {

// Redos a step takes at the most: the count grows by half each time.
constexpr int kStrainRedoAttempts = 3;

// The count a redo takes from n: half as many again, one more at least,
// within `most`.
SOAK_INLINE int strainRedoSubsteps(int n, int most) {
  const int raised = n + (n / 2 > 1 ? n / 2 : 1);
  return raised < most ? raised : most;
}

// The strain rule's state after a redo to `substeps`: the redo is a raise
// (AdaptiveSubsteps.h, strainRaised), so the steps after it keep the count
// and a probe it undoes doubles the wait for the next.
SOAK_INLINE StrainSubsteps strainRedone(StrainSubsteps s, int substeps) {
  if (s.substeps < substeps) s.substeps = substeps;
  s.leftBy = substeps;
  return strainRaised(s);
}

struct StrainRedoCheck {
  const ClothEdge* edges = nullptr;  // the strain rule's edges (ClothSystem::strainEdges)
  const float* rest = nullptr;
  int edgeCount = 0;
  float bound = 0.f;  // clothStrainRedo x clothStrainTarget
  int most = 0;       // the strain rule's most sub-steps
  bool stretchOnly = false;  // clothStrainStretchOnly: as the strain rule, stretch alone
};

// After a sub-step: where it was the step's last, counts the edges whose
// strain at the cloth's x* (edgeStrain, AdaptiveSubsteps.h) passes the
// bound, and redoes the step where more than 1 % do, up to kStrainRedoAttempts times and within
// `most` sub-steps. Queues two kernels; the clock's redo fields are reset
// for the next step by chooseClothSubsteps.
void checkStrainRedo(Device d, ParticleView p, const int* vertexSlot, StrainRedoCheck check, SubstepClock* clock);

}  // namespace soak
