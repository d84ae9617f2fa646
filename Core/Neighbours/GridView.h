#pragma once
// The neighbourhood grid as solver functions see it.
//
// Space is cut into cubic cells of edge `cellSize` (the largest support
// radius). A cell is identified by its integer coordinates wrapped modulo
// 1024 per axis and packed into 30 bits (the cell key). Cells are hashed into
// 2^bucketBits buckets by the low bits of the key's Morton code, which keeps
// neighbouring cells in nearby buckets (locality) and uses memory in
// proportion to the particle count, never to the extent of the domain.
// Particles are sorted by bucket; bucket b holds slots [range[b].start, range[b].end).
// A bucket may hold several cells (hash collisions), so a candidate is
// accepted only if its own cell key equals the visited cell's key: each
// particle is then visited at most once per query, because the 27 cells
// around any cell have 27 distinct keys.
//
// A grid may also index a subset of the particles (the cloth's, Cloth/
// ClothGrid): its entries are then that subset's slots in increasing order,
// `slot` maps an entry to its particle slot, and the queries below call f
// with particle slots either way. The subset keeps the full grid's order, so
// a query visits the subset's particles in the same order as the full grid.
#include <cmath>
#include <cstdint>

#include "Base/HostDevice.h"
#include "Base/Lanes.h"
#include "Base/Vec3.h"

