#include "Cloth/ClothSolve.h"

#include "Backend/DeviceLoop.h"
#include "Backend/ForEach.h"
#include "Backend/ForEachPhased.h"
#include "Base/ReadOnly.h"
#include "Physics/Collider.h"
#include "Physics/Integrate.h"

namespace soak {

void solveClothConstraints(Device d, ParticleView p, ClothView c, const std::vector<int>& stretchColours,
                           const std::vector<int>& bendColours, int iterations, SubstepTime t) {
  // One index space: tethers [0, V), then the stretch constraints [V, V + E),
  // then the bends; one phase for the tethers and one per colour, repeated
  // for every iteration (ForEachPhased.h: one launch on the GPU).
  const int vertices = c.vertexCount, edgeBase = vertices;
  const int bendBase = edgeBase + (stretchColours.empty() ? 0 : stretchColours.back());
  PhaseList phases;
  phases.repeat = iterations;
  bool fits = !c.anyTethers || phases.add(0, vertices);  // no phase where no vertex has a tether
  for (std::size_t col = 0; col + 1 < stretchColours.size(); ++col)
    fits = fits && phases.add(edgeBase + stretchColours[col], edgeBase + stretchColours[col + 1]);
  for (std::size_t col = 0; col + 1 < bendColours.size(); ++col)
    fits = fits && phases.add(bendBase + bendColours[col], bendBase + bendColours[col + 1]);
  if (!fits) throw std::logic_error("cloth solve: more constraint colours than kMaxPhases");
  if (phases.count == 0) return;  // every cloth is solved by the Jacobi solve
  // The solve works on a copy of the predicted positions in vertex order:
  // constraints name vertices, so each load is one indirection shorter than
  // through the particle slots, and neighbouring vertices share cache lines.
  Float4* x = c.vertexScratch;
  forEach(d, vertices, SOAK_LAMBDA(int v) { x[v] = p.predicted[c.vertexSlot[v]]; }, "cloth.constraints.gather");
  forEachPhased(d, phases, SOAK_LAMBDA(int k) {
    if (k < edgeBase) {
      // Tethers: unilateral, only the free vertex moves (its pins do not).
      // The pins, their lengths and positions are loaded before the
      // sequential projections, so the loads overlap.
      const int v = k;
      if (c.solvedByJacobi[v]) return;  // the Jacobi solve clamps its iterates to the tethers
      const TetherPins pins = loadReadOnly(reinterpret_cast<const TetherPins*>(c.tetherPin) + v);
      const Float4 xv = x[v];
      if (xv.w == 0.f || pins.pin[0] < 0) return;
      const TetherLengths lengths = loadReadOnly(reinterpret_cast<const TetherLengths*>(c.tetherLength) + v);
      Vec3 anchor[kTethers];
      for (int t = 0; t < kTethers; ++t)
        if (pins.pin[t] >= 0) anchor[t] = x[pins.pin[t]].xyz();
      Vec3 q = xv.xyz();
      for (int t = 0; t < kTethers; ++t) {
        if (pins.pin[t] < 0) break;
        const Vec3 dd = q - anchor[t];
        const float len = length(dd), maxLen = lengths.length[t];
        if (len > maxLen) q = anchor[t] + dd * (maxLen / len);
      }
      x[v] = Float4(q, xv.w);
    } else if (k < bendBase) {
      // Stretch (Eq. 8).
      const int e = k - edgeBase;
      const ClothEdge edge = loadReadOnly(c.edges + e);
      const Float4 xa = x[edge.a], xb = x[edge.b];
      Vec3 da, db;
      projectStretch(xa.xyz(), xa.w, xb.xyz(), xb.w, loadReadOnly(c.edgeRest + e), loadReadOnly(c.edgeStiffness + e), t.h(),
                     c.edgeLambda[e], da, db);
      x[edge.a] = Float4(xa.xyz() + da, xa.w);
      x[edge.b] = Float4(xb.xyz() + db, xb.w);
    } else {
      // Bending (Eq. 9).
      const int b = k - bendBase;
      const ClothBend bend = loadReadOnly(c.bends + b);
      Vec3 q[4], dx[4];
      float w[4];
      for (int a = 0; a < 4; ++a) {
        const Float4 xa = x[bend.v[a]];
        q[a] = xa.xyz();
        w[a] = xa.w;
      }
      const ConstraintStiffness k = scaledStiffness(loadReadOnly(c.bendStiffness + b), bendScaleOf(c.bendScale, bend.v));
      projectBend(q, w, loadReadOnly(c.bendRest + b), k, t.h(), c.bendLambda[b], dx);
      for (int a = 0; a < 4; ++a) x[bend.v[a]] = Float4(q[a] + dx[a], w[a]);
    }
  }, "cloth.constraints");
  forEach(d, vertices, SOAK_LAMBDA(int v) { p.predicted[c.vertexSlot[v]] = x[v]; }, "cloth.constraints.scatter");
}

namespace {
// The end of a sub-step for slot i: its velocity from the sub-step's motion,
// and its x* the next sub-step's start (pinned and attached vertices keep
// theirs). Run by the next sub-step's predict kernel, or by the finish
// kernel after the last, rather than as a launch of its own: each reads and
// writes only slot i.
SOAK_INLINE void endSubstep(const ParticleView& p, const ClothSubstepScratch& s, int i, float h) {
  const Float4 q = p.predicted[i];
  if (q.w == 0.f) return;
  s.velocity[i] = (q.xyz() - s.start[i].xyz()) * (1.f / h);
  s.start[i] = q;
}

// What one sub-step works on.
struct Substep {
  Device d;
  ParticleView p, substepView;
  ClothSystem* cloth;
  const Collider* colliders;
  int colliderCount;
  float collisionRadiusScale;
  Vec3 gravity;
  SubstepTime t;
  bool oneSubstep;
  int iterations;
  ChebyshevSchedule chebyshev;
  ClothSubstepScratch s;
  const ClothContactPasses* contacts;
};

// One sub-step. Its place and length are the clock's (SubstepClock.h), so
// that the sub-steps can run as a device loop.
void runSubstep(const Substep& a) {
  const Device d = a.d;
  const ParticleView p = a.p;
  const ClothView c = a.cloth->view();
  const ClothSubstepScratch s = a.s;
  const SubstepTime t = a.t;
  const Collider* colliders = a.colliders;
  const int colliderCount = a.colliderCount;
  const float collisionRadiusScale = a.collisionRadiusScale;
  const Vec3 gravity = a.gravity;
  const bool oneSubstep = a.oneSubstep;
  forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
    const int i = c.vertexSlot[v];
    const float h = t.h();
    if (v == 0) t.clock->contactsDue = t.contactsIn(t.index()) ? 1 : 0;  // read by later kernels only
    if (t.index() > 0) {
      endSubstep(p, s, i, h);  // the sub-step before this one ends here
      if (t.contactsIn(t.index() - 1)) s.contactStart[i] = s.start[i];
    } else if (t.clock->attempt > 0) {
      // A redo (StrainRedo.h): the step's sub-steps again from its start.
      s.start[i] = p.position[i];
      s.contactStart[i] = p.position[i];
      s.velocity[i] = s.firstVelocity[i];
    }
    const Float4 x = p.position[i];
    if (x.w == 0.f) {
      const int k = c.attachCollider[v];
      // Attached vertices follow their collider's path, reaching its end
      // point with the last sub-step; fixed pins stay.
      const Vec3 target = k >= 0 ? c.restPosition[v] + colliders[k].displacement : x.xyz();
      p.predicted[i] = Float4(t.last() ? target : x.xyz() + (target - x.xyz()) * t.along(), 0.f);
      return;
    }
    if (oneSubstep) return;
    const Vec3 vel = s.velocity[i] + gravity * h;
    s.velocity[i] = vel;
    p.predicted[i] = Float4(s.start[i].xyz() + vel * h, x.w);
  }, "cloth.substep.predict");
  if (!oneSubstep) a.contacts->separate(a.substepView);
  a.cloth->resetMultipliers();
  solveClothConstraints(d, p, c, a.cloth->edgeColourStart(), a.cloth->bendColourStart(), a.iterations, t);
  solveClothJacobi(d, p, c, a.iterations, t, a.chebyshev, colliders, colliderCount, collisionRadiusScale,
                   oneSubstep ? nullptr : s.start);
  if (oneSubstep) {
    // The paper's single pass projects every particle out of the
    // colliders here, the water too (which collide projects again).
    projectColliders(d, p, colliders, colliderCount, collisionRadiusScale, t.dt, c.frictionScale);
  } else if (c.jacobiVertexCount < c.vertexCount) {
    // The chebyshev cloths were projected by their solve's last phase.
    forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
      const int i = c.vertexSlot[v];
      const Float4 xp = p.predicted[i];
      if (xp.w == 0.f || c.solvedByJacobi[v]) return;
      const float r = collisionRadiusScale * p.radius[i];
      const float friction = c.frictionScale ? c.frictionScale[v] : 1.f;
      p.predicted[i] = Float4(
          projectOutOfColliders(colliders, colliderCount, s.start[i].xyz(), xp.xyz(), r, t.h(), friction,
                                t.colliderLag()),
          xp.w);
    }, "cloth.substep.colliders");
  }
  if (oneSubstep) a.contacts->separate(a.substepView);
  a.contacts->uncross(a.substepView);
}
}  // namespace

