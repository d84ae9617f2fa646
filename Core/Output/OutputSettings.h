#pragma once
// How frames are written (<Output>): the compressor of the VTK files, the
// formats for other tools (OpenVDB, PLY) and the background writers that
// take frames off the stepping thread (Output/FrameWriter.h). Doc/output.md
// measures the compressors and the writer threads.
#include <string>

#include "Backend/Device.h"

namespace soak {

enum class Compression { None, LZ4, ZLib, LZMA };

struct OutputSettings {
  Compression compression = Compression::LZ4;
  // Background threads that build and write frame files; 0 writes them on
  // the stepping thread; kAutoWriterThreads: writerThreadsFor's choice.
  static constexpr int kAutoWriterThreads = -1;
  int writerThreads = kAutoWriterThreads;
  int queuedFrames = 8;   // frames captured and not yet on disk before a step waits
  bool vdb = false;       // water as OpenVDB (Output/VdbFiles.h), water_vdb/
  bool ply = false;       // cloth as binary PLY (Output/PlyFiles.h), cloth_<name>_ply/
  std::string plyColour = "saturation";  // channel the PLY vertex colours show; empty: none
};

// <WaterSurface>: a water surface mesh per frame (FrameWriter.h), for the
// scenes that have the element.
struct WaterSurfaceSettings {
  float cellSize = 0.014f;  // m: the splat grid's cell (0.7 r0 at r0 = 0.02 m, as the paper)
  float iso = 0.5f;         // relative density rho / rho0 of the surface
  long long maxCells = 64ll * 1024 * 1024;  // larger grids take a coarser cell
};

// The writer threads a run gets. Automatic: 8 where the simulation runs on
// the GPU (its host cores are free for writing: 8 measured fastest on a
// 16-core host), 1 on the CPU, where OpenMP's threads take every core and
// more writers at once stall them (on 2 cores, 8 writers cost 1.04-1.07
// times the run's time, 1 writer 1.03, writing on the stepping thread
// 1.04-1.05: Doc/output.md).
inline int writerThreadsFor(const OutputSettings& s, Device d) {
  if (s.writerThreads != OutputSettings::kAutoWriterThreads) return s.writerThreads;
  return d == Device::Cuda ? 8 : 1;
}

}  // namespace soak