namespace soak {

// Bucket b's entries are [start, end); {0, 0} for an empty bucket. One
// 8-byte load per visited cell (most cells a query visits hold nothing).
struct alignas(8) BucketRange {
  std::uint32_t start, end;
};

struct GridView {
  float invCellSize = 1.f;
  std::uint32_t bucketMask = 0;
  const BucketRange* range = nullptr;      // per bucket
  const std::uint32_t* cellKey = nullptr;  // per entry (for the full grid: per particle slot)
  const std::uint32_t* slotKey = nullptr;  // per particle slot: its cell key (query centres)
  const int* slot = nullptr;               // per entry: its particle slot; null: the entry is the slot
  // Optional (a subset's grid, Cloth/ClothGrid): one bit per bucket, set for
  // the bucket of every cell within one cell (the 27 around) of a cell that
  // holds an entry. A clear bit for cell c's bucket proves that none of the
  // 27 cells around c holds an entry, so a query there can stop at once
  // (hash collisions only set more bits). Null: every query walks its cells.
  const std::uint32_t* nearBits = nullptr;
};

SOAK_INLINE int slotOfEntry(const GridView& g, std::uint32_t j) {
  return g.slot ? g.slot[j] : static_cast<int>(j);
}

constexpr std::uint32_t kCellWrap = 1024u;

SOAK_INLINE int cellCoordinate(float x, float invCellSize) {
  float c = floorf(x * invCellSize);
  // Clamp before converting so far-away points stay defined behaviour.
  c = minf(maxf(c, -1.0e9f), 1.0e9f);
  return static_cast<int>(c);
}

SOAK_INLINE std::uint32_t packCellKey(int ix, int iy, int iz) {
  return (static_cast<std::uint32_t>(ix) & 1023u) | ((static_cast<std::uint32_t>(iy) & 1023u) << 10) |
         ((static_cast<std::uint32_t>(iz) & 1023u) << 20);
}

SOAK_INLINE std::uint32_t cellKeyOf(Vec3 p, float invCellSize) {
  return packCellKey(cellCoordinate(p.x, invCellSize), cellCoordinate(p.y, invCellSize),
                     cellCoordinate(p.z, invCellSize));
}

// Spreads the low 10 bits of v to every third bit.
SOAK_INLINE std::uint32_t spreadBits3(std::uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

SOAK_INLINE std::uint32_t bucketOfKey(std::uint32_t key, std::uint32_t bucketMask) {
  std::uint32_t morton = spreadBits3(key) | (spreadBits3(key >> 10) << 1) | (spreadBits3(key >> 20) << 2);
  return morton & bucketMask;
}

// Whether some entry may lie in the 27 cells around the cell of bucket b
// (always true for a grid without nearBits).
SOAK_INLINE bool mayHoldNear(const GridView& g, std::uint32_t b) {
  return !g.nearBits || ((g.nearBits[b >> 5] >> (b & 31u)) & 1u);
}

// Calls f(j) for the slots j of the cell with key `key` in bucket `b` (the
// key's bucket, bucketOfKey) that are this lane's: of the bucket's entries,
// every lanes.size-th from lanes.index (all of them, in order, for one lane).
template <class F>
SOAK_INLINE void forEachInBucket(const GridView& g, std::uint32_t key, std::uint32_t b, const Lanes& lanes, F&& f) {
  const BucketRange r = g.range[b];
  for (std::uint32_t j = r.start + std::uint32_t(lanes.index); j < r.end; j += std::uint32_t(lanes.size))
    if (g.cellKey[j] == key) f(slotOfEntry(g, j));
}

// The Morton code of cell (x, y, z) is spread(x) | spread(y) << 1 |
// spread(z) << 2 (bucketOfKey); a query over a block of cells spreads each
// axis' coordinates once instead of three per cell.
SOAK_INLINE std::uint32_t spreadAxis(int coordinate, int axis) {
  return spreadBits3(static_cast<std::uint32_t>(coordinate)) << axis;
}

// spread[k][d]: axis k's spread of coordinate c[k] + d - 1, for the 27 cells
// around c (cell (c + d) has bucket spread[0][dx] | spread[1][dy] |
// spread[2][dz], masked).
SOAK_INLINE void spreadAround(const int c[3], std::uint32_t spread[3][3]) {
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) spread[k][d] = spreadAxis(c[k] + d - 1, k);
}

// Calls f(key, bucket) for the 27 cells around the cell with key
// `centerKey`, in the order every query visits them; none where the grid's
// near bits show that no entry lies in them.
template <class F>
SOAK_INLINE void forEachCellAround(const GridView& g, std::uint32_t centerKey, F&& f) {
  const int c[3] = {int(centerKey & 1023u), int((centerKey >> 10) & 1023u), int((centerKey >> 20) & 1023u)};
  std::uint32_t spread[3][3];
  spreadAround(c, spread);
  if (!mayHoldNear(g, (spread[0][1] | spread[1][1] | spread[2][1]) & g.bucketMask)) return;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        f(packCellKey(c[0] + dx, c[1] + dy, c[2] + dz),
          (spread[0][dx + 1] | spread[1][dy + 1] | spread[2][dz + 1]) & g.bucketMask);
}

// Up to lanes.size cells' buckets laid end to end, for a group of lanes
// (Base/Lanes.h): each lane loads one cell's bucket range, and a scan of
// their sizes numbers the entries of all of them in the cells' order. The
// group then takes lanes.size entries a round across cells, where a walk
// cell by cell spends a round (a chain of dependent loads) on each cell,
// however few entries it holds. The coupling's path boxes (27 or more
// cells of the cloth's grid, most of them empty or nearly) walk so
// (TriangleCoupling.cpp). The 27-cell walks of the water's grid do not:
// there the cells are full, and finding an entry's cell costs each round
// more than the rounds it saves (Doc/performance.md, "Cells in batches").
struct CellBatch {
  std::uint32_t key = 0, first = 0;  // this lane's cell: its key, its bucket's first entry
  int before = 0;                    // entries of the batch's cells before this lane's
  int total = 0;                     // entries of all its cells
  // `has`: whether this lane holds a cell (key, bucket). Every lane of the
  // group must construct it.
  SOAK_INLINE CellBatch(const GridView& g, const Lanes& lanes, bool has, std::uint32_t cellKey,
                        std::uint32_t bucket) {
    int size = 0;
    if (has) {
      const BucketRange r = g.range[bucket];
      key = cellKey;
      first = r.start;
      size = int(r.end - r.start);
    }
    const int through = laneInclusiveScan(lanes, size);
    before = through - size;
    total = laneFrom(lanes, through, lanes.size - 1);
  }
  // Entry `at` of the sequence (meaningful for at < total): its index in
  // the grid's entries, and in `cellKey` its cell's key. Every lane of the
  // group must call it.
  SOAK_INLINE std::uint32_t entry(const Lanes& lanes, int at, std::uint32_t& cellKey) const {
    // The cell holding entry `at`: the last lane whose cell starts at or
    // before it (the starts do not decrease; an empty cell starts where the
    // next one does, and the lanes past the last cell start at total).
    int owner = 0;
    for (int step = lanes.size / 2; step > 0; step /= 2)
      if (laneFrom(lanes, before, owner + step) <= at) owner += step;
    cellKey = laneFrom(lanes, key, owner);
    return laneFrom(lanes, first, owner) + std::uint32_t(at - laneFrom(lanes, before, owner));
  }
};

// Calls f(j) once for every slot j whose cell is one of the 27 cells around
// the cell with key `centerKey` (with `lanes`: this lane's share of them).
// The caller applies its own distance test.
template <class F>
SOAK_INLINE void forEachCandidate(const GridView& g, std::uint32_t centerKey, const Lanes& lanes, F&& f) {
  forEachCellAround(g, centerKey, [&](std::uint32_t key, std::uint32_t b) { forEachInBucket(g, key, b, lanes, f); });
}

// The same in rounds, for passes that must keep the grid's order with
// several lanes (building lists): in each round the group's lanes take
// adjacent entries of a cell's bucket, and every lane calls f(valid, j) in
// every round, valid telling whether it holds a candidate j of the cell.
// All lanes of a group make the same calls, so f may vote (laneBallot).
template <class F>
SOAK_INLINE void forEachCandidateInRounds(const GridView& g, std::uint32_t centerKey, const Lanes& lanes, F&& f) {
  forEachCellAround(g, centerKey, [&](std::uint32_t key, std::uint32_t b) {
    const BucketRange r = g.range[b];
    for (std::uint32_t base = r.start; base < r.end; base += std::uint32_t(lanes.size)) {
      const std::uint32_t k = base + std::uint32_t(lanes.index);
      const bool valid = k < r.end && g.cellKey[k] == key;
      f(valid, valid ? slotOfEntry(g, k) : -1);
    }
  });
}

template <class F>
SOAK_INLINE void forEachCandidate(const GridView& g, std::uint32_t centerKey, F&& f) {
  forEachCandidate(g, centerKey, Lanes{}, f);
}

// Calls f(key, first, end) for each cell of the 27 around x's cell that
// comes within `reach` cell sizes of x, in the order of forEachCandidate:
// the cell's bucket holds entries [first, end), those whose cellKey is key
// belonging to the cell. For reach 1 (a search radius of one cell) about 21
// of the 27 cells remain on average. The cell test keeps a margin of 1e-3
// cell sizes, well above the rounding of x * invCellSize, so no pair within
// reach is lost.
template <class F>
SOAK_INLINE void forEachCellWithin(const GridView& g, Vec3 x, float reach, F&& f) {
  const float xs[3] = {x.x, x.y, x.z};
  int c[3];
  float below[3], above[3];  // squared distance to the cell below and above, per axis (cell sizes)
  for (int k = 0; k < 3; ++k) {
    c[k] = cellCoordinate(xs[k], g.invCellSize);
    const float f0 = minf(maxf(xs[k] * g.invCellSize - float(c[k]), 0.f), 1.f);
    below[k] = f0 * f0;
    above[k] = (1.f - f0) * (1.f - f0);
  }
  const float limit = (reach + 1e-3f) * (reach + 1e-3f);
  std::uint32_t spread[3][3];
  spreadAround(c, spread);
  for (int dz = -1; dz <= 1; ++dz) {
    const float ez = dz < 0 ? below[2] : (dz > 0 ? above[2] : 0.f);
    for (int dy = -1; dy <= 1; ++dy) {
      const float ey = ez + (dy < 0 ? below[1] : (dy > 0 ? above[1] : 0.f));
      if (ey >= limit) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        const float ex = ey + (dx < 0 ? below[0] : (dx > 0 ? above[0] : 0.f));
        if (ex >= limit) continue;
        const std::uint32_t key = packCellKey(c[0] + dx, c[1] + dy, c[2] + dz);
        const std::uint32_t b = (spread[0][dx + 1] | spread[1][dy + 1] | spread[2][dz + 1]) & g.bucketMask;
        const BucketRange r = g.range[b];
        f(key, r.start, r.end);
      }
    }
  }
}

