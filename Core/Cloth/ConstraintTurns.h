#pragma once
// The turns of a coloured constraint solve (Base/Turns.h): for every
// constraint and each of its vertices, how many constraints take that vertex
// before it in one iteration (the tethers' phase, then the stretch colours,
// then the bend colours, as Cloth/ClothSolve.cpp runs them). A vertex's
// counter runs through the iterations: in iteration r a constraint with turn
// t on v waits for counter >= r * kTurnsPerRound + t; the vertex's last
// constraint of the iteration moves the counter to the next iteration's
// first turn.
//
// A turn is 16 bits: the turn within the iteration (bits 0-14) and whether
// the constraint is the vertex's last in the iteration (bit 15).
#include <cstdint>
#include <vector>

#include "Base/HostDevice.h"

namespace soak {

constexpr int kTurnsPerRound = 1 << 15;
// Counters are ints: iterations of one solve at most this many.
constexpr int kMaxTurnRounds = (1 << 30) / kTurnsPerRound;

// Where the counter must be before the constraint with 16-bit turn `t` may
// take the vertex in iteration `round`.
SOAK_INLINE int turnInRound(std::uint32_t t, int round) { return round * kTurnsPerRound + int(t & 0x7fffu); }
// Where it leaves the counter.
SOAK_INLINE int turnAfter(std::uint32_t t, int round) {
  return (t & 0x8000u) ? (round + 1) * kTurnsPerRound : turnInRound(t, round) + 1;
}

// Two 16-bit turns in a word: vertex a in the low half, b in the high.
SOAK_INLINE std::uint32_t lowTurn(std::uint32_t word) { return word & 0xffffu; }
SOAK_INLINE std::uint32_t highTurn(std::uint32_t word) { return word >> 16; }

// A bend's four turns, one 8-byte load.
struct alignas(8) BendTurns {
  std::uint32_t word[2];  // v[0] | v[1] << 16, v[2] | v[3] << 16
};

struct ConstraintTurns {
  std::vector<std::uint32_t> tether;  // per vertex: its tether's turn (0 where it has none)
  std::vector<std::uint32_t> edge;    // per edge, in colour order: a | b << 16
  std::vector<BendTurns> bend;        // per bend, in colour order
  bool fits = true;                   // false: a vertex has more constraints than kTurnsPerRound
};

// `tethered[v]`: vertex v has a tether (the solve's first phase). The edges'
// (2 per edge) and bends' (4 per bend) vertices in colour order, as the
// solve runs them.
ConstraintTurns constraintTurns(int vertexCount, const std::vector<char>& tethered,
                                const std::vector<int>& edgeVertices, const std::vector<int>& bendVertices);

}  // namespace soak
