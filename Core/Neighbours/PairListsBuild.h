#pragma once
// buildPairLists: counts, places and fills PairLists (PairLists.h) from a
// candidate walk. `candidates` is a copyable functor with
// `template <class F> void operator()(int i, F&& f) const` calling f(j) for
// every slot j that belongs in item i's list, in the order the passes would
// visit them; it runs twice (count, fill) and must list the same both times.
#include "Backend/ForEach.h"
#include "Neighbours/PairLists.h"

namespace soak {

template <class Candidates>
void buildPairLists(Device d, PairLists& lists, int n, bool sizeExactly, Candidates candidates, const char* countName,
                    const char* fillName) {
  int* count = lists.countsFor(n);
  forEach(d, n, SOAK_LAMBDA(int i) {
    int c = 0;
    candidates(i, [&](int) { ++c; });
    count[i] = c;
  }, countName);
  lists.placeLists(sizeExactly);
  const PairLists::Fill t = lists.fill();
  forEach(d, n, SOAK_LAMBDA(int i) {
    int k = t.start[i];
    if (k + t.count[i] > t.capacity) {  // no room: the passes walk the grid
      *t.overflow = 1;
      return;
    }
    candidates(i, [&](int j) { t.index[k++] = j; });
  }, fillName);
}

}  // namespace soak