// Whether some entry may lie in the cells a..b (per axis, inclusive): tests
// the near bits of cells a+1, a+4, ... per axis, each of which covers
// itself and the cells either side.
SOAK_INLINE bool mayHoldInBox(const GridView& g, const int a[3], const int b[3]) {
  if (!g.nearBits) return true;
  for (int z = a[2] + 1; z - 1 <= b[2]; z += 3) {
    const std::uint32_t sz = spreadAxis(z, 2);
    for (int y = a[1] + 1; y - 1 <= b[1]; y += 3) {
      const std::uint32_t syz = sz | spreadAxis(y, 1);
      for (int x = a[0] + 1; x - 1 <= b[0]; x += 3)
        if (mayHoldNear(g, (syz | spreadAxis(x, 0)) & g.bucketMask)) return true;
    }
  }
  return false;
}

// A box query visits the cells that overlap the box [lo, hi], at most
// kMaxBoxCells per axis (centred on the box beyond that).
constexpr int kMaxBoxCells = 8;

// The cells of a box query, numbered x fastest, then y, then z: the order
// forEachCellInBox visits them. No cells where the near bits prove the box
// empty (mayHoldInBox).
struct CellBox {
  int a[3], b[3];
  int nx = 0, nxy = 0, count = 0;
  SOAK_INLINE CellBox(const GridView& g, Vec3 lo, Vec3 hi)
      : a{cellCoordinate(lo.x, g.invCellSize), cellCoordinate(lo.y, g.invCellSize),
          cellCoordinate(lo.z, g.invCellSize)},
        b{cellCoordinate(hi.x, g.invCellSize), cellCoordinate(hi.y, g.invCellSize),
          cellCoordinate(hi.z, g.invCellSize)} {
    for (int k = 0; k < 3; ++k)
      if (b[k] - a[k] >= kMaxBoxCells) {
        const int mid = a[k] + (b[k] - a[k]) / 2;
        a[k] = mid - kMaxBoxCells / 2;
        b[k] = a[k] + kMaxBoxCells - 1;
      }
    if (!mayHoldInBox(g, a, b)) return;
    nx = b[0] - a[0] + 1;
    nxy = nx * (b[1] - a[1] + 1);
    count = nxy * (b[2] - a[2] + 1);
  }
  // Cell i's key; its bucket in `bucket`.
  SOAK_INLINE std::uint32_t cell(const GridView& g, int i, std::uint32_t& bucket) const {
    const int z = a[2] + i / nxy, y = a[1] + (i % nxy) / nx, x = a[0] + i % nx;
    bucket = (spreadAxis(z, 2) | spreadAxis(y, 1) | spreadAxis(x, 0)) & g.bucketMask;
    return packCellKey(x, y, z);
  }
};

