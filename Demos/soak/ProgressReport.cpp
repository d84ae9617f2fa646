#include "ProgressReport.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace soak::cli {

namespace {
void formatDuration(double s, char* buf, std::size_t n) {
  long t = static_cast<long>(s + 0.5);
  std::snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
}
}  // namespace

ProgressReport::ProgressReport(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0) {}

void ProgressReport::update(const RunProgress& p) {
  if (quiet_) return;
  char eta[32];
  formatDuration(p.etaSeconds, eta, sizeof(eta));
  // Frames on disk: the frame simulated last may still be queued for writing.
  const int written = std::max(0, p.framesWritten - 1);
  const double frac = p.frames > 0 ? double(written) / p.frames : 1.0;
  if (tty_) {
    const int width = 30;
    int filled = static_cast<int>(frac * width + 0.5);
    char bar[width + 1];
    for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
    bar[width] = 0;
    std::fprintf(stderr, "\r[%s] frame %d/%d  t=%.3f/%.3f s  %.1f steps/s  ETA %s ", bar, written, p.frames,
                 p.simTime, p.endTime, p.stepsPerSecond, eta);
    std::fflush(stderr);
    drawn_ = true;
    return;
  }
  int decile = static_cast<int>(frac * 10.0);
  if (decile == lastDecile_ && written != p.frames) return;
  lastDecile_ = decile;
  std::fprintf(stderr, "progress: frame %d/%d (%3.0f%%)  t=%.3f s  %.1f steps/s  ETA %s\n", written, p.frames,
               frac * 100.0, p.simTime, p.stepsPerSecond, eta);
}

void ProgressReport::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace soak::cli
