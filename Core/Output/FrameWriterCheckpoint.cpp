// FrameWriter's part of a checkpoint: what the output folder held at the
// checkpoint's frame, so that a resumed run continues the same files.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "Checkpoint/StateStream.h"
#include "Output/FrameWriter.h"

namespace soak {

namespace {
void putEntries(StateWriter& out, const PvdCollection& c) {
  out.put<std::uint64_t>(c.entries().size());
  for (const auto& e : c.entries()) {
    out.put<double>(e.first);
    out.putString(e.second);
  }
}
std::vector<PvdCollection::Entry> getEntries(StateReader& in) {
  const std::uint64_t n = in.get<std::uint64_t>();
  std::vector<PvdCollection::Entry> entries;
  for (std::uint64_t k = 0; k < n; ++k) {
    const double t = in.get<double>();
    entries.emplace_back(t, in.getString());
  }
  return entries;
}
}  // namespace

void FrameWriter::saveState(StateWriter& out) const {
  out.putString("output");
  out.put<std::int32_t>(frames_);
  putEntries(out, water_);
  out.put<std::int32_t>(static_cast<std::int32_t>(cloth_.size()));
  for (const auto& c : cloth_) {
    out.putString(c->path().substr(dir_.size() + 1));
    putEntries(out, *c);
  }
  out.put<std::int32_t>(surface_ ? 1 : 0);
  if (surface_) putEntries(out, *surface_);
  out.put<std::int32_t>(static_cast<std::int32_t>(statsColumns_.size()));
  for (const std::string& c : statsColumns_) out.putString(c);
  out.put<std::uint64_t>(statsBytes_);
}

void FrameWriter::loadState(StateReader& in) {
  in.expect("output");
  frames_ = in.get<std::int32_t>();
  water_.restore(getEntries(in));
  const int cloths = in.get<std::int32_t>();
  cloth_.clear();
  for (int k = 0; k < cloths; ++k) {
    const std::string name = in.getString();
    if (name.find('/') != std::string::npos || name.find("..") != std::string::npos) in.fail("bad collection name");
    cloth_.push_back(std::make_unique<PvdCollection>(dir_ + "/" + name));
    cloth_.back()->restore(getEntries(in));
  }
  surface_.reset();
  if (in.get<std::int32_t>() != 0) {
    surface_ = std::make_unique<PvdCollection>(dir_ + "/water_surface.pvd");
    surface_->restore(getEntries(in));
  }
  const int columns = in.get<std::int32_t>();
  statsColumns_.clear();
  for (int k = 0; k < columns; ++k) statsColumns_.push_back(in.getString());
  statsBytes_ = in.get<std::uint64_t>();

  // stats.csv: keep the rows of the saved frames, append from there.
  const std::string stats = dir_ + "/stats.csv";
  struct stat st {};
  if (::stat(stats.c_str(), &st) != 0 || std::uint64_t(st.st_size) < statsBytes_)
    throw InputError("cannot resume: '" + stats + "' is missing or shorter than at the checkpoint");
  if (::truncate(stats.c_str(), static_cast<off_t>(statsBytes_)) != 0)
    throw InputError("cannot resume: cannot cut '" + stats + "' back: " + std::strerror(errno));
  stats_.close();
  stats_.open(stats, std::ios::out | std::ios::app);
  if (!stats_) throw InputError("cannot resume: cannot append to '" + stats + "'");
}

}  // namespace soak