// Calls f(key, bucket) for every cell of the box, in the order
// forEachCandidateInBox visits them.
template <class F>
SOAK_INLINE void forEachCellInBox(const GridView& g, Vec3 lo, Vec3 hi, F&& f) {
  const CellBox box(g, lo, hi);
  if (box.count == 0) return;
  const int* a = box.a;
  const int* b = box.b;
  for (int z = a[2]; z <= b[2]; ++z) {
    const std::uint32_t sz = spreadAxis(z, 2);
    for (int y = a[1]; y <= b[1]; ++y) {
      const std::uint32_t syz = sz | spreadAxis(y, 1);
      for (int x = a[0]; x <= b[0]; ++x) f(packCellKey(x, y, z), (syz | spreadAxis(x, 0)) & g.bucketMask);
    }
  }
}

// Calls f(j) once for every slot j whose cell overlaps the box. Cheaper
// than the 27 cells when the box is smaller than a cell, and it follows a
// moving particle's whole path when it is longer.
template <class F>
SOAK_INLINE void forEachCandidateInBox(const GridView& g, Vec3 lo, Vec3 hi, const Lanes& lanes, F&& f) {
  forEachCellInBox(g, lo, hi, [&](std::uint32_t key, std::uint32_t b) { forEachInBucket(g, key, b, lanes, f); });
}

template <class F>
SOAK_INLINE void forEachCandidateInBox(const GridView& g, Vec3 lo, Vec3 hi, F&& f) {
  forEachCandidateInBox(g, lo, hi, Lanes{}, f);
}

// Same, around an arbitrary point.
template <class F>
SOAK_INLINE void forEachCandidateNear(const GridView& g, Vec3 p, F&& f) {
  forEachCandidate(g, cellKeyOf(p, g.invCellSize), static_cast<F&&>(f));
}

}  // namespace soak
