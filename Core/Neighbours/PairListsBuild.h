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
#include <cstdint>

#include "Backend/ForEach.h"
#include "Base/Atomic.h"
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
// Keyed lists: item i's list goes into its key's room. An item whose
// candidates outgrow the room claims room for all of them in the spill
// area after the rooms and walks them again into it; where the spill is
// full too it gets no list (its start is put past the buffer, so listed()
// fails). Its count stays true either way, for the next sizing.
template <class Candidates, class KeyOf>
struct FillRooms {
  Candidates candidates;
  KeyOf keyOf;
  PairLists::RoomFill t;
  SOAK_INLINE void operator()(int i, const Lanes& lanes) const {
    // A key past the rooms (an item added since the sizing) has none.
    const int key = keyOf(i);
    const bool has = key >= 0 && key < t.keys;
    int first = has ? t.roomStart[key] : 0;
    const int room = has ? t.roomStart[key + 1] - first : 0;
    int k = 0;
    candidates(i, lanes, [&](bool keep, int j) {
      const unsigned votes = laneBallot(lanes, keep);
      const int at = k + lanesBefore(lanes, votes);
      if (keep && at < room) t.index[first + at] = j;
      k += voteCount(votes);
    });
    if (k > room) {
      // The leader claims k entries of the spill; the others add 0.
      const int claimed = laneSum(lanes, int(lanes.leader() ? atomicAddInt(t.spillUsed, k) : 0));
      first = claimed + k <= t.spill ? t.spillStart + claimed : t.capacity;
      if (first < t.capacity) {
        int m = 0;
        candidates(i, lanes, [&](bool keep, int j) {
          const unsigned votes = laneBallot(lanes, keep);
          if (keep) t.index[first + m + lanesBefore(lanes, votes)] = j;
          m += voteCount(votes);
        });
      } else if (lanes.leader()) {
        *t.overflow = 1;
      }
    }
    if (!lanes.leader()) return;
    t.count[i] = k;
    t.start[i] = first;
  }
};

// A key's room: its item's count now, plus a sixteenth, plus 2 (a
// particle's count moves by one or two as its neighbours cross the reach;
// those that grow more use the spill).
SOAK_INLINE int roomFor(int count) { return count + count / 16 + 2; }
}  // namespace detail

// Runs f(i, lanes) over n items, with lane groups as buildPairLists chose.
template <class F>
void forEachListItem(Device d, int n, bool lanes, int minLanes, F f, const char* name) {
  if (lanes)
    forEachLanes(d, n, SOAK_LAMBDA(int i, Lanes l) { f(i, l); }, name, minLanes);
  else
    forEach(d, n, SOAK_LAMBDA(int i) { f(i, Lanes{}); }, name);
}

template <class Candidates>
void buildPairLists(Device d, PairLists& lists, int n, bool sizeExactly, Candidates candidates, int minLanes,
                    const char* countName, const char* fillName);

// Keyed lists (PairLists.h, rooms): keyOf(i) gives item i's key in [0,
// keys), a different one for every item, the same from step to step. On a
// sizing the items are counted and each key's room placed (with
// uniformRooms, where keyOf(i) = i, rooms of one size); between sizings one
// pass fills the lists into the rooms, an item whose key is past them (added
// since the sizing) into the spill (without rooms, as after a sizing that had
// none, the unkeyed build, which waits for nothing either).
template <class Candidates, class KeyOf>
void buildKeyedPairLists(Device d, PairLists& lists, int n, bool sizeExactly, Candidates candidates, KeyOf keyOf,
                         int keys, int minLanes, const char* countName, const char* fillName,
                         bool uniformRooms = false) {
  if (!sizeExactly && !lists.hasRooms(keys)) {
    buildPairLists(d, lists, n, false, candidates, minLanes, countName, fillName);
    return;
  }
  const bool lanes = minLanes > 0 && lanesFor(n, minLanes) > 1;
  int* counts = lists.countsFor(n);
  if (sizeExactly) {
    const detail::CountPairs<Candidates> count{candidates, counts};
    forEachListItem(d, n, lanes, minLanes, count, countName);
    int* room = lists.roomCountsFor(keys);
    if (uniformRooms) {
      // Rooms of one size (keyOf(i) = i, and n <= keys at a sizing): the
      // mean count of the items with pairs, plus a quarter, plus 2, and a
      // spill that holds at least every list longer than that, so that a
      // sizing leaves no item without a list. The room sizes serve as
      // scratch for the two sums read back first.
      const int total = lists.countTotal(n);
      forEach(d, n, SOAK_LAMBDA(int i) { room[i] = counts[i] > 0 ? 1 : 0; }, "lists.listing");
      const int listing = lists.roomCountTotal(n);
      const int each = listing > 0 ? int((std::int64_t(total) * 5 / 4) / listing) + 2 : 2;
      forEach(d, n, SOAK_LAMBDA(int i) { room[i] = counts[i] > each ? counts[i] : 0; }, "lists.longer");
      const int longer = lists.roomCountTotal(n);
      forEach(d, keys, SOAK_LAMBDA(int k) { room[k] = each; }, "lists.rooms");
      lists.placeRooms(longer);
    } else {
      forEach(d, n, SOAK_LAMBDA(int i) { room[keyOf(i)] = detail::roomFor(counts[i]); }, "lists.rooms");
      lists.placeRooms();
    }
  }
  lists.clearSpill();
  const detail::FillRooms<Candidates, KeyOf> fill{candidates, keyOf, lists.roomFill()};
  forEachListItem(d, n, lanes, minLanes, fill, fillName);
}

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
