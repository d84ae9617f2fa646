// wet.volume (before the core's coupling): each cloth particle's volume,
// saturation and wet weight, and the coupling stiffness the core's coupling
// stage reads (Eq. 10, Eq. 22, Section 4.4's excess water to the buffer).
// The cloth stays where its solve left it until wet.stick, so the
// cloth-cloth lists every wetting pass reads are built here, once a step.
#include "Cloth/ClothVolume.h"
#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetKernels.h"
#include "WetState.h"

namespace soak::wet {

void updatePorosity(Device d, ParticleView p, WetArrays a, const WetParams& w) {
  const float sEW = w.sEW, c = w.c, sT = w.sT, sMax = w.sMax;
  const bool wetWeight = w.wetWeight;
  const float bendSoftening = w.wetBendSoftening, wetFriction = w.wetFriction;
  const ClothListWalk lists{a.clothNeighbours};
  // One pass: the volume over the cloth's lists (which read positions, not
  // the masses and inverse masses this pass writes), then the rest.
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const float V = clothVolumeOf(p, i, v, lanes, lists);
    if (!lanes.leader()) return;
    a.volume[i] = V;
    float held = a.held[i];
    // Water above S^EW is excess (Section 4.4): it leaves the fabric for the buffer.
    const float limit = sEW * V / c;
    if (held > limit) {
      const float excess = held - limit;
      a.buffer[i] += excess;
      held -= excess;
      a.held[i] = held;
    }
    const float S = saturationOf(c, held, V);  // Eq. 10
    a.saturation[i] = S;
    const int vertex = p.id[i];
    // Eq. 22 (per vertex), from all the water the particle carries, held and
    // buffered: cloth with excess water is the wettest (Doc/model.md).
    const float wetness = minf(saturationOf(c, held + a.buffer[i], V), sMax);
    a.kappaCouple[vertex] = couplingStiffnessOf(wetness, sT, sMax);
    // Wet cloth bends easier and grips colliders harder (Doc/model.md,
    // "Wet stiffness and friction"), in proportion to S / S^MAX.
    if (a.bendScale) a.bendScale[vertex] = 1.f - bendSoftening * wetness / sMax;
    if (a.frictionScale) a.frictionScale[vertex] = 1.f + wetFriction * wetness / sMax;
    if (wetWeight) {
      // Held and buffered water weigh on the cloth particle (the paper's rho0* = (m_i + m_j) / m_i).
      const float m = a.dryMass[vertex] + held + a.buffer[i];
      p.mass[i] = m;
      if (p.position[i].w > 0.f) {
        p.position[i].w = 1.f / m;
        p.predicted[i].w = 1.f / m;
      }
    }
  }, "wet.porosity", kListLanes);
}

void runVolume(WetState& st, Simulation& s) {
  const ClothView c = s.cloth.view();
  st.clothNeighbours->build(s.particles.view(), s.cloth.grid(), clothSlots(c), c.thickness, s.sizeListsNow());
  if (!st.initialised) {
    st.initialised = true;
    if (st.w.initialSaturation > 0.f) st.setInitialSaturation(s);
  }
  updatePorosity(s.device(), s.particles.view(), st.arrays(s), st.w);
}

}  // namespace soak::wet
