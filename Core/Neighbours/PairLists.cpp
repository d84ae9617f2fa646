#include "Neighbours/PairLists.h"

#include "Backend/Primitives.h"

namespace soak {

int* PairLists::countsFor(int n) {
  items_ = n;
  start_.resize(std::size_t(n));
  count_.resize(std::size_t(n));
  if (overflow_.size() == 0) {
    overflow_.resize(1);
    overflow_.fillZero();
  }
  return count_.data();
}

// Items went without a list since the last sizing: the pairs grow faster
// than the headroom, so double it (up to as many again as now).
void PairLists::growHeadroomIfOverflowed() {
  if (overflow_.download()[0] != 0) {
    headroomEighths_ = headroomEighths_ < 8 ? 2 * headroomEighths_ : 8;
    overflow_.fillZero();
  }
}

void PairLists::placeLists(bool sizeExactly) {
  roomKeys_ = 0;
  if (!sizeExactly) {
    exclusiveScanAsync(device_, count_.data(), start_.data(), items_);
    return;
  }
  const int total = exclusiveScan(device_, count_.data(), start_.data(), items_);
  growHeadroomIfOverflowed();
  // Room for more than now (1/8 at first), so that lists growing until the
  // next sizing still fit; the old contents are not needed.
  const std::size_t entries = std::size_t(total > 0 ? total : 1);
  if (entries > index_.size()) {
    index_ = Buffer<int>(device_);
    index_.resize(entries + entries * std::size_t(headroomEighths_) / 8);
  }
}

int* PairLists::roomCountsFor(int keys) {
  growHeadroomIfOverflowed();
  roomKeys_ = 0;
  roomCount_.resize(std::size_t(keys) + 1);
  roomCount_.fillZero();
  roomStart_.resize(std::size_t(keys) + 1);
  return roomCount_.data();
}

void PairLists::placeRooms(int spillAtLeast) {
  const int keys = int(roomCount_.size()) - 1;
  // Over keys + 1 counts, the last 0: roomStart[keys] is the total.
  const int total = exclusiveScan(device_, roomCount_.data(), roomStart_.data(), keys + 1);
  // The rooms, then the spill (the headroom's eighths of them); the buffer
  // is made again where it is too small or more than twice too large.
  const std::size_t entries = std::size_t(total) + std::size_t(total) * std::size_t(headroomEighths_) / 8 +
                              std::size_t(spillAtLeast) + 1;
  if (entries > index_.size() || 2 * entries < index_.size()) {
    index_ = Buffer<int>(device_);
    index_.resize(entries);
  }
  roomKeys_ = keys;
  roomsEnd_ = total;
}

int PairLists::countTotal(int n) { return exclusiveScan(device_, count_.data(), start_.data(), n); }
int PairLists::roomCountTotal(int n) { return exclusiveScan(device_, roomCount_.data(), roomStart_.data(), n); }

void PairLists::clearSpill() {
  if (spillUsed_.size() == 0) spillUsed_.resize(1);
  spillUsed_.fillZero();
}

PairLists::RoomFill PairLists::roomFill() {
  const int capacity = int(index_.size());
  return {roomStart_.data(), start_.data(), count_.data(), index_.data(), capacity, overflow_.data(),
          roomsEnd_, capacity - roomsEnd_, spillUsed_.data(), roomKeys_};
}

PairLists::Fill PairLists::fill() {
  return {start_.data(), count_.data(), index_.data(), int(index_.size()), overflow_.data()};
}

PairListView PairLists::view() const {
  return {start_.data(), count_.data(), index_.data(), int(index_.size())};
}

PairListSizing PairLists::sizing() const {
  PairListSizing s;
  s.capacity = int(index_.size());
  s.headroomEighths = headroomEighths_;
  s.overflowed = overflow_.size() > 0 && overflow_.download()[0] != 0;
  if (roomKeys_ > 0) s.roomStart = roomStart_.download();
  return s;
}

void PairLists::setSizing(const PairListSizing& s) {
  index_ = Buffer<int>(device_);
  index_.resize(std::size_t(s.capacity > 0 ? s.capacity : 0));
  headroomEighths_ = s.headroomEighths;
  overflow_.resize(1);
  overflow_.upload({s.overflowed ? 1 : 0});
  roomKeys_ = 0;
  // Rooms past the buffer are dropped: the next build counts and places the
  // lists as without rooms (a checkpoint's sizing never has them,
  // getListSizing refuses it).
  if (s.roomStart.size() > 1 && s.roomStart.back() <= s.capacity) {
    roomStart_.upload(s.roomStart);
    roomCount_.resize(s.roomStart.size());
    roomKeys_ = int(s.roomStart.size()) - 1;
    roomsEnd_ = s.roomStart.back();
  }
}

int PairLists::itemsWithoutList() const {
  const std::vector<int> start = start_.download(), count = count_.download();
  const int capacity = int(index_.size());
  int without = 0;
  for (std::size_t i = 0; i < start.size() && i < std::size_t(items_); ++i)
    without += start[i] + count[i] > capacity ? 1 : 0;
  return without;
}

std::vector<std::vector<int>> PairLists::download() const {
  const std::vector<int> start = start_.download(), count = count_.download(), index = index_.download();
  std::vector<std::vector<int>> lists(static_cast<std::size_t>(items_));
  for (std::size_t i = 0; i < lists.size(); ++i)
    if (start[i] + count[i] <= int(index.size()))
      lists[i].assign(index.begin() + start[i], index.begin() + start[i] + count[i]);
  return lists;
}

std::size_t PairLists::bytes() const {
  return (start_.size() + count_.size() + index_.size() + overflow_.size()) * sizeof(int);
}

}  // namespace soak