void substepCloth(Device d, ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
                  float collisionRadiusScale, Vec3 gravity, SubstepTime t, int knownSubsteps,
                  int iterations, ChebyshevSchedule chebyshev, ClothSubstepScratch s,
                  const ClothContactPasses& contacts, const SubstepCheck& check, float speedUpMargin) {
  const ClothView c = cloth.view();
  const float dt = t.dt;
  const bool oneSubstep = knownSubsteps == 1;
  // One sub-step is the step itself: its free motion is the predict stage's
  // x* as it stands, its start the step's, and it carries no velocity to a
  // next sub-step nor leaves one to fix.
  ParticleView substepView = p;  // position: the sub-step's start
  if (!oneSubstep) {
    // Non-cloth particles keep their place in the sub-step view.
    forEach(d, p.count, SOAK_LAMBDA(int i) {
      s.velocityFix[i] = Vec3(0.f, 0.f, 0.f);
      s.start[i] = p.position[i];
      s.contactStart[i] = p.position[i];
    }, "cloth.substep.clear");
    substepView.position = s.contactStart;
    // The step's free motion x* - x holds gravity over dt; take it out again
    // so that each sub-step adds its own h of it.
    forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
      const int i = c.vertexSlot[v];
      const Vec3 x = p.position[i].xyz();
      s.velocity[i] = (p.predicted[i].xyz() - x) * (1.f / dt) - gravity * dt;
      if (s.firstVelocity) s.firstVelocity[i] = s.velocity[i];
    }, "cloth.substep.begin");
  }
  const Substep one{d, p, substepView, &cloth, colliders, colliderCount, collisionRadiusScale, gravity, t,
                    oneSubstep, iterations, chebyshev, s, &contacts};
  auto substep = [&one, &check] {
    runSubstep(one);
    if (check) check();
  };
  if (oneSubstep) {
    runSubstep(one);
    return;
  }
  repeatOnDevice(d, &t.clock->substep, &t.clock->substeps, knownSubsteps, substep, bool(check));
  forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
    const int i = c.vertexSlot[v];
    endSubstep(p, s, i, t.h());
    const Float4 x = p.position[i];
    if (x.w == 0.f) return;
    const Vec3 mean = (p.predicted[i].xyz() - x.xyz()) * (1.f / dt);
    s.velocityFix[i] = clothEndVelocity(s.velocity[i], mean, speedUpMargin) - mean;
  }, "cloth.substep.finish");
}

}  // namespace soak
