// soak.sweep_plan, sweep_run, sweep_status, sweep_collect: `soak sweep`
// from Python (Doc/sweeps.md), on the same code.
#include "SweepPython.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "Base/Error.h"
#include "Sweep/LocalExecutor.h"
#include "Sweep/SlurmExecutor.h"
#include "Sweep/SweepCollect.h"
#include "Sweep/SweepFolder.h"

namespace py = pybind11;
using namespace soak;

namespace {

// A value or range as a description line writes it: a string as it is
// ("log 0.001 0.01 5"), a list or tuple as "list a b c", a number as
// "list x".
std::string rangeText(const py::handle& v) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  std::string text = "list";
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    for (const py::handle& item : v.cast<py::sequence>()) text += " " + py::str(item).cast<std::string>();
    return text;
  }
  return text + " " + py::str(v).cast<std::string>();
}

py::list rowsOf(const SweepState& s) {
  py::list rows;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    py::dict row;
    row["point"] = s.points[i].id;
    row["repeat"] = s.points[i].repeat;
    for (std::size_t k = 0; k < s.description.parameters.size(); ++k)
      row[py::str(s.description.parameters[k].name)] = s.points[i].values[k];
    const PointRecord& r = s.records[i];
    row["status"] = r.status;
    row["exit_code"] = r.exitCode >= 0 ? py::object(py::int_(r.exitCode)) : py::object(py::none());
    row["wall_s"] = r.wallSeconds;
    row["attempts"] = r.attempts;
    row["error"] = r.error;
    rows.append(row);
  }
  return rows;
}

}  // namespace

