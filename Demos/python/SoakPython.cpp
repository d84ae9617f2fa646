// The `soak` Python module (pybind11): load a scene, step it, read and
// write its particle arrays as numpy arrays, share them without copies
// (DeviceArrayPython.h), write runs as `soak run` does. Doc/python.md is its
// guide. numpy is reached through its Python API and the buffer protocol
// only, so that one build works with numpy 1 and 2 whatever pybind11's
// numpy.h knows of their C structures.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <mutex>
#include <sstream>

#include "Base/Error.h"
#include "DeviceArrayPython.h"
#include "Output/CatalystLoader.h"
#include "Output/FrameWriter.h"
#include "Output/OutputFolder.h"
#include "Output/RunFolder.h"
#include "Simulation/Instability.h"
#include "Simulation/LoadedScene.h"
#include "Simulation/Runner.h"
#include "SharedArrays.h"
#include "SimulationArrays.h"
#include "SweepPython.h"

namespace py = pybind11;
using namespace soak;

namespace {

// `--set`'s text for a Python value: numbers as Python writes them, booleans
// as true/false, sequences (vectors) joined by spaces.
std::string overrideText(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) return py::repr(v).cast<std::string>();
  if (py::isinstance<py::sequence>(v)) {
    std::string out;
    for (const py::handle& item : v.cast<py::sequence>()) out += (out.empty() ? "" : " ") + overrideText(item);
    return out;
  }
  throw py::type_error("override values are numbers, booleans, strings or sequences of numbers, not " +
                       py::repr(v.get_type()).cast<std::string>());
}

// One simulation, as Python holds it. Calls that step or read release the
// GIL; a mutex keeps two Python threads from stepping it at once.
class PySimulation {
 public:
  PySimulation(const std::string& path, const std::string& xml, const std::string& device, const py::dict& overrides,
               const std::vector<std::string>& plugins) {
    SceneSource source;
    source.path = path.empty() ? "<xml string>" : path;
    source.text = xml;
    for (const auto& item : overrides)
      source.overrides.push_back(py::str(item.first).cast<std::string>() + "=" + overrideText(item.second));
    source.plugins = plugins;
    const Device d = resolveDevice(device);
    py::gil_scoped_release release;
    loaded_ = loadScene(source, d);
  }

  Simulation& sim() {
    if (!loaded_) throw std::runtime_error("this simulation is closed");
    return *loaded_->sim;
  }

  ~PySimulation() { generation_->bump(); }

  void close() {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    generation_->bump();
    loaded_.reset();
  }

  // Steps `n` times; Ctrl-C (a Python signal) stops between steps.
  void step(long long n, bool profile) {
    if (n < 0) throw py::value_error("step(n): n must be >= 0");
    Simulation& s = sim();
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    if (n > 0) generation_->bump();
    for (long long k = 0; k < n; ++k) {
      s.step(profile);
      if (k % 16 == 15) checkSignals();
    }
  }

