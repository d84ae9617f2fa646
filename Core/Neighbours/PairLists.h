#pragma once
// Neighbour lists built once per step from the grid (the fluid's and the
// wet cloth's): for item i, the slots of its candidates that pass the
// builder's test, in the grid's visiting order.
//
// The lists' buffer is sized from the host only on maintenance steps (a
// read-back waits for the device); between them an item whose entries would
// run past it gets no list, and its passes walk the grid instead (the same
// candidates, in the same order, and more: a list of infinite reach). The
// headroom left when sizing doubles, up to as many entries again, whenever
// an item went without a list since the last sizing. The sizing decides
// which items walk the grid, so checkpoints keep it (PairListSizing).
//
// Rooms (keyed lists): where every item has a key that stays its own from
// step to step (a cloth particle's vertex), a sizing also gives each key a
// room in the buffer, its count then plus a little, and the builds between
// sizings fill each item's list straight into its key's room, in one pass,
// without counting first (the count pass and its scan were a third of the
// cloth lists' time in the paper scenes). After the rooms lies a spill area
// of the headroom's size: an item that outgrew its room walks its
// candidates again into room claimed there (by an atomic: the place of its
// list may change from run to run, not the list), and one that finds the
// spill full gets no list until the next sizing, as above. The fluid's
// lists key each slot by itself with rooms of one size (the mean count of
// the items with pairs, plus a quarter): a slot holds another particle
// after each sort, but about as many pairs, and the lists stay in the
// grid's order, side by side.
#include <vector>

#include "Backend/Buffer.h"
#include "Base/HostDevice.h"

namespace soak {

struct PairListView {
  const int* start = nullptr;  // first entry of item i
  const int* count = nullptr;  // entries of item i
  const int* index = nullptr;  // the listed slots
  int capacity = 0;            // entries the index buffer holds
  SOAK_INLINE bool listed(int i) const { return start[i] + count[i] <= capacity; }
};

// What decides which items get a list: kept by checkpoints, so that a
// resumed run gives the same bits as an uninterrupted one.
struct PairListSizing {
  int capacity = 0;         // entries the index buffer holds
  int headroomEighths = 1;  // room made beyond the pairs counted when sizing
  bool overflowed = false;  // an item went without a list since the last sizing
  std::vector<int> roomStart;  // keyed lists: key k's room is [roomStart[k], roomStart[k + 1]); else empty
};

class PairLists {
 public:
  explicit PairLists(Device d)
      : start_(d), count_(d), index_(d), overflow_(d), roomCount_(d), roomStart_(d), spillUsed_(d), device_(d) {}

  // Building (PairListsBuild.h does the three steps): per-item counts to be
  // written for n items; then the offsets (with `sizeExactly`, a maintenance
  // step, the total is read back and the buffer sized with headroom); then
  // the fill's target.
  int* countsFor(int n);
  void placeLists(bool sizeExactly);
  struct Fill {
    const int* start;
    const int* count;
    int* index;
    int capacity;
    int* overflow;  // set to 1 by an item without room
  };
  Fill fill();

  // Keyed lists (PairListsBuild.h): whether rooms for `keys` keys are
  // placed (else the build counts and sizes them first); on a sizing: the
  // per-key room sizes to be written (zeroed, keys + 1 of them), then the
  // rooms' placing (reads the total back; the spill after them takes the
  // headroom's eighths of it). Before each fill the spill is emptied. The
  // fill then writes each item's list into its key's room or the spill.
  bool hasRooms(int keys) const { return roomKeys_ == keys && keys > 0; }
  int roomKeys() const { return roomKeys_; }  // keys with a room placed (0: none)
  // The sum of the n counts just written, and of the first n room sizes
  // (downloads: sizing steps only).
  int countTotal(int n);
  int roomCountTotal(int n);
  int* roomCountsFor(int keys);
  void placeRooms(int spillAtLeast = 0);  // the spill: the headroom's eighths of the rooms, and spillAtLeast
  void clearSpill();
  struct RoomFill {
    const int* roomStart;
    int* start;
    int* count;
    int* index;
    int capacity;
    int* overflow;
    int spillStart, spill;  // the spill area: [spillStart, spillStart + spill)
    int* spillUsed;         // entries of it claimed in this build
    int keys;               // keys with a room
  };
  RoomFill roomFill();

  PairListView view() const;
  // The index buffer's size and headroom (a download).
  PairListSizing sizing() const;
  void setSizing(const PairListSizing& s);
  // Items of the last build without a list (a download; for tests).
  int itemsWithoutList() const;
  // The lists as the host sees them (downloads; for tests): item i's
  // entries, or none without a list.
  std::vector<std::vector<int>> download() const;
  std::size_t bytes() const;

 private:
  void growHeadroomIfOverflowed();

  Buffer<int> start_, count_, index_;
  Buffer<int> overflow_;  // 1 once an item went without a list
  Buffer<int> roomCount_, roomStart_;  // keyed lists: per key (+ 1)
  Buffer<int> spillUsed_;              // keyed lists: entries of the spill claimed
  int roomKeys_ = 0;                   // keys with a room placed (0: none)
  int roomsEnd_ = 0;                   // keyed lists: the rooms' end, where the spill starts
  int items_ = 0;
  int headroomEighths_ = 1;
  Device device_;
};

}  // namespace soak
