#pragma once
// What became of one point, kept in its own file (points/ID/status), so
// that points run at once on many machines never write the same file; the
// manifest is rebuilt from these files.
//
// Statuses:
//   planned      not run yet
//   invalid      its values are refused by the scene (error says why); not run
//   running      a run of it is under way
//   done         its run reached the end (exit code 0)
//   failed       its run ended with an error (exit code and error say which)
//   interrupted  its run was stopped (a signal, Ctrl-C, scancel, preemption)
//                and resumes from its checkpoint on the next run
#include <string>

namespace soak {

struct PointRecord {
  std::string status = "planned";
  int exitCode = -1;         // the last run's; -1 before any
  double wallSeconds = 0.0;  // all runs of the point together
  int attempts = 0;          // runs started (a resume counts as one)
  std::string error;         // the last failed run's message (one line)
  std::string host;          // where the last run ran
  long long pid = 0;         // the process that runs it (while running)
};

// Missing file: a planned point. A damaged file reads as planned too (it
// is rewritten whole by the next run).
PointRecord readPointRecord(const std::string& path);

// Written under a temporary name and renamed (never half a file).
void writePointRecord(const std::string& path, const PointRecord& r);

// Whether a point counts as finished for a sweep run (done or invalid).
inline bool pointSettled(const PointRecord& r) { return r.status == "done" || r.status == "invalid"; }

// This machine's short host name.
std::string thisHostName();

}  // namespace soak
