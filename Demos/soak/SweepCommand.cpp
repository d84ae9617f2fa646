#include "SweepCommand.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "Arguments.h"
#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Sweep/LocalExecutor.h"
#include "Sweep/SlurmExecutor.h"
#include "Sweep/SweepCollect.h"
#include "Sweep/SweepFolder.h"
#include "Sweep/SweepLaunch.h"
#include "Sweep/SweepTask.h"

namespace soak::cli {

const char* kSweepUsage =
    "usage: soak sweep <verb> ... (Doc/sweeps.md)\n"
    "\n"
    "  plan SWEEP.txt [-o DIR]       expand a sweep description into DIR (default:\n"
    "                                soak-sweeps/<description name>): a folder per point\n"
    "  plan -o DIR --scene S.xml [--vary 'Element.attr=RANGE']... [--set Element.attr=V]...\n"
    "       [--frames N | --time T] [--checkpoint-every N] [--repeats N] [--device D]\n"
    "                                the same from options; RANGE: list A B C | linear FROM TO COUNT\n"
    "                                | log FROM TO COUNT\n"
    "  run DIR [--executor local]    run the points not done, N at a time on this machine:\n"
    "          [--jobs N] [--threads N] [--gpus 0,1,...|none]\n"
    "  run DIR --executor slurm      submit them as an sbatch job array:\n"
    "          [--max-running K] [--cpus-per-task N] [--mem SIZE] [--gpus-per-task N]\n"
    "          [--time-limit T] [--partition P] [--sbatch-arg ARG]...\n"
    "  run DIR --executor print [--plain]\n"
    "                                one command line per point not done (soak sweep task ...;\n"
    "                                --plain: the bare soak run lines, which record no status)\n"
    "  status DIR                    each point's status; rewrites DIR/manifest.csv\n"
    "  collect DIR [--figures a,b,...] [-o FILE.csv] [--plot FIGURE --against Element.attr]\n"
    "                                one CSV of values and summary figures (default\n"
    "                                DIR/collect.csv) and an SVG plot (DIR/plot-FIGURE.svg)\n"
    "  task DIR POINT [--threads N]  run one point to its end (what each Slurm task runs)\n"
    "\n"
    "figures: held buffered drained free evaporated drips max_saturation worst_strain\n"
    "         worst_stretch steps simulated_s wall_s, or final|max|min|mean:STATS_COLUMN\n"
    "exit codes of run: 0 every point done, 2 bad input, 6 points failed or invalid\n"
    "         (the manifest says which and why), 130 stopped by a signal\n";

namespace {

// The arguments of one verb, taken in order.
class Options {
 public:
  explicit Options(std::vector<std::string> args) : args_(std::move(args)) {}
  bool more() const { return i_ < args_.size(); }
  const std::string& next() { return args_[i_++]; }
  std::string value(const std::string& option) {
    if (!more()) throw InputError(option + " needs a value (see soak sweep help)");
    return next();
  }
  int integer(const std::string& option, int lo, int hi) {
    const std::string v = value(option);
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || d != std::floor(d) || d < lo || d > hi)
      throw InputError(option + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                       "], not '" + clipForMessage(v) + "'");
    return int(d);
  }

 private:
  std::vector<std::string> args_;
  std::size_t i_ = 0;
};

[[noreturn]] void unknown(const std::string& verb, const std::string& a) {
  throw InputError("soak sweep " + verb + ": unexpected argument '" + clipForMessage(a) + "' (see soak sweep help)");
}

std::string stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  return name.substr(0, name.find_last_of('.'));
}

void say(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }

std::string absolute(const std::string& dir) {
  char* real = ::realpath(dir.c_str(), nullptr);
  if (!real) return dir;
  std::string r(real);
  std::free(real);
  return r;
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw InputError("cannot write '" + path + "'");
}

