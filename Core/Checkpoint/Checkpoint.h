#pragma once
// Checkpoint files (soak run --checkpoint-every N, soak run --resume DIR).
//
// File layout: magic "SOAKCKPT", format version (u32), payload length (u64),
// payload, FNV-1a 64 checksum of the payload (u64). It is written to a
// temporary file, synced and renamed, so a run killed while writing leaves
// the previous checkpoint whole. A file whose magic, version, length or
// checksum is wrong is refused (InputError) before anything is restored.
//
// The payload holds, in order: the scene (its path and its text as run),
// where the run stands (frame, planned frames), the output writer's state
// and the simulation's state (CheckpointState::saveState).
#include <cstdint>
#include <string>
#include <vector>

#include "Checkpoint/CheckpointState.h"
#include "Output/FrameWriter.h"

namespace soak {

struct CheckpointHeader {
  std::string scenePath;  // absolute path of the scene file (relative meshes resolve from its folder)
  std::string sceneText;  // the scene as run (what OUT/scene.xml holds)
  int frame = 0;          // last frame written before the checkpoint
  int plannedFrames = 0;  // frames the run was asked for
  std::string device;     // backend that wrote it ("cpu", "cuda")
  int checkpointEvery = 0;  // the run's --checkpoint-every (a resumed run keeps it)
};

constexpr std::uint32_t kCheckpointVersion = 7;
// The checkpoint's name inside a run's output folder.
constexpr const char* kCheckpointFile = "checkpoint.soak";

std::uint64_t fnv1a64(const char* data, std::size_t size);

void writeCheckpoint(const std::string& path, const CheckpointHeader& header, const FrameWriter& writer,
                     const CheckpointState& state);

// A checkpoint read and verified; restore() puts the state back.
class Checkpoint {
 public:
  static Checkpoint read(const std::string& path);
  // The same from a file's bytes (`path` names it in messages).
  static Checkpoint fromBytes(const std::string& file, const std::string& path);
  const CheckpointHeader& header() const { return header_; }
  // Restores the writer's and the simulation's state. The simulation must be
  // built from header().sceneText; a mismatch is refused with InputError.
  void restore(FrameWriter& writer, CheckpointState& state) const;
  // restore() without its last part: reads and checks the writer's state
  // against its folder and loads the simulation's, then returns the
  // writer's state for FrameWriter::resume; nothing on disk is touched.
  FrameWriter::ResumeState load(const FrameWriter& writer, CheckpointState& state) const;

 private:
  std::string path_;
  std::vector<char> payload_;
  std::size_t stateOffset_ = 0;  // where the writer's state starts
  CheckpointHeader header_;
};

}  // namespace soak
