#pragma once
// How frames are written (<Output>): the compressor of the VTK files, and the
// background writers that take frames off the stepping thread
// (Output/FrameWriter.h). Doc/output.md measures the compressors.
namespace soak {

enum class Compression { None, LZ4, ZLib, LZMA };

struct OutputSettings {
  Compression compression = Compression::LZ4;
  int writerThreads = 8;  // background threads that build and write frame files
  int queuedFrames = 8;   // frames captured and not yet on disk before a step waits
};

}  // namespace soak
