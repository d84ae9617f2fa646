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
  SOAK_INLINE VertexTethers(const ClothView& c, int v, const Float4* at)
      : VertexTethers(c, v, at, loadReadOnly(reinterpret_cast<const TetherPins*>(c.tetherPin) + v)) {}
  SOAK_INLINE VertexTethers(const ClothView& c, int v, const Float4* at, const TetherPins& pins) {
    if (pins.pin[0] < 0) return;
    const TetherLengths lengths = loadReadOnly(reinterpret_cast<const TetherLengths*>(c.tetherLength) + v);
    // A vertex's tethers come first in its kTethers (pin -1 after the last).
    bool has = true;
    SOAK_UNROLL
    for (int t = 0; t < kTethers; ++t) {
      has = has && pins.pin[t] >= 0;
      length[t] = lengths.length[t];
      anchor[t] = has ? at[pins.pin[t]].xyz() : Vec3(0.f, 0.f, 0.f);
      count += has ? 1 : 0;
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

// What a lane keeps of its vertex through a launch's phases where the
// launch holds one vertex per lane group (jacobiResidentKernel): the
// springs it sums (the first kCachedSprings of them), the tethers' pins
// and the stiffness, loaded once instead of once a phase. A phase's loads
// are then the positions alone, and none waits for another (Doc/performance.md,
// "The Jacobi solve's vertex kept in registers").
constexpr int kCachedSprings = 8;
struct LaneCache {
  int springs = 0;  // cached, at most kCachedSprings
  JacobiSpring spring[kCachedSprings];
  TetherPins pins;
  float stiffness = 0.f;
};

// The lane's springs are springStart[v] + l.index + j l.size, j = 0, 1, ...,
// summed in that order by addSprings (chunk by chunk); the cache holds the
// first kCachedSprings of them.
SOAK_INLINE LaneCache loadLaneCache(const ClothView& c, int v, const Lanes& l) {
  LaneCache k;
  const int first = c.springStart[v] + l.index, end = c.springStart[v + 1];
  SOAK_UNROLL
  for (int j = 0; j < kCachedSprings; ++j)
    if (first + j * l.size < end) {
      k.spring[j] = loadReadOnly(c.springs + first + j * l.size);
      k.springs = j + 1;
    }
  k.pins = loadReadOnly(reinterpret_cast<const TetherPins*>(c.tetherPin) + v);
  k.stiffness = loadReadOnly(c.springStiffness + v);
  return k;
}

// addSprings with the lane's springs from its cache: the same terms in the
// same order, so the same sums.
SOAK_INLINE void addCachedSprings(JacobiSums& sums, const ClothView& c, const Float4* x, int v, Vec3 xi,
                                  const Lanes& l, const LaneCache& k) {
  SOAK_UNROLL
  for (int j0 = 0; j0 < kCachedSprings; j0 += kSpringChunk) {
    Vec3 other[kSpringChunk];
    SOAK_UNROLL
    for (int q = 0; q < kSpringChunk; ++q)
      if (j0 + q < k.springs) other[q] = x[k.spring[j0 + q].other].xyz();
    SOAK_UNROLL
    for (int q = 0; q < kSpringChunk; ++q)
      if (j0 + q < k.springs) addSpringTerm(sums, xi, other[q], k.spring[j0 + q], k.stiffness);
  }
  for (int e = c.springStart[v] + l.index + kCachedSprings * l.size, end = c.springStart[v + 1]; e < end;
       e += l.size) {
    const JacobiSpring sp = loadReadOnly(c.springs + e);
    addSpringTerm(sums, xi, x[sp.other].xyz(), sp, k.stiffness);
  }
}

// Lanes per vertex: a vertex's spring list (edges and stretch limits, about
// 30 on a large sheet) is split over them. 4 is measured fastest on the
// H100 (cloth.solve fig6b 3.30 / 3.16 / 3.69 ms at 2 / 4 / 8 lanes,
// Doc/performance.md).
constexpr int kJacobiLanes = 4;
// What the stages read and write.
struct JacobiArgs {
  ParticleView p;
  ClothView c;
  SubstepTime t;
  const Collider* colliders = nullptr;
  int colliderCount = 0;
  float collisionRadiusScale = 1.f;
  const Float4* substepStart = nullptr;
  Float4* even = nullptr;    // iterate buffer 0
  Float4* odd = nullptr;     // iterate buffer 1
  Float4* target = nullptr;  // the predicted positions and collision radii
};

// Stage `local` of a launch for vertex v, on the lanes of l; with Cached,
// the lane's springs and pins from `*cache` (jacobiResidentKernel), else
// from memory (`cache` unused).
template <bool Cached>
SOAK_INLINE void jacobiStage(const JacobiArgs& a, const JacobiLaunch& launch, int local, int v, const Lanes& l,
                             const LaneCache* cache) {
  const ParticleView& p = a.p;
  const ClothView& c = a.c;
  const SubstepTime& t = a.t;
  Float4* target = a.target;
  const int s = launch.base + local;
  Float4* out = (s & 1) ? a.odd : a.even;
  const Float4* x = (s & 1) ? a.even : a.odd;
  switch (launch.kind[local]) {
    case kGather: {
      if (!l.leader()) return;
      const int slot = c.vertexSlot[v];
      const Float4 y = p.predicted[slot];
      out[v] = y;
      target[v] = Float4(y.xyz(), a.collisionRadiusScale * p.radius[slot]);
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
          for (int corner = 0; corner < 4; ++corner) {
            const Float4 xa = x[bend.v[corner]];
            q[corner] = xa.xyz();
            w[corner] = xa.w;
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
      const VertexTethers tethers = Cached ? VertexTethers(c, v, x, cache->pins) : VertexTethers(c, v, x);
      JacobiSums sums;
      if (Cached)
        addCachedSprings(sums, c, x, v, xi, l, *cache);
      else
        addSprings(sums, c, x, v, xi, loadReadOnly(c.springStiffness + v), l);
      sums.weighted = laneSum(l, sums.weighted);
      sums.weight = laneSum(l, sums.weight);
      if (!l.leader()) return;
      addColliderTerms(sums, xi, yr.w, a.colliders, a.colliderCount, t.colliderLag());
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
      if (a.substepStart)
        q = projectOutOfColliders(a.colliders, a.colliderCount, a.substepStart[slot].xyz(), q, target[v].w, t.h(),
                                  c.frictionScale ? c.frictionScale[v] : 1.f, t.colliderLag());
      p.predicted[slot] = Float4(q, xv.w);
      return;
    }
  }
}

#if defined(__CUDACC__)
// The launch's phases with one vertex per lane group throughout: each
// lane loads its LaneCache once, then runs every phase on its own vertex,
// with the grid barrier between phases (Backend/ForEachPhased.h). Two
// blocks an SM must fit (fig9b's 14.4k vertices take 225 blocks of 256 on
// the H100's 132 SMs), hence at most 128 registers a thread.
__global__ void __launch_bounds__(kForEachBlockSize, 2)
    jacobiResidentKernel(JacobiArgs a, JacobiLaunch launch, int phases, int vertices, int barrierSlot) {
  unsigned* barrier = gPhaseBarrier + barrierSlot;
  const int t = blockIdx.x * blockDim.x + threadIdx.x;
  Lanes l;
  l.size = kJacobiLanes;
  l.index = t & (kJacobiLanes - 1);
  l.mask = ((1u << kJacobiLanes) - 1u) << ((threadIdx.x & 31u) & ~unsigned(kJacobiLanes - 1));
  const int group = t / kJacobiLanes;
  const bool has = group < vertices;
  const int v = has ? a.c.jacobiVertices[group] : 0;
  LaneCache cache;
  if (has) cache = loadLaneCache(a.c, v, l);
  for (int local = 0; local < phases; ++local) {
    if (has) jacobiStage<true>(a, launch, local, v, l, &cache);
    phaseBarrier(barrier);
  }
}

// Runs the launch as jacobiResidentKernel where its lane groups fit on the
// GPU at once; false where they do not (or cooperative launches are
// refused), for the caller's general path.
bool launchResident(const JacobiArgs& a, const JacobiLaunch& launch, int phases, int vertices, Device d) {
  static int maxBlocks = coResidentBlocks(jacobiResidentKernel);
  const long long threads = static_cast<long long>(vertices) * kJacobiLanes;
  if (threads > static_cast<long long>(maxBlocks) * kForEachBlockSize) return false;
  JacobiArgs args = a;
  JacobiLaunch list = launch;
  int count = phases, n = vertices, slot = phaseBarrierSlot();
  void* params[] = {&args, &list, &count, &n, &slot};
  return launchCooperative(jacobiResidentKernel, threads, maxBlocks, params, d, "cloth.jacobi");
}
#endif
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
  JacobiArgs args;
  args.p = p;
  args.c = c;
  args.t = t;
  args.colliders = colliders;
  args.colliderCount = colliderCount;
  args.collisionRadiusScale = collisionRadiusScale;
  args.substepStart = substepStart;
  args.even = c.vertexScratch;
  args.odd = c.jacobiPrevious;
  args.target = c.jacobiTarget;
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
#if defined(__CUDACC__)
    if (d == Device::Cuda && launchResident(args, launch, phases.count, n, d)) continue;
#endif
    forEachPhasedLanes(d, phases, kJacobiLanes, SOAK_LAMBDA(int k, Lanes l) {
      const int local = k / n;
      jacobiStage<false>(args, launch, local, c.jacobiVertices[k - local * n], l, nullptr);
    }, "cloth.jacobi");
  }
}

}  // namespace soak
