#pragma once
// The cloth sub-steps' clock: which sub-step of how many, in device memory,
// so that the step's count can be chosen on the device and its sub-steps
// run as a device loop (Backend/DeviceLoop.h) with no host wait
// (Doc/design.md, "Step graphs"). Every kernel of a sub-step reads its
// length and place from here rather than taking them by value.
#include "Base/HostDevice.h"
#include "Cloth/AdaptiveSubsteps.h"

namespace soak {

struct SubstepClock {
  // substep and substeps side by side: a host that queues the sub-steps
  // reads both back in one copy after a redo's check (Backend/DeviceLoop.h).
  int substep = 0;         // the sub-step under way, from 0
  int substeps = 0;        // the step's count (0 before the first step)
  long long taken = 0;     // sub-steps of all steps so far
  int contactSubsteps = 0; // of the step's sub-steps, how many run the contact passes (contactsIn)
  int contactsDue = 1;     // 1 while the sub-step under way runs them: the contact kernels' onlyIf
  StrainSubsteps strain;   // what the strain asks for (AdaptiveSubsteps.h): state a checkpoint keeps
  int attempt = 0;         // the step's redos so far (StrainRedo.h); 0 while its first sub-steps run
  int redoPast = 0;        // edges past the redo's bound, counted after the step's last sub-step
};

// What a kernel needs to read the clock: where it is, the step's dt, and
// the fewest sub-steps (Simulation.clothSubsteps), over which the bends'
// stiffness is configured.
struct SubstepTime {
  SubstepClock* clock = nullptr;  // written only by the loop that runs the sub-steps
  float dt = 0.f;
  int fewest = 1;
  SOAK_INLINE int count() const { return clock->substeps; }
  SOAK_INLINE int index() const { return clock->substep; }
  SOAK_INLINE float h() const { return dt / float(clock->substeps); }
  // The fraction of the step done at the end of the sub-step under way.
  SOAK_INLINE float along() const { return float(clock->substep + 1) / float(clock->substeps); }
  SOAK_INLINE bool last() const { return clock->substep + 1 == clock->substeps; }
  // How long before the step's end the sub-step under way ends: where it
  // sees a scripted collider (colliderBefore); 0 in the last sub-step.
  SOAK_INLINE float colliderLag() const { return last() ? 0.f : dt * (1.f - along()); }
  // ClothView's bends take 1 - (1 - k')^e a sub-step, e = fewest / count, so
  // that a step bends alike whatever its count.
  SOAK_INLINE float bendExponent() const { return float(fewest) / float(clock->substeps); }
  // Whether sub-step k runs the cloth's contact passes: contactSubsteps of
  // the count, spread evenly, the last always; every one where
  // contactSubsteps is 0 or not below the count (AdaptiveSubsteps.h,
  // contactSubstepsForTravel).
  SOAK_INLINE bool contactsIn(int k) const {
    const int c = clock->contactSubsteps, n = clock->substeps;
    if (c <= 0 || c >= n) return true;
    return (k + 1) * c / n > k * c / n;
  }
};

}  // namespace soak
