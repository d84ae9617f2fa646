#pragma once
// buildPairLists: counts, places and fills PairLists (PairLists.h) from a
// candidate walk in rounds. `candidates` is a copyable functor with
// `template <class F> void operator()(int i, const Lanes& lanes, F&& f) const`
// that walks item i's candidates in the grid's order, in rounds as
// forEachCandidateInRounds does, calling f(keep, j) in every round on every
// lane: keep tells whether the lane's candidate j belongs in the list. It
// runs twice (count, fill) and must decide the same both times. The fill
// ranks each round's kept candidates by lane (a ballot), so the list keeps
// the grid's order whatever the group's width.
//
// With minLanes > 0 the builder gives each item a group of at least that
// many lanes (Base/Lanes.h; more where fewer than a million threads would
// run), with 0 one thread. The cloth's lists take 4 (14.4k items in the
// paper scenes: one thread each left most of the GPU idle). The fluid's
// take 1: groups only where there are few particles; at 1M and more, 4
// lanes made their build slower (Doc/performance.md).
#include "Backend/ForEach.h"
#include "Neighbours/PairLists.h"

namespace soak {

namespace detail {
template <class Candidates>
struct CountPairs {
  Candidates candidates;
  int* count;
  SOAK_INLINE void operator()(int i, const Lanes& lanes) const {
    int c = 0;
    candidates(i, lanes, [&](bool keep, int) { c += keep ? 1 : 0; });
    c = laneSum(lanes, c);
    if (lanes.leader()) count[i] = c;
  }
};
template <class Candidates>
struct FillPairs {
  Candidates candidates;
  PairLists::Fill t;
  SOAK_INLINE void operator()(int i, const Lanes& lanes) const {
    int k = t.start[i];
    if (k + t.count[i] > t.capacity) {  // no room: the passes walk the grid
      if (lanes.leader()) *t.overflow = 1;
      return;
    }
    candidates(i, lanes, [&](bool keep, int j) {
      const unsigned votes = laneBallot(lanes, keep);
      if (keep) t.index[k + lanesBefore(lanes, votes)] = j;
      k += voteCount(votes);
    });
  }
};
}  // namespace detail

template <class Candidates>
void buildPairLists(Device d, PairLists& lists, int n, bool sizeExactly, Candidates candidates, int minLanes,
                    const char* countName, const char* fillName) {
  // One lane per item runs as one thread: the group's code (ballots, sums)
  // in the kernel cost the fluid's build at 1M about 5 % (fluid.solve 11.1 ->
  // 11.8 ms on the H100).
  const bool lanes = minLanes > 0 && lanesFor(n, minLanes) > 1;
  const detail::CountPairs<Candidates> count{candidates, lists.countsFor(n)};
  if (lanes)
    forEachLanes(d, n, SOAK_LAMBDA(int i, Lanes l) { count(i, l); }, countName, minLanes);
  else
    forEach(d, n, SOAK_LAMBDA(int i) { count(i, Lanes{}); }, countName);
  lists.placeLists(sizeExactly);
  const detail::FillPairs<Candidates> fill{candidates, lists.fill()};
  if (lanes)
    forEachLanes(d, n, SOAK_LAMBDA(int i, Lanes l) { fill(i, l); }, fillName, minLanes);
  else
    forEach(d, n, SOAK_LAMBDA(int i) { fill(i, Lanes{}); }, fillName);
}

}  // namespace soak