  // Steps until the simulated time has grown by `seconds` (whole steps: the
  // first step at or past it).
  long long advance(double seconds, bool profile) {
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) throw py::value_error("advance(seconds): seconds must be >= 0");
    Simulation& s = sim();
    const double dt = s.settings.timeStep;
    const long long steps = (long long)std::ceil(seconds / dt - 1e-9);
    step(steps, profile);
    return steps;
  }

  // Writes a run as `soak run` does, from the scene's initial state.
  py::dict run(const std::string& output, int frames, double time, int checkpointEvery, bool overwrite,
               const std::vector<std::string>& catalyst, int catalystEvery, const std::string& live) {
    Simulation& s = sim();
    if (s.stepIndex() != 0)
      throw std::runtime_error("run() starts from the scene's initial state, and this simulation has been stepped "
                               "already; make a new Simulation to run it");
    const Scene& scene = loaded_->scene;
    const FolderClaim claim = overwrite ? FolderClaim::Overwrite : FolderClaim::Fresh;
    checkOutputFolder(output, scene.inputFiles());
    checkRunFolderClaim(output, claim);
    RunOptions options;
    options.frames = frames;
    options.time = time;
    options.checkpointEvery = checkpointEvery;
    options.checkpointPath = output + "/" + kCheckpointFile;
    options.checkpointHeader.scenePath = scene.path();
    options.checkpointHeader.sceneText = scene.textAsRun();
    options.checkpointHeader.device = deviceName(s.device());
    options.checkpointHeader.checkpointEvery = checkpointEvery;
    const int planned = Runner(s, nullptr).plannedFrames(options);
    s.checkPlannedParticles(planned / s.settings.frameRate);
    // The scene's <Catalyst> with these scripts added (`soak run --catalyst`).
    CatalystSettings catalystSettings = s.settings.catalyst;
    for (const std::string& script : catalyst) catalystSettings.scripts.push_back(script);
    if (catalystEvery > 0) catalystSettings.every = catalystEvery;
    if (!live.empty()) catalystSettings.live = live;
    if (!catalystSettings.live.empty()) parseLiveAddress(catalystSettings.live, "live");
    RunProgress result;
    int written = 0;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      generation_->bump();
      // Without the GIL: the adaptor's thread takes it for ParaView's Python.
      std::unique_ptr<FrameSink> sink;
      if (catalystSettings.wanted()) sink = loadCatalyst(catalystSettings, output);
      const RunFolderLock folderLock = claimRunFolder(output, claim);
      FrameWriter writer(output, scene.textAsRun(), FrameWriter::Start::Fresh, s.settings.output);
      writer.attachSink(sink.get());
      Runner runner(s, &writer);
      bool interrupted = false;
      try {
        result = runner.run(options, [&](const RunProgress&) {
          py::gil_scoped_acquire acquire;
          if (PyErr_CheckSignals() != 0) {
            PyErr_Clear();
            interrupted = true;
            runner.requestStop();
          }
        });
      } catch (const InstabilityError&) {
        writer.flush();  // the frames before the instability are kept
        throw;
      }
      writer.flush();
      written = writer.framesWritten();
      if (interrupted) throw InterruptedRun{written};
    }
    py::dict d;
    d["frames_written"] = written;
    d["steps"] = result.steps;
    d["wall_seconds"] = result.wallSeconds;
    d["simulated_seconds"] = s.time();
    return d;
  }

  struct InterruptedRun {
    int framesWritten;
  };

  std::mutex& mutex() { return mutex_; }
  // What device_arrays() handles are checked against.
  const std::shared_ptr<ArrayGeneration>& generation() const { return generation_; }

 private:
  static void checkSignals() {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }

  std::unique_ptr<LoadedScene> loaded_;
  std::mutex mutex_;
  std::shared_ptr<ArrayGeneration> generation_ = std::make_shared<ArrayGeneration>();
};

py::dict statsDict(const StatsRow& row) {
  py::dict d;
  for (const auto& c : row.values()) d[py::str(c.first)] = c.second;
  return d;
}

// Runs `f(simulation)` without the GIL, holding the simulation's mutex (a
// thread that steps it releases the GIL while it holds the mutex: taking the
// mutex with the GIL held could deadlock).
template <class F>
auto locked(PySimulation& s, F&& f) {
  Simulation& sim = s.sim();
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(s.mutex());
  return f(sim);
}

// A writable numpy array owning a copy of `a` (a bytearray under it).
py::object toNumpy(const HostArray& a) {
  const char* bytes =
      a.integer ? reinterpret_cast<const char*>(a.ints.data()) : reinterpret_cast<const char*>(a.values.data());
  const std::size_t size = a.integer ? a.ints.size() * sizeof(int) : a.values.size() * sizeof(float);
  PyObject* raw = PyByteArray_FromStringAndSize(bytes, py::ssize_t(size));
  if (!raw) throw py::error_already_set();
  const py::object buffer = py::reinterpret_steal<py::object>(raw);
  const py::module_ np = py::module_::import("numpy");
  py::object out = np.attr("frombuffer")(buffer, py::arg("dtype") = a.integer ? "int32" : "float32");
  if (a.components > 1) out = out.attr("reshape")(py::ssize_t(a.rows()), a.components);
  return out;
}

py::dict toDict(const std::vector<HostArray>& arrays) {
  py::dict d;
  for (const HostArray& a : arrays) d[py::str(a.name)] = toNumpy(a);
  return d;
}

// Values to write: a numeric array (or sequence) as C-ordered float32,
// converted when it is another numeric type; TypeError for anything else.
struct Floats {
  py::object array;  // keeps the buffer alive
  py::buffer_info info;
  const float* data() const { return static_cast<const float*>(info.ptr); }
  std::size_t rows() const { return info.ndim > 0 ? std::size_t(info.shape[0]) : 0; }
  std::size_t columns() const {
    if (info.ndim == 1) return 0;
    if (info.ndim == 2) return std::size_t(info.shape[1]);
    throw std::invalid_argument("values must be 1- or 2-dimensional, got " + std::to_string(info.ndim) + " dimensions");
  }
};