void addSweepFunctions(py::module_& m) {
  m.def(
      "sweep_plan",
      [](const std::string& folder, const py::object& description, const py::object& scene, const py::dict& vary,
         const py::dict& set, const py::object& frames, const py::object& time, int checkpointEvery, int repeats,
         const std::string& device) {
        SweepDescription d;
        if (!description.is_none()) {
          if (!scene.is_none() || vary.size() > 0 || set.size() > 0)
            throw py::value_error("give a description file or scene=/vary=/set=, not both");
          d = readSweepDescription(py::str(description).cast<std::string>());
        } else {
          if (scene.is_none()) throw py::value_error("give a description file or scene=");
          std::string text = "scene = " + py::str(scene).cast<std::string>() + "\n";
          if (!frames.is_none()) text += "frames = " + py::str(frames).cast<std::string>() + "\n";
          if (!time.is_none()) text += "time = " + py::str(time).cast<std::string>() + "\n";
          text += "checkpoint_every = " + std::to_string(checkpointEvery) + "\n";
          text += "repeats = " + std::to_string(repeats) + "\ndevice = " + device + "\n";
          for (const auto& kv : set) text += "set " + py::str(kv.first).cast<std::string>() + " = " +
                                              py::str(kv.second).cast<std::string>() + "\n";
          for (const auto& kv : vary)
            text += "vary " + py::str(kv.first).cast<std::string>() + " = " + rangeText(kv.second) + "\n";
          d = parseSweepDescription(text, "(sweep_plan arguments)");
        }
        PlanSummary s;
        {
          py::gil_scoped_release release;
          s = planSweep(d, folder);
        }
        py::dict result;
        result["points"] = s.points;
        result["added"] = s.added;
        result["invalid"] = s.invalid;
        return result;
      },
      py::arg("folder"), py::arg("description") = py::none(), py::kw_only(), py::arg("scene") = py::none(),
      py::arg("vary") = py::dict(), py::arg("set") = py::dict(), py::arg("frames") = py::none(),
      py::arg("time") = py::none(), py::arg("checkpoint_every") = 10, py::arg("repeats") = 1,
      py::arg("device") = "auto",
      R"(Plans a sweep into `folder` (soak sweep plan): from a description file, or from
scene=, vary={"WetCloth.diffusivity": "log 0.002 0.02 5" or [values]}, set={name: value},
frames= or time=. Returns {"points", "added", "invalid"}.)");

  m.def(
      "sweep_run",
      [](const std::string& folder, const std::string& executor, int jobs, int threads, const py::object& gpus,
         const std::string& soakProgram, int maxRunning, int cpusPerTask, const std::string& memory, int gpusPerTask) {
        py::dict result;
        if (executor == "local") {
          LocalRunOptions o;
          o.jobs = jobs;
          o.threads = threads;
          o.soakProgram = soakProgram;
          if (!gpus.is_none()) {
            o.detectGpus = false;
            o.gpus = gpus.cast<std::vector<std::string>>();
          }
          SweepRunSummary s;
          {
            py::gil_scoped_release release;
            s = runLocalSweep(folder, o);
          }
          result["points"] = s.points;
          result["started"] = s.started;
          result["done"] = s.done;
          result["failed"] = s.failed;
          result["interrupted"] = s.interrupted;
          result["stopped"] = s.stopped;
          result["exit_code"] = sweepExitCode(s);
          return result;
        }
        if (executor == "slurm") {
          SlurmOptions o;
          o.maxRunning = maxRunning;
          o.cpusPerTask = cpusPerTask;
          o.memory = memory;
          o.gpusPerTask = gpusPerTask;
          o.soakProgram = soakProgram;
          const SlurmSubmission s = submitSlurmSweep(folder, o);
          result["points"] = s.points;
          result["queued"] = s.queued;
          result["job_id"] = s.jobId;
          result["command"] = s.command;
          return result;
        }
        throw py::value_error("executor is 'local' or 'slurm', not '" + executor + "'");
      },
      py::arg("folder"), py::kw_only(), py::arg("executor") = "local", py::arg("jobs") = 0, py::arg("threads") = 0,
      py::arg("gpus") = py::none(), py::arg("soak_program") = "", py::arg("max_running") = 0,
      py::arg("cpus_per_task") = 1, py::arg("memory") = "", py::arg("gpus_per_task") = 0,
      R"(Runs the points of a planned sweep that are not done (soak sweep run): executor="local"
(jobs at a time, threads each, gpus=[ids]) or "slurm" (an sbatch job array: max_running,
cpus_per_task, memory, gpus_per_task). Ctrl-C stops the local runs cleanly. Returns a summary dict.)");

  m.def(
      "sweep_status", [](const std::string& folder) {
        const SweepState s = loadSweep(folder);
        writeManifest(s);
        return rowsOf(s);
      },
      py::arg("folder"), "Each point of the sweep as a dict (its values, status, exit_code, wall_s, error).");

  m.def(
      "sweep_collect",
      [](const std::string& folder, const std::vector<std::string>& figures, const std::string& output,
         const std::string& plot, const std::string& against) {
        std::vector<std::string> f = figures;
        if (!plot.empty() && std::find(f.begin(), f.end(), plot) == f.end()) {
          if (f.empty()) f = defaultSweepFigures();
          if (std::find(f.begin(), f.end(), plot) == f.end()) f.push_back(plot);
        }
        const CollectedSweep c = collectSweep(folder, f);
        const std::string csvPath = output.empty() ? folder + "/collect.csv" : output;
        std::ofstream(csvPath, std::ios::trunc) << collectedCsv(c);
        if (!plot.empty()) {
          if (against.empty()) throw py::value_error("plot= needs against= (a varying value)");
          std::ofstream(folder + "/plot-" + plot + ".svg", std::ios::trunc) << collectedPlotSvg(c, plot, against);
        }
        py::list rows;
        for (const CollectedSweep::Row& r : c.rows) {
          py::dict row;
          row["point"] = r.id;
          row["repeat"] = r.repeat;
          for (std::size_t k = 0; k < c.parameters.size(); ++k) row[py::str(c.parameters[k])] = r.values[k];
          row["status"] = r.status;
          for (std::size_t k = 0; k < c.figures.size(); ++k)
            row[py::str(c.figures[k])] = std::isnan(r.figures[k]) ? py::object(py::none()) : py::object(py::float_(r.figures[k]));
          rows.append(row);
        }
        return rows;
      },
      py::arg("folder"), py::kw_only(), py::arg("figures") = std::vector<std::string>{}, py::arg("output") = "",
      py::arg("plot") = "", py::arg("against") = "",
      R"(Collects a sweep (soak sweep collect): writes folder/collect.csv (or output=) and, with
plot= and against=, folder/plot-FIGURE.svg; returns one dict per point, its values and figures
(None where the point is not done).)");
}
