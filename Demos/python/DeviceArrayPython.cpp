#include "DeviceArrayPython.h"

#include <stdexcept>
#include <string>

#include "Backend/Device.h"
#include "DLPack.h"

namespace py = pybind11;

namespace soak {

namespace {

struct StaleArrayError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Soak queues a step's GPU work on the stepping thread's per-thread default
// stream (CudaBackend.cu), which __cuda_array_interface__ and DLPack call 2.
// It is a blocking stream: work on the legacy default stream (1), PyTorch's
// and CuPy's default, waits for it and it for that work.
constexpr int kPerThreadDefaultStream = 2;
constexpr int kLegacyDefaultStream = 1;
// Soak runs on the process's first GPU.
constexpr int kCudaDeviceId = 0;

class DeviceArray {
 public:
  DeviceArray(SharedArray a, Device device, long long stepIndex, std::uint64_t generation,
              std::shared_ptr<ArrayGeneration> current, py::object owner)
      : a_(std::move(a)), device_(device), stepIndex_(stepIndex), generation_(generation),
        current_(std::move(current)), owner_(std::move(owner)) {}

  const SharedArray& array() const { return a_; }
  Device device() const { return device_; }
  long long stepIndex() const { return stepIndex_; }
  bool valid() const { return current_->value.load() == generation_; }

  // Every way in to the memory passes here.
  void check() const {
    if (!valid())
      throw StaleArrayError("the handle of '" + a_.name + "' was made at step " + std::to_string(stepIndex_) +
                            ", and the simulation has stepped, run or closed since (its arrays are reordered and "
                            "may move): call device_arrays() again");
  }

  py::tuple shape() const {
    return a_.columns ? py::make_tuple(a_.rows, a_.columns) : py::make_tuple(a_.rows);
  }
  py::tuple byteStrides() const {
    const std::int64_t row = 4 * a_.rowStride;
    return a_.columns ? py::make_tuple(row, 4) : py::make_tuple(row);
  }
  bool compact() const { return a_.rowStride == (a_.columns ? a_.columns : 1); }
  py::object interfaceStrides() const { return compact() ? py::object(py::none()) : py::object(byteStrides()); }
  const char* typestr() const { return a_.integer ? "<i4" : "<f4"; }
  const char* dtypeName() const { return a_.integer ? "int32" : "float32"; }
  std::uintptr_t pointer() const { return reinterpret_cast<std::uintptr_t>(a_.data); }
  py::tuple dlpackDevice() const {
    return device_ == Device::Cuda ? py::make_tuple(int(dlpack::kDLCUDA), kCudaDeviceId)
                                   : py::make_tuple(int(dlpack::kDLCPU), 0);
  }