Floats asFloats(const py::object& values) {
  const py::module_ np = py::module_::import("numpy");
  const py::object given = np.attr("asarray")(values);
  const std::string kind = given.attr("dtype").attr("kind").cast<std::string>();
  if (kind != "f" && kind != "i" && kind != "u")
    throw py::type_error("values must be a numeric array (float32 preferred), not dtype " +
                         py::str(given.attr("dtype")).cast<std::string>());
  Floats f;
  f.array = np.attr("ascontiguousarray")(given, py::arg("dtype") = "float32");
  f.info = py::reinterpret_borrow<py::buffer>(f.array).request();
  return f;
}

}  // namespace

PYBIND11_MODULE(soak, m) {
  m.doc() = "Soak: position-based cloth wetting (Shao et al. 2017) from Python. See Doc/python.md.";
  static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
  static py::exception<DeviceError> deviceError(m, "DeviceError", PyExc_RuntimeError);
  static py::exception<StorageError> storageError(m, "StorageError", PyExc_OSError);
  static py::exception<InstabilityError> instabilityError(m, "InstabilityError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      inputError(e.what());
    } catch (const StorageError& e) {
      storageError(e.what());
    } catch (const DeviceError& e) {
      deviceError(e.what());
    } catch (const InstabilityError& e) {
      instabilityError(e.what());
    } catch (const PySimulation::InterruptedRun& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt,
                      ("run interrupted; " + std::to_string(e.framesWritten) + " frames were written").c_str());
    }
  });

  addSweepFunctions(m);
  addDeviceArrayClass(m);

  m.def("cuda_available", [] { return cudaDeviceAvailable(); }, "Whether the CUDA backend is built and a GPU is present.");

  py::class_<PySimulation>(m, "Simulation", R"(A scene built into a simulation.

Simulation(path=None, *, xml=None, device="auto", overrides=None, plugins=None)
  path: a scene file; or xml: the scene's XML text.
  device: "auto" (the GPU when present), "cpu" or "cuda".
  overrides: {"Element.attr": value} with `soak run --set`'s meaning.
  plugins: extra plugin libraries (the standard ones load by themselves).)")
      .def(py::init([](const py::object& path, const py::object& xml, const std::string& device,
                       const py::object& overrides, const std::vector<std::string>& plugins) {
             if (path.is_none() == xml.is_none())
               throw py::value_error("give either a scene path or xml=, not both and not neither");
             py::dict o = overrides.is_none() ? py::dict() : py::dict(overrides);
             return std::make_unique<PySimulation>(path.is_none() ? "" : py::str(path).cast<std::string>(),
                                                   xml.is_none() ? "" : xml.cast<std::string>(), device, o, plugins);
           }),
           py::arg("path") = py::none(), py::kw_only(), py::arg("xml") = py::none(), py::arg("device") = "auto",
           py::arg("overrides") = py::none(), py::arg("plugins") = std::vector<std::string>{})
      .def("close", &PySimulation::close, "Frees the simulation; any later call raises RuntimeError.")
      .def("__enter__", [](PySimulation& s) -> PySimulation& { return s; }, py::return_value_policy::reference)
      .def("__exit__", [](PySimulation& s, const py::args&) { s.close(); })
      .def_property_readonly("device", [](PySimulation& s) { return std::string(deviceName(s.sim().device())); })
      .def_property_readonly("time", [](PySimulation& s) { return s.sim().time(); }, "Simulated seconds.")
      .def_property_readonly("step_index", [](PySimulation& s) { return s.sim().stepIndex(); })
      .def_property_readonly("time_step", [](PySimulation& s) { return s.sim().settings.timeStep; })
      .def_property_readonly("frame_rate", [](PySimulation& s) { return s.sim().settings.frameRate; })
      .def_property_readonly("particle_count", [](PySimulation& s) { return s.sim().particles.count(); })
      .def("step", &PySimulation::step, py::arg("n") = 1, py::arg("profile") = false,
           "Advances n time steps (the GIL is released). profile=True times each stage (stage_times()).")
      .def("advance", &PySimulation::advance, py::arg("seconds"), py::arg("profile") = false,
           "Advances by whole steps until `seconds` more are simulated; returns the steps taken.")
      .def("run", &PySimulation::run, py::arg("output"), py::kw_only(), py::arg("frames") = -1,
           py::arg("time") = -1.0, py::arg("checkpoint_every") = 0, py::arg("overwrite") = false,
           py::arg("catalyst") = std::vector<std::string>{}, py::arg("catalyst_every") = 0, py::arg("live") = "",
           "Writes a run into `output` as `soak run` does (frames=N or time=T; the scene's duration by default), "
           "from the scene's initial state. `output` must be new or empty, as for `soak run`; overwrite=True "
           "replaces the run already there. catalyst=[SCRIPT.py, ...], catalyst_every=N and live=\"HOST:PORT\" "
           "are `soak run`'s --catalyst, --catalyst-every and --live (Doc/paraview.md, \"In situ and live\"). "
           "Returns frames_written, steps, wall_seconds, simulated_seconds.")
      .def("fields", [](PySimulation& s) { return arrayFieldNames(s.sim()); },
           "Names get() and set() take: the particle arrays, then the channels (saturation, held_water, ...).")
      .def("get",
           [](PySimulation& s, const std::string& field) {
             return toNumpy(locked(s, [&](Simulation& sim) { return getField(sim, field); }));
           },
           py::arg("field"),
           "A copy of a per-particle array, in slot order (slots are reordered every step: use 'id' and "
           "'phase', or water() and cloth(), for a stable order).")
      .def("set",
           [](PySimulation& s, const std::string& field, const py::object& values) {
             const Floats f = asFloats(values);
             const std::size_t rows = f.rows(), cols = f.columns();
             locked(s, [&](Simulation& sim) { setField(sim, field, f.data(), rows, cols); return 0; });
           },
           py::arg("field"), py::arg("values"),
           "Writes a per-particle array in slot order: position, velocity or a channel.")
      .def("device_arrays",
           [](const py::object& self) {
             PySimulation& s = self.cast<PySimulation&>();
             struct Taken {
               std::vector<SharedArray> arrays;
               long long step;
               std::uint64_t generation;
             };
             const Taken t = locked(s, [&](Simulation& sim) {
               return Taken{sharedArrays(sim), sim.stepIndex(), s.generation()->value.load()};
             });
             return makeDeviceArrays(t.arrays, s.sim().device(), t.step, t.generation, s.generation(), self);
           },
           "The simulation's own arrays, shared without copies: name -> DeviceArray, in slot order "
           "(position, velocity, inverse_mass, mass, radius, phase, id, then the channels). On the GPU they "
           "implement __cuda_array_interface__ and DLPack (torch.from_dlpack, cupy.asarray); on the CPU numpy() "
           "and DLPack give numpy views. Valid until the next step, run or close: a handle used after that raises "
           "StaleArrayError. Writing position, velocity or a channel through them changes the simulation.")
      .def("water", [](PySimulation& s) { return toDict(locked(s, [](Simulation& sim) { return waterArrays(sim); })); },
           "The water particles' arrays, ordered by id.")
      .def("cloth_names", [](PySimulation& s) { return clothNames(s.sim()); })
      .def("cloth",
           [](PySimulation& s, const std::string& name) {
             return toDict(locked(s, [&](Simulation& sim) { return clothArrays(sim, name); }));
           },
           py::arg("name"), "One cloth's arrays in vertex order, with its triangles.")
      .def("set_cloth",
           [](PySimulation& s, const std::string& name, const std::string& field, const py::object& values) {
             const Floats f = asFloats(values);
             const std::size_t rows = f.rows(), cols = f.columns();
             locked(s, [&](Simulation& sim) { setClothField(sim, name, field, f.data(), rows, cols); return 0; });
           },
           py::arg("name"), py::arg("field"), py::arg("values"),
           "Writes one cloth's position, velocity or a channel, in vertex order (a pinned vertex moves with it).")
      .def("stats",
           [](PySimulation& s) { return statsDict(locked(s, [](Simulation& sim) { return sim.collectStats(); })); },
           "The stats.csv columns of the current state, as a dict.")
      .def("water_budget",
           [](PySimulation& s) {
             const StatsRow row = locked(s, [](Simulation& sim) { return sim.collectStats(); });
             py::dict d;
             for (const auto& c : row.values())
               if (c.first.size() > 11 && c.first.compare(c.first.size() - 11, 11, "_water_mass") == 0)
                 d[py::str(c.first.substr(0, c.first.size() - 11))] = c.second;
             return d;
           },
           "Water masses in kg: free, held, buffered, drained, emitted, total (held and buffered with WetCloth).")
      .def("stage_times",
           [](PySimulation& s) {
             py::dict d;
             for (const StageTiming& t : s.sim().pipeline.timings()) d[py::str(t.name)] = t.meanMs();
             return d;
           },
           "Mean milliseconds per step of each stage over the steps taken with profile=True.");
}
