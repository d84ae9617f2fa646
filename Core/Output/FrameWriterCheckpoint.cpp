// FrameWriter's part of a checkpoint: what the output folder held at the
// checkpoint's frame, so that a resumed run continues the same files.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "Base/SafeName.h"
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

namespace {
bool isRegularFile(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}
}  // namespace

FrameWriter::ResumeState FrameWriter::readResumeState(StateReader& in) const {
  ResumeState s;
  in.expect("output");
  s.frames = in.get<std::int32_t>();
  if (s.frames < 0) in.fail("negative frame count");
  s.water = getEntries(in);
  const int cloths = in.get<std::int32_t>();
  if (cloths < 0) in.fail("negative cloth count");
  for (int k = 0; k < cloths; ++k) {
    const std::string name = in.getString();
    if (!isSafeFileName(name)) in.fail("bad collection name");
    s.cloth.emplace_back(name, getEntries(in));
  }
  s.surface = in.get<std::int32_t>() != 0;
  if (s.surface) s.surfaceEntries = getEntries(in);
  const int columns = in.get<std::int32_t>();
  if (columns < 0) in.fail("negative column count");
  for (int k = 0; k < columns; ++k) s.statsColumns.push_back(in.getString());
  s.statsBytes = in.get<std::uint64_t>();

  // The folder must still hold what the checkpoint lists.
  const std::string stats = dir_ + "/stats.csv";
  struct stat st {};
  if (::stat(stats.c_str(), &st) != 0 || std::uint64_t(st.st_size) < s.statsBytes)
    throw InputError("cannot resume: '" + stats + "' is missing or shorter than at the checkpoint");
  if (::access(stats.c_str(), W_OK) != 0)
    throw InputError("cannot resume: '" + stats + "' is not writable: " + std::strerror(errno));
  auto checkFrames = [&](const std::string& folder, const std::vector<PvdCollection::Entry>& entries) {
    for (const auto& e : entries) {
      if (e.second.find("..") != std::string::npos || (!e.second.empty() && e.second[0] == '/'))
        in.fail("a frame file name leaves the output folder");
      if (!isRegularFile(folder + "/" + e.second))
        throw InputError("cannot resume: frame file '" + folder + "/" + e.second +
                         "', listed at the checkpoint, is missing");
    }
  };
  checkFrames(dir_, s.water);
  for (const auto& c : s.cloth) checkFrames(dir_, c.second);
  checkFrames(dir_, s.surfaceEntries);
  return s;
}

void FrameWriter::resume(const ResumeState& s) {
  makeDirectories(dir_ + "/water");
  frames_ = s.frames;
  water_.restore(s.water);
  cloth_.clear();
  for (const auto& c : s.cloth) {
    cloth_.push_back(std::make_unique<PvdCollection>(dir_ + "/" + c.first));
    cloth_.back()->restore(c.second);
  }
  surface_.reset();
  if (s.surface) {
    surface_ = std::make_unique<PvdCollection>(dir_ + "/water_surface.pvd");
    surface_->restore(s.surfaceEntries);
  }
  statsColumns_ = s.statsColumns;
  statsBytes_ = s.statsBytes;

  // stats.csv: keep the rows of the saved frames, append from there.
  const std::string stats = dir_ + "/stats.csv";
  if (::truncate(stats.c_str(), static_cast<off_t>(statsBytes_)) != 0)
    throw InputError("cannot resume: cannot cut '" + stats + "' back: " + std::strerror(errno));
  stats_.close();
  stats_.open(stats, std::ios::out | std::ios::app);
  if (!stats_) throw InputError("cannot resume: cannot append to '" + stats + "'");
}

}  // namespace soak