 private:
  SharedArray a_;
  Device device_;
  long long stepIndex_;
  std::uint64_t generation_;
  std::shared_ptr<ArrayGeneration> current_;
  py::object owner_;
};

py::dict arrayInterface(const DeviceArray& d, bool cuda) {
  d.check();
  const bool onCuda = d.device() == Device::Cuda;
  if (cuda != onCuda)
    throw py::attribute_error(onCuda ? "a GPU array has no __array_interface__: use __cuda_array_interface__, "
                                       "DLPack (torch.from_dlpack, cupy.from_dlpack) or Simulation.get() for a copy"
                                     : "a CPU array has no __cuda_array_interface__: use numpy() or __array_interface__");
  py::dict i;
  i["shape"] = d.shape();
  i["typestr"] = d.typestr();
  i["data"] = py::make_tuple(d.pointer(), !d.array().writable);
  i["strides"] = d.interfaceStrides();
  i["version"] = 3;
  if (cuda) i["stream"] = kPerThreadDefaultStream;
  return i;
}

// What a DLPack capsule owns: the tensor, its shape and strides, and a
// reference to the handle (and so to the simulation).
struct DLPackHolder {
  dlpack::DLManagedTensor tensor{};
  std::int64_t shape[2] = {0, 0};
  std::int64_t strides[2] = {0, 0};
  PyObject* handle = nullptr;
};

void dlpackDeleter(dlpack::DLManagedTensor* self) {
  auto* holder = static_cast<DLPackHolder*>(self->manager_ctx);
  // Consumers may free a tensor on any thread, with or without the GIL.
  if (Py_IsInitialized()) {
    const PyGILState_STATE state = PyGILState_Ensure();
    Py_XDECREF(holder->handle);
    PyGILState_Release(state);
  }
  delete holder;
}

void capsuleDestructor(PyObject* capsule) {
  // A consumer renames the capsule it takes ("used_dltensor") and calls the
  // deleter itself; one never taken is freed here.
  if (PyCapsule_IsValid(capsule, "dltensor")) {
    auto* t = static_cast<dlpack::DLManagedTensor*>(PyCapsule_GetPointer(capsule, "dltensor"));
    if (t && t->deleter) t->deleter(t);
  }
}

// __dlpack__(*, stream, max_version, dl_device, copy). Whatever max_version
// asks, the capsule is an unversioned "dltensor" (DLPack 0.x), which the
// protocol lets a producer return and every consumer reads.
py::capsule dlpackCapsule(const py::object& self, const py::object& stream, const py::object& /*maxVersion*/,
                          const py::object& dlDevice, const py::object& copy) {
  const DeviceArray& d = self.cast<const DeviceArray&>();
  d.check();
  if (!copy.is_none() && copy.cast<bool>())
    throw py::buffer_error("device_arrays() share the simulation's memory and never copy: use Simulation.get()");
  if (!dlDevice.is_none() && !dlDevice.equal(d.dlpackDevice()))
    throw py::buffer_error("this array lives on " + py::repr(d.dlpackDevice()).cast<std::string>() +
                           " and cannot be exported to another device");
  if (d.device() == Device::Cuda && !stream.is_none()) {
    const long long s = stream.cast<long long>();
    // None and 1 (the legacy default stream, which waits for Soak's blocking
    // stream by itself) and -1 (no synchronisation) need nothing; any other
    // stream, 2 of another thread included, must see the step's work done:
    // the host waits for it.
    if (s == 0) throw py::value_error("__dlpack__: stream 0 is ambiguous (use 1 for the legacy default stream)");
    if (s != kLegacyDefaultStream && s != -1) {
      py::gil_scoped_release release;
      synchronize(Device::Cuda);
    }
  }
  const SharedArray& a = d.array();
  auto* holder = new DLPackHolder;
  dlpack::DLTensor& t = holder->tensor.dl_tensor;
  t.data = a.data;
  t.device = d.device() == Device::Cuda ? dlpack::DLDevice{dlpack::kDLCUDA, kCudaDeviceId}
                                        : dlpack::DLDevice{dlpack::kDLCPU, 0};
  t.ndim = a.columns ? 2 : 1;
  t.dtype = {a.integer ? std::uint8_t(dlpack::kDLInt) : std::uint8_t(dlpack::kDLFloat), 32, 1};
  holder->shape[0] = a.rows;
  holder->shape[1] = a.columns;
  holder->strides[0] = a.rowStride;
  holder->strides[1] = 1;
  t.shape = holder->shape;
  t.strides = holder->strides;
  t.byte_offset = 0;
  holder->handle = self.ptr();
  Py_INCREF(holder->handle);
  holder->tensor.manager_ctx = holder;
  holder->tensor.deleter = dlpackDeleter;
  PyObject* capsule = PyCapsule_New(&holder->tensor, "dltensor", capsuleDestructor);
  if (!capsule) {
    dlpackDeleter(&holder->tensor);
    throw py::error_already_set();
  }
  return py::reinterpret_steal<py::capsule>(capsule);
}

py::object numpyView(const py::object& self) {
  const DeviceArray& d = self.cast<const DeviceArray&>();
  d.check();
  if (d.device() == Device::Cuda)
    throw py::type_error("'" + d.array().name + "' lives on the GPU: share it with torch.from_dlpack(h) or "
                         "cupy.asarray(h), or copy it to the host with Simulation.get('" + d.array().name + "')");
  return py::module_::import("numpy").attr("asarray")(self);  // through __array_interface__: a view
}

}  // namespace

void addDeviceArrayClass(py::module_& m) {
  static py::exception<StaleArrayError> staleError(m, "StaleArrayError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const StaleArrayError& e) {
      staleError(e.what());
    }
  });

  py::class_<DeviceArray>(m, "DeviceArray", R"(One of a simulation's own arrays, shared without a copy.

From Simulation.device_arrays(). On the GPU it implements
__cuda_array_interface__ (v3) and DLPack (torch.from_dlpack, cupy.asarray,
cupy.from_dlpack, jax.dlpack); on the CPU __array_interface__ and DLPack
(numpy()/numpy.asarray, numpy.from_dlpack). Slot order, as get().

Valid until the simulation steps, runs or closes: then its arrays are
reordered and may move, and any use of the handle raises StaleArrayError.
Arrays made from it (tensors, numpy views) share the memory and are not
checked: drop them before the next step.)")
      .def_property_readonly("name", [](const DeviceArray& d) { return d.array().name; })
      .def_property_readonly("shape", &DeviceArray::shape)
      .def_property_readonly("dtype", [](const DeviceArray& d) { return std::string(d.dtypeName()); })
      .def_property_readonly("strides", &DeviceArray::byteStrides, "Strides in bytes.")
      .def_property_readonly("device", [](const DeviceArray& d) { return std::string(deviceName(d.device())); })
      .def_property_readonly("ptr", [](const DeviceArray& d) { d.check(); return d.pointer(); },
                             "The address of the first element (a device pointer on the GPU).")
      .def_property_readonly("writable", [](const DeviceArray& d) { return d.array().writable; },
                             "position, velocity and the channels; the others are read-only.")
      .def_property_readonly("step_index", &DeviceArray::stepIndex, "The step the handle was made at.")
      .def_property_readonly("valid", &DeviceArray::valid, "False once the simulation has stepped, run or closed.")
      .def_property_readonly("__cuda_array_interface__", [](const DeviceArray& d) { return arrayInterface(d, true); })
      .def_property_readonly("__array_interface__", [](const DeviceArray& d) { return arrayInterface(d, false); })
      .def("__dlpack__", &dlpackCapsule, py::kw_only(), py::arg("stream") = py::none(),
           py::arg("max_version") = py::none(), py::arg("dl_device") = py::none(), py::arg("copy") = py::none())
      .def("__dlpack_device__", [](const DeviceArray& d) { d.check(); return d.dlpackDevice(); })
      .def("numpy", &numpyView, "On the CPU: a numpy view of the array (writable where the array is).")
      .def("__array__",
           [](const py::object& self, const py::object& dtype, const py::object&) {
             py::object view = numpyView(self);
             return dtype.is_none() ? view : view.attr("astype")(dtype);
           },
           py::arg("dtype") = py::none(), py::kw_only(), py::arg("copy") = py::none())
      .def("__repr__", [](const DeviceArray& d) {
        return "<soak.DeviceArray '" + d.array().name + "' " + d.dtypeName() + " " +
               py::repr(d.shape()).cast<std::string>() + " on " + deviceName(d.device()) + ", step " +
               std::to_string(d.stepIndex()) + (d.valid() ? "" : ", stale") + ">";
      });
}

py::dict makeDeviceArrays(const std::vector<SharedArray>& arrays, Device device, long long stepIndex,
                          std::uint64_t generation, const std::shared_ptr<ArrayGeneration>& current,
                          const py::object& owner) {
  py::dict out;
  for (const SharedArray& a : arrays)
    out[py::str(a.name)] = py::cast(DeviceArray(a, device, stepIndex, generation, current, owner));
  return out;
}

}  // namespace soak
