#pragma once
#include <string>
#include <vector>

namespace soak {

// A ParaView collection (.pvd): one dataset per time. Rewritten atomically
// after every frame, so a run killed at any moment leaves a valid file that
// lists every completed frame.
class PvdCollection {
 public:
  explicit PvdCollection(std::string path) : path_(std::move(path)) {}
  // `file` is relative to the .pvd's folder.
  void add(double time, const std::string& file);
  const std::string& path() const { return path_; }
  std::size_t size() const { return entries_.size(); }
  using Entry = std::pair<double, std::string>;  // time, file
  const std::vector<Entry>& entries() const { return entries_; }
  // Replaces the list (resuming from a checkpoint) and rewrites the file.
  void restore(std::vector<Entry> entries);

 private:
  void write() const;
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace soak
