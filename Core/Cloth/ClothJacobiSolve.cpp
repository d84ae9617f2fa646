// The Jacobi-Chebyshev cloth solve (ClothJacobi.h): one parallel phase per
// iteration over the vertices of the chebyshev cloths, all phases of a
// sub-step in one cooperative launch on the GPU (Backend/ForEachPhased.h).
#include <algorithm>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "Backend/ForEachPhased.h"
#include "Base/ReadOnly.h"
#include "Base/Unroll.h"
#include "Cloth/ClothSolve.h"

namespace soak {

namespace {
// A vertex's tethers: their lengths and their pins' positions, loaded
// before they are needed so that the loads overlap other work.
// Every index into the arrays is a constant (the loops unroll), so they
// stay in registers instead of the thread's local memory.
struct VertexTethers {
  int count = 0;
  float length[kTethers];
  Vec3 anchor[kTethers];
  SOAK_INLINE VertexTethers(const ClothView& c, int v, const Float4* at) {
    const TetherPins pins = loadReadOnly(reinterpret_cast<const TetherPins*>(c.tetherPin) + v);
    if (pins.pin[0] < 0) return;
    const TetherLengths lengths = loadReadOnly(reinterpret_cast<const TetherLengths*>(c.tetherLength) + v);
    SOAK_UNROLL
    for (int t = 0; t < kTethers; ++t) {
      const bool has = pins.pin[t] >= 0 && count == t;
      length[t] = lengths.length[t];
      anchor[t] = has ? at[pins.pin[t]].xyz() : Vec3(0.f, 0.f, 0.f);
      if (has) count = t + 1;
    }
  }
  // x limited by every tether.
  SOAK_INLINE Vec3 clamp(Vec3 x) const {
    SOAK_UNROLL
    for (int t = 0; t < kTethers; ++t)
      if (t < count) x = clampToTether(x, anchor[t], length[t]);
    return x;
  }
};

// The stages of one sub-step's solve, in order: gather the predicted
// positions, the bend pass (if any bends), the iterations, scatter back.
// Stage s writes iterate buffer s % 2 and reads buffer (s - 1) % 2, so an
// iteration overwrites x_{k-1}, the one Chebyshev's step reads (each vertex
// only its own).
enum JacobiStage : int { kGather, kBend, kIterate, kScatter };

// The stages [base, base + count) of one launch: what each is and, for an
// iteration, its number (from 1) and Chebyshev weight.
struct JacobiLaunch {
  int base = 0;
  JacobiStage kind[kMaxPhases] = {};
  float omega[kMaxPhases] = {};
  short iteration[kMaxPhases] = {};
};

// The springs a lane sums, kSpringChunk at a time: the chunk's springs are
// loaded, then their other ends, then summed in the list's order (the same
// sums), so that a lane's loads overlap instead of each waiting for the one
// before it.
constexpr int kSpringChunk = 4;

#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
// The CPU's spring sum, four springs to an SSE register: the springs'
// records are loaded two to a register and split into their other ends
// and rest lengths, the other ends' positions loaded and transposed, and
// each term of addSpringTerm computed in all four lanes and masked where
// it does not pull (a slack limit, coincident ends). The four lanes' sums
// are added at the end, then the last springs one by one: a fixed order,
// so a run's bits do not depend on anything but its inputs. The README
// example's step on one thread: 252-269 ms with the scalar loop, 212-222
// with this one (Doc/performance.md, "The default's cost").
SOAK_INLINE void addSpringsSse(JacobiSums& sums, const ClothView& c, const Float4* x, int v, Vec3 xi, float stiffness) {
  const __m128 xiX = _mm_set1_ps(xi.x), xiY = _mm_set1_ps(xi.y), xiZ = _mm_set1_ps(xi.z);
  const __m128 tiny = _mm_set1_ps(1e-24f), k = _mm_set1_ps(stiffness), zero = _mm_setzero_ps();
  const __m128 signBit = _mm_set1_ps(-0.f);
  __m128 sumX = _mm_setzero_ps(), sumY = _mm_setzero_ps(), sumZ = _mm_setzero_ps(), sumW = _mm_setzero_ps();
  int e = c.springStart[v];
  const int end = c.springStart[v + 1];
  for (; e + 4 <= end; e += 4) {
    // Springs e, e+1 and e+2, e+3: (other, rest) pairs.
    const float* sp = reinterpret_cast<const float*>(c.springs + e);
    const __m128 first = _mm_loadu_ps(sp), second = _mm_loadu_ps(sp + 4);  // 8-byte aligned
    const __m128 other = _mm_shuffle_ps(first, second, _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 signedRest = _mm_shuffle_ps(first, second, _MM_SHUFFLE(3, 1, 3, 1));
    alignas(16) int index[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(index), _mm_castps_si128(other));
    __m128 px = _mm_load_ps(&x[index[0]].x), py = _mm_load_ps(&x[index[1]].x), pz = _mm_load_ps(&x[index[2]].x),
           pw = _mm_load_ps(&x[index[3]].x);
    _MM_TRANSPOSE4_PS(px, py, pz, pw);
    const __m128 rest = _mm_andnot_ps(signBit, signedRest);
    const __m128 isUnilateral = _mm_cmplt_ps(signedRest, zero);
    const __m128 dx = _mm_sub_ps(xiX, px), dy = _mm_sub_ps(xiY, py), dz = _mm_sub_ps(xiZ, pz);
    const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    const __m128 slack = _mm_and_ps(isUnilateral, _mm_cmple_ps(len2, _mm_mul_ps(rest, rest)));
    const __m128 pulls = _mm_andnot_ps(slack, _mm_cmpge_ps(len2, tiny));
    const __m128 scale = _mm_and_ps(pulls, _mm_div_ps(rest, _mm_sqrt_ps(len2)));
    const __m128 w = _mm_and_ps(pulls, k);
    sumX = _mm_add_ps(sumX, _mm_mul_ps(_mm_add_ps(px, _mm_mul_ps(dx, scale)), w));
    sumY = _mm_add_ps(sumY, _mm_mul_ps(_mm_add_ps(py, _mm_mul_ps(dy, scale)), w));
    sumZ = _mm_add_ps(sumZ, _mm_mul_ps(_mm_add_ps(pz, _mm_mul_ps(dz, scale)), w));
    sumW = _mm_add_ps(sumW, w);
  }
  alignas(16) float lane[4][4];
  _mm_store_ps(lane[0], sumX);
  _mm_store_ps(lane[1], sumY);
  _mm_store_ps(lane[2], sumZ);
  _mm_store_ps(lane[3], sumW);
  sums.weighted += Vec3((lane[0][0] + lane[0][1]) + (lane[0][2] + lane[0][3]),
                        (lane[1][0] + lane[1][1]) + (lane[1][2] + lane[1][3]),
                        (lane[2][0] + lane[2][1]) + (lane[2][2] + lane[2][3]));
  sums.weight += (lane[3][0] + lane[3][1]) + (lane[3][2] + lane[3][3]);
  for (; e < end; ++e) {
    const JacobiSpring s = c.springs[e];
    addSpringTerm(sums, xi, x[s.other].xyz(), s, stiffness);
  }
}
#endif

// The vertex's springs, each of weight `stiffness` (the cloth's).
SOAK_INLINE void addSprings(JacobiSums& sums, const ClothView& c, const Float4* x, int v, Vec3 xi, float stiffness,
                            const Lanes& l) {
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
  (void)l;  // one lane a vertex on the CPU
  addSpringsSse(sums, c, x, v, xi, stiffness);
#else
  for (int e = c.springStart[v] + l.index, end = c.springStart[v + 1]; e < end; e += kSpringChunk * l.size) {
    JacobiSpring sp[kSpringChunk];
    Vec3 other[kSpringChunk];
    SOAK_UNROLL
    for (int q = 0; q < kSpringChunk; ++q)
      if (e + q * l.size < end) sp[q] = loadReadOnly(c.springs + e + q * l.size);
    SOAK_UNROLL
    for (int q = 0; q < kSpringChunk; ++q)
      if (e + q * l.size < end) other[q] = x[sp[q].other].xyz();
    SOAK_UNROLL
    for (int q = 0; q < kSpringChunk; ++q)
      if (e + q * l.size < end) addSpringTerm(sums, xi, other[q], sp[q], stiffness);
  }
#endif
}

// Lanes per vertex: a vertex's spring list (edges and stretch limits, about
// 30 on a large sheet) is split over them. 4 is measured fastest on the
// H100 (cloth.solve fig6b 3.30 / 3.16 / 3.69 ms at 2 / 4 / 8 lanes,
// Doc/performance.md).
constexpr int kJacobiLanes = 4;
}  // namespace

void solveClothJacobi(Device d, ParticleView p, ClothView c, int iterations, SubstepTime t, ChebyshevSchedule chebyshev,
                      const Collider* colliders, int colliderCount, float collisionRadiusScale,
                      const Float4* substepStart) {
  const int n = c.jacobiVertexCount;
  if (n == 0 || iterations <= 0) return;
  std::vector<JacobiStage> kinds{kGather};
  if (c.anyJacobiBends) kinds.push_back(kBend);
  for (int it = 0; it < iterations; ++it) kinds.push_back(kIterate);
  kinds.push_back(kScatter);
  const int stages = int(kinds.size());
  Float4* even = c.vertexScratch;  // iterate buffers 0 and 1
  Float4* odd = c.jacobiPrevious;
  Float4* target = c.jacobiTarget;
  float omega = 1.f;
  int iteration = 0;
  // Stages go to launches of at most kMaxPhases phases (one for up to
  // kMaxPhases - 3 iterations).
  for (int base = 0; base < stages; base += kMaxPhases) {
    JacobiLaunch launch;
    launch.base = base;
    PhaseList phases;
    for (int s = base; s < std::min(stages, base + kMaxPhases); ++s) {
      const int local = s - base;
      launch.kind[local] = kinds[s];
      if (kinds[s] == kIterate) {
        omega = chebyshev.weight(++iteration, omega);
        launch.omega[local] = omega;
        launch.iteration[local] = short(iteration);
      }
      phases.add(local * n, (local + 1) * n);
    }
    forEachPhasedLanes(d, phases, kJacobiLanes, SOAK_LAMBDA(int k, Lanes l) {
      const int local = k / n, s = launch.base + local;
      const int v = c.jacobiVertices[k - local * n];
      Float4* out = (s & 1) ? odd : even;
      const Float4* x = (s & 1) ? even : odd;
      switch (launch.kind[local]) {
        case kGather: {
          if (!l.leader()) return;
          const int slot = c.vertexSlot[v];
          const Float4 y = p.predicted[slot];
          out[v] = y;
          target[v] = Float4(y.xyz(), collisionRadiusScale * p.radius[slot]);
          return;
        }
        case kBend: {
          // One averaged Jacobi pass of Eq. 9's projections.
          const Float4 xv = x[v];
          Vec3 sum(0.f, 0.f, 0.f);
          int count = 0;
          if (xv.w != 0.f)
            for (int r = c.bendRefStart[v] + l.index, end = c.bendRefStart[v + 1]; r < end; r += l.size) {
              const JacobiBendRef ref = loadReadOnly(c.bendRefs + r);
              const ClothBend bend = loadReadOnly(c.jacobiBends + ref.bend);
              Vec3 q[4];
              float w[4];
              for (int a = 0; a < 4; ++a) {
                const Float4 xa = x[bend.v[a]];
                q[a] = xa.xyz();
                w[a] = xa.w;
              }
              float kPrime = loadReadOnly(c.jacobiBendStiffness + ref.bend);
              const float exponent = t.bendExponent();
              if (exponent != 1.f) kPrime = 1.f - powf(1.f - kPrime, exponent);
              addBendCorrection(sum, count, q, w, ref.role, loadReadOnly(c.jacobiBendRest + ref.bend),
                                kPrime * bendScaleOf(c.bendScale, bend.v));
            }
          sum = laneSum(l, sum);
          count = laneSum(l, count);
          if (l.leader()) out[v] = count > 0 ? Float4(xv.xyz() + sum * (1.f / float(count)), xv.w) : xv;
          return;
        }
        case kIterate: {
          const Float4 xv = x[v];
          if (xv.w == 0.f) {  // pinned or attached: stays where it was put
            if (l.leader()) out[v] = xv;
            return;
          }
          // Everything the leader needs after the lane sum, loaded first:
          // the loop's loads then hide their latency.
          const Vec3 xi = xv.xyz();
          const Float4 yr = target[v];
          const Vec3 y = yr.xyz();
          const Vec3 older = out[v].xyz();  // x_{k-1}
          const VertexTethers tethers(c, v, x);
          const float stiffness = loadReadOnly(c.springStiffness + v);
          JacobiSums sums;
          addSprings(sums, c, x, v, xi, stiffness, l);
          sums.weighted = laneSum(l, sums.weighted);
          sums.weight = laneSum(l, sums.weight);
          if (!l.leader()) return;
          addColliderTerms(sums, xi, yr.w, colliders, colliderCount, t.colliderLag());
          const float h = t.h();
          Vec3 xhat = jacobiMinimum(sums, y, 1.f / (h * h) / xv.w);
          // Tethers as hard limits on the Jacobi step's result: their pins
          // do not move during the solve, so the projection needs no other
          // vertex's new position and costs no phase; it carries the pins'
          // hold across the sheet in one iteration (Kim et al. 2012).
          xhat = tethers.clamp(xhat);
          // Chebyshev: x_{k+1} = omega (xhat - x_{k-1}) + x_{k-1}.
          const Vec3 before = launch.iteration[local] == 1 ? xhat : older;
          out[v] = Float4(before + (xhat - before) * launch.omega[local], xv.w);
          return;
        }
        case kScatter: {
          if (!l.leader()) return;
          const Float4 xv = x[v];
          const int slot = c.vertexSlot[v];
          if (xv.w == 0.f) {
            p.predicted[slot] = xv;
            return;
          }
          Vec3 q = VertexTethers(c, v, x).clamp(xv.xyz());
          // A sub-step's projection out of the colliders, with friction
          // over the sub-step's motion (here rather than a launch of its own).
          if (substepStart)
            q = projectOutOfColliders(colliders, colliderCount, substepStart[slot].xyz(), q, target[v].w, t.h(),
                                      c.frictionScale ? c.frictionScale[v] : 1.f, t.colliderLag());
          p.predicted[slot] = Float4(q, xv.w);
          return;
        }
      }
    }, "cloth.jacobi");
  }
}

}  // namespace soak
