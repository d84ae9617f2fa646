// libFuzzer target: the checkpoint reader (Checkpoint::fromBytes, the
// writer's part checked against a real run's folder, Simulation::loadState)
// on arbitrary bytes. A resume may refuse anything with InputError; nothing
// may crash, leak, hit undefined behaviour or allocate more than the bytes
// it was given can describe.
//
// Most mutated inputs would fail the checksum; so that the fuzzer reaches
// the state behind it, an input whose last byte is even gets its length and
// checksum fields set to match (odd: taken as it is, checksum included).
// Setting SOAK_FUZZ_SEED=FILE writes the sample run's checkpoint to FILE
// and exits (run_fuzzers.sh makes the seed corpus so).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "Base/Error.h"
#include "Base/ReadInput.h"
#include "FuzzRun.h"

namespace {
const std::string kRunDir = "checkpoint_fuzz_run";
soak::LoadedScene* g_scene = nullptr;
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_scene = soak::fuzz::writeSampleRun(kRunDir).release();
  if (const char* seed = std::getenv("SOAK_FUZZ_SEED")) {
    std::ofstream(seed, std::ios::binary) << soak::readInputFile(kRunDir + "/" + soak::kCheckpointFile,
                                                                 soak::kMaxCheckpointBytes, "checkpoint");
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string file(reinterpret_cast<const char*>(data), size);
  constexpr std::size_t kPrefix = 8 + 4 + 8;  // magic, version, length (Checkpoint.h)
  if (size >= kPrefix + 8 && (data[size - 1] & 1) == 0) {
    const std::uint64_t length = size - kPrefix - 8;
    std::memcpy(&file[12], &length, 8);
    const std::uint64_t sum = soak::fnv1a64(file.data() + kPrefix, length);
    std::memcpy(&file[kPrefix + length], &sum, 8);
  }
  try {
    const soak::Checkpoint c = soak::Checkpoint::fromBytes(file, "fuzz.soak");
    soak::FrameWriter writer(kRunDir, "", soak::FrameWriter::Start::Resume);
    (void)c.load(writer, *g_scene->sim);
  } catch (const soak::InputError&) {
  }
  return 0;
}
