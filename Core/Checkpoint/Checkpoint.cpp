#include "Checkpoint/Checkpoint.h"

#include <sys/stat.h>

#include <cstring>
#include <fstream>
#include <iterator>

#include "Base/Error.h"
#include "Base/ReadInput.h"
#include "Checkpoint/StateStream.h"
#include "Output/FrameWriter.h"
#include "Output/VtkFiles.h"

namespace soak {

namespace {
constexpr char kMagic[8] = {'S', 'O', 'A', 'K', 'C', 'K', 'P', 'T'};
bool fileExists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}
constexpr std::size_t kPrefix = sizeof(kMagic) + sizeof(std::uint32_t) + sizeof(std::uint64_t);

void putHeader(StateWriter& out, const CheckpointHeader& h) {
  out.putString("run");
  out.putString(h.scenePath);
  out.putString(h.sceneText);
  out.put<std::int32_t>(h.frame);
  out.put<std::int32_t>(h.plannedFrames);
  out.putString(h.device);
  out.put<std::int32_t>(h.checkpointEvery);
}

CheckpointHeader getHeader(StateReader& in) {
  CheckpointHeader h;
  in.expect("run");
  h.scenePath = in.getString();
  h.sceneText = in.getString();
  h.frame = in.get<std::int32_t>();
  h.plannedFrames = in.get<std::int32_t>();
  h.device = in.getString();
  h.checkpointEvery = in.get<std::int32_t>();
  if (h.frame < 0 || h.plannedFrames < 0) in.fail("negative frame number");
  return h;
}
}  // namespace

std::uint64_t fnv1a64(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(data[i]);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

void writeCheckpoint(const std::string& path, const CheckpointHeader& header, const FrameWriter& writer,
                     const CheckpointState& state) {
  StateWriter payload;
  putHeader(payload, header);
  writer.saveState(payload);
  state.saveState(payload);
  const std::vector<char>& body = payload.bytes();
  std::string file(kMagic, sizeof(kMagic));
  auto append = [&file](const auto& v) { file.append(reinterpret_cast<const char*>(&v), sizeof(v)); };
  append(kCheckpointVersion);
  append(static_cast<std::uint64_t>(body.size()));
  file.append(body.data(), body.size());
  append(fnv1a64(body.data(), body.size()));
  writeFileAtomically(path, file);
}

Checkpoint Checkpoint::read(const std::string& path) {
  if (!fileExists(path)) throw InputError("no checkpoint here (a run writes one with --checkpoint-every N)", path);
  return fromBytes(readInputFile(path, kMaxCheckpointBytes, "checkpoint"), path);
}

Checkpoint Checkpoint::fromBytes(const std::string& file, const std::string& path) {
  if (file.size() < kPrefix + sizeof(std::uint64_t) || std::memcmp(file.data(), kMagic, sizeof(kMagic)) != 0)
    throw InputError("not a Soak checkpoint (wrong magic bytes or too short)", path);
  std::uint32_t version = 0;
  std::uint64_t size = 0, checksum = 0;
  std::memcpy(&version, file.data() + sizeof(kMagic), sizeof(version));
  std::memcpy(&size, file.data() + sizeof(kMagic) + sizeof(version), sizeof(size));
  if (version != kCheckpointVersion)
    throw InputError("checkpoint format version " + std::to_string(version) + "; this soak reads version " +
                         std::to_string(kCheckpointVersion),
                     path);
  if (size != file.size() - kPrefix - sizeof(checksum))
    throw InputError("checkpoint is truncated or has trailing bytes: it announces " + std::to_string(size) +
                         " bytes of state, the file holds " + std::to_string(file.size() - kPrefix - sizeof(checksum)),
                     path);
  std::memcpy(&checksum, file.data() + kPrefix + size, sizeof(checksum));
  if (fnv1a64(file.data() + kPrefix, size) != checksum)
    throw InputError("checkpoint is corrupted: its checksum does not match its contents", path);

  Checkpoint c;
  c.path_ = path;
  c.payload_.assign(file.begin() + kPrefix, file.begin() + kPrefix + std::ptrdiff_t(size));
  StateReader reader(c.payload_.data(), c.payload_.size(), path);
  c.header_ = getHeader(reader);
  c.stateOffset_ = reader.offset();
  return c;
}

FrameWriter::ResumeState Checkpoint::load(const FrameWriter& writer, CheckpointState& state) const {
  StateReader in(payload_.data() + stateOffset_, payload_.size() - stateOffset_, path_);
  const FrameWriter::ResumeState output = writer.readResumeState(in);
  state.loadState(in);
  if (!in.atEnd()) in.fail("it holds more state than this scene reads");
  return output;
}

void Checkpoint::restore(FrameWriter& writer, CheckpointState& state) const {
  // Everything is read and checked before the output folder is touched: a
  // refused resume leaves the run it refuses as it was.
  writer.resume(load(writer, state));
}

}  // namespace soak