int planVerb(Options o) {
  std::string file, dir;
  std::vector<std::string> lines, plugins;
  while (o.more()) {
    const std::string a = o.next();
    if (a == "-o" || a == "--output") dir = o.value(a);
    else if (a == "--plugin") plugins.push_back(o.value(a));
    else if (a == "--scene") lines.push_back("scene = " + absolute(o.value(a)));
    else if (a == "--vary") lines.push_back("vary " + o.value(a));
    else if (a == "--set") lines.push_back("set " + o.value(a));
    else if (a == "--frames") lines.push_back("frames = " + o.value(a));
    else if (a == "--time") lines.push_back("time = " + o.value(a));
    else if (a == "--checkpoint-every") lines.push_back("checkpoint_every = " + o.value(a));
    else if (a == "--repeats") lines.push_back("repeats = " + o.value(a));
    else if (a == "--device") lines.push_back("device = " + o.value(a));
    else if (!a.empty() && a[0] != '-' && file.empty()) file = a;
    else unknown("plan", a);
  }
  if (!file.empty() && !lines.empty())
    throw InputError("soak sweep plan: give a description file or --scene/--vary/... options, not both");
  if (file.empty() && lines.empty()) throw InputError("soak sweep plan: no sweep description (see soak sweep help)");
  SweepDescription d;
  if (!file.empty()) {
    d = readSweepDescription(file);
    if (dir.empty()) dir = "soak-sweeps/" + stem(file);
  } else {
    if (dir.empty()) throw InputError("soak sweep plan: -o DIR is needed when the sweep is given as options");
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    d = parseSweepDescription(text, "(options)");
  }
  const PlanSummary s = planSweep(d, dir, plugins);
  std::printf("soak sweep: %s: %d points (%d new", dir.c_str(), s.points, s.added);
  if (s.invalid > 0) std::printf(", %d invalid: their values are refused, see the manifest", s.invalid);
  std::printf("); manifest %s/manifest.csv\n", dir.c_str());
  return kExitOk;
}

int runVerb(Options o) {
  std::string dir, executor = "local";
  LocalRunOptions local;
  SlurmOptions slurm;
  bool plain = false;
  while (o.more()) {
    const std::string a = o.next();
    if (a == "--executor") executor = o.value(a);
    else if (a == "--jobs" || a == "-j") local.jobs = o.integer(a, 1, 100000);
    else if (a == "--threads") local.threads = o.integer(a, 1, kMaxThreads);
    else if (a == "--gpus") {
      const std::string v = o.value(a);
      local.gpus.clear();
      local.detectGpus = false;
      if (v != "none")
        for (std::size_t at = 0; at <= v.size();) {
          const std::size_t comma = std::min(v.find(',', at), v.size());
          if (comma > at) local.gpus.push_back(v.substr(at, comma - at));
          at = comma + 1;
        }
    } else if (a == "--max-running") slurm.maxRunning = o.integer(a, 1, 1000000);
    else if (a == "--cpus-per-task") slurm.cpusPerTask = o.integer(a, 1, kMaxThreads);
    else if (a == "--mem") slurm.memory = o.value(a);
    else if (a == "--gpus-per-task") slurm.gpusPerTask = o.integer(a, 0, 64);
    else if (a == "--time-limit") slurm.timeLimit = o.value(a);
    else if (a == "--partition") slurm.partition = o.value(a);
    else if (a == "--job-name") slurm.jobName = o.value(a);
    else if (a == "--sbatch-arg") slurm.sbatchArguments.push_back(o.value(a));
    else if (a == "--sbatch") slurm.sbatch = o.value(a);
    else if (a == "--squeue") slurm.squeue = o.value(a);
    else if (a == "--plain") plain = true;
    else if (!a.empty() && a[0] != '-' && dir.empty()) dir = a;
    else unknown("run", a);
  }
  if (dir.empty()) throw InputError("soak sweep run: no sweep folder given (soak sweep run DIR)");
  dir = absolute(dir);
  if (executor == "local") {
    local.say = say;
    return sweepExitCode(runLocalSweep(dir, local));
  }
  if (executor == "slurm") {
    const SlurmSubmission sub = submitSlurmSweep(dir, slurm);
    if (sub.points == 0)
      std::printf("soak sweep: nothing to submit: every point is done, invalid%s\n",
                  sub.queued > 0 ? (", or queued (" + std::to_string(sub.queued) + ")").c_str() : "");
    else
      std::printf("soak sweep: submitted %d point(s) as job %s (%s)%s\n  %s\n", sub.points, sub.jobId.c_str(),
                  sub.batchFile.c_str(),
                  sub.queued > 0 ? (", " + std::to_string(sub.queued) + " still queued").c_str() : "",
                  sub.command.c_str());
    return kExitOk;
  }
  if (executor == "print") {
    const SweepState s = loadSweep(dir);
    const std::string program = soakProgramPath(local.soakProgram);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      if (pointSettled(s.records[i])) continue;
      const SweepPoint& p = s.points[i];
      if (!plain) {
        std::printf("%s\n", shellCommand({program, "sweep", "task", dir, p.id}).c_str());
        continue;
      }
      const PointLaunch launch = pointLaunch(s.layout, s.description, p, program, local.threads);
      if (launch.kind != LaunchKind::AlreadyDone) std::printf("%s\n", shellCommand(launch.argv).c_str());
    }
    return kExitOk;
  }
  throw InputError("soak sweep run: unknown executor '" + clipForMessage(executor) + "' (local, slurm or print)");
}

