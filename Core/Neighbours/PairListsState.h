#pragma once
// A PairListSizing in a checkpoint (the fluid's lists in the simulation's
// section, the wet cloth's in its module's).
#include <cstdint>
#include <string>

#include "Checkpoint/StateStream.h"
#include "Neighbours/PairLists.h"

namespace soak {

inline void putListSizing(StateWriter& out, const PairListSizing& s) {
  out.put<std::int32_t>(s.capacity);
  out.put<std::int32_t>(s.headroomEighths);
  out.put<std::int32_t>(s.overflowed ? 1 : 0);
  out.putVector(s.roomStart);
}

// `what` names the lists in the refusal of a sizing out of range.
// `maxCapacity`: the most pairs the lists can need (keys x the candidates of
// 27 full grid cells), so that a forged sizing cannot allocate without end.
inline PairListSizing getListSizing(StateReader& in, const std::string& what, double maxCapacity) {
  PairListSizing s;
  s.capacity = in.get<std::int32_t>();
  s.headroomEighths = in.get<std::int32_t>();
  s.overflowed = in.get<std::int32_t>() != 0;
  s.roomStart = in.getVector<int>();
  if (s.capacity < 0 || double(s.capacity) > maxCapacity || s.headroomEighths < 1 || s.headroomEighths > 8)
    in.fail(what + " sizing out of range");
  // Rooms: from 0, never shrinking, within the buffer.
  for (std::size_t k = 0; k < s.roomStart.size(); ++k) {
    const int prev = k == 0 ? 0 : s.roomStart[k - 1];
    if (s.roomStart[k] < prev || s.roomStart[k] > s.capacity || (k == 0 && s.roomStart[0] != 0))
      in.fail(what + " rooms out of range");
  }
  return s;
}

}  // namespace soak