int statusVerb(Options o) {
  std::string dir;
  while (o.more()) {
    const std::string a = o.next();
    if (!a.empty() && a[0] != '-' && dir.empty()) dir = a;
    else unknown("status", a);
  }
  if (dir.empty()) throw InputError("soak sweep status: no sweep folder given");
  const SweepState s = loadSweep(dir);
  writeManifest(s);
  std::printf("%-14s %-6s", "point", "repeat");
  for (const SweepParameter& p : s.description.parameters) std::printf(" %-14s", p.name.c_str());
  std::printf(" %-11s %4s %9s  %s\n", "status", "exit", "wall_s", "error");
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const PointRecord& r = s.records[i];
    std::printf("%-14s %-6d", s.points[i].id.c_str(), s.points[i].repeat);
    for (const std::string& v : s.points[i].values) std::printf(" %-14s", v.c_str());
    std::printf(" %-11s %4s %9.1f  %s\n", r.status.c_str(), r.exitCode >= 0 ? std::to_string(r.exitCode).c_str() : "",
                r.wallSeconds, clipForMessage(r.error).c_str());
  }
  std::printf("soak sweep: %s (%s)\n", statusCounts(s).c_str(), s.layout.manifest().c_str());
  return kExitOk;
}

int collectVerb(Options o) {
  std::string dir, out, plot, against, plotFile;
  std::vector<std::string> figures;
  while (o.more()) {
    const std::string a = o.next();
    if (a == "--figures") {
      const std::string v = o.value(a);
      for (std::size_t at = 0; at <= v.size();) {
        const std::size_t comma = std::min(v.find(',', at), v.size());
        if (comma > at) figures.push_back(v.substr(at, comma - at));
        at = comma + 1;
      }
    } else if (a == "-o" || a == "--output") out = o.value(a);
    else if (a == "--plot") plot = o.value(a);
    else if (a == "--against") against = o.value(a);
    else if (a == "--plot-file") plotFile = o.value(a);
    else if (!a.empty() && a[0] != '-' && dir.empty()) dir = a;
    else unknown("collect", a);
  }
  if (dir.empty()) throw InputError("soak sweep collect: no sweep folder given");
  if (plot.empty() != against.empty()) throw InputError("soak sweep collect: --plot and --against go together");
  if (!plot.empty() && figures.empty()) figures = defaultSweepFigures();
  if (!plot.empty() && std::find(figures.begin(), figures.end(), plot) == figures.end()) figures.push_back(plot);
  const CollectedSweep c = collectSweep(dir, figures);
  if (out.empty()) out = dir + "/collect.csv";
  writeFile(out, collectedCsv(c));
  int done = 0;
  for (const CollectedSweep::Row& r : c.rows) done += r.status == "done";
  std::printf("soak sweep: %s: %d of %zu points done and collected\n", out.c_str(), done, c.rows.size());
  if (!plot.empty()) {
    if (plotFile.empty()) {
      std::string name = plot;
      for (char& ch : name)
        if (!std::isalnum((unsigned char)ch) && ch != '_' && ch != '-') ch = '_';
      plotFile = dir + "/plot-" + name + ".svg";
    }
    writeFile(plotFile, collectedPlotSvg(c, plot, against));
    std::printf("soak sweep: %s: %s against %s\n", plotFile.c_str(), plot.c_str(), against.c_str());
  }
  return kExitOk;
}

int taskVerb(Options o) {
  std::string dir, point;
  int threads = 0;
  while (o.more()) {
    const std::string a = o.next();
    if (a == "--threads") threads = o.integer(a, 1, kMaxThreads);
    else if (!a.empty() && a[0] != '-' && dir.empty()) dir = a;
    else if (!a.empty() && a[0] != '-' && point.empty()) point = a;
    else unknown("task", a);
  }
  if (point.empty()) throw InputError("soak sweep task: usage: soak sweep task DIR POINT [--threads N]");
  return runSweepTask(dir, point, threads, "", say);
}

}  // namespace

int sweepCommand(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kSweepUsage, args.empty() ? stderr : stdout);
    return args.empty() ? kExitInput : kExitOk;
  }
  const std::string verb = args[0];
  Options rest(std::vector<std::string>(args.begin() + 1, args.end()));
  if (verb == "plan") return planVerb(rest);
  if (verb == "run") return runVerb(rest);
  if (verb == "status") return statusVerb(rest);
  if (verb == "collect") return collectVerb(rest);
  if (verb == "task") return taskVerb(rest);
  throw InputError("soak sweep: unknown verb '" + clipForMessage(verb) + "' (plan, run, status, collect, task)");
}

}  // namespace soak::cli
