"""Simulation.device_arrays() on the CPU: numpy views of the simulation's
own arrays, the DLPack capsule's C layout, and stale handles raising.
(The GPU's side, with PyTorch and CuPy: Tests/Gpu/test_device_arrays.py.)"""
import ctypes
import gc

import numpy as np
import pytest

import soak

SHEET = """<Scene><Simulation timeStep="0.01"/>
<Cloth name="sheet" origin="-0.3 0.5 -0.3" axisU="1 0 0" axisV="0 0 1" width="0.6" height="0.6" cellsU="20"
       cellsV="20" pinCorners="u0v0 u1v0 u0v1 u1v1"/>
<WaterBlock min="-0.1 0.53 -0.1" max="0.1 0.63 0.1"/><WetCloth/></Scene>"""


class DLDevice(ctypes.Structure):
    _fields_ = [("device_type", ctypes.c_int32), ("device_id", ctypes.c_int32)]


class DLDataType(ctypes.Structure):
    _fields_ = [("code", ctypes.c_uint8), ("bits", ctypes.c_uint8), ("lanes", ctypes.c_uint16)]


class DLTensor(ctypes.Structure):
    _fields_ = [("data", ctypes.c_void_p), ("device", DLDevice), ("ndim", ctypes.c_int32), ("dtype", DLDataType),
                ("shape", ctypes.POINTER(ctypes.c_int64)), ("strides", ctypes.POINTER(ctypes.c_int64)),
                ("byte_offset", ctypes.c_uint64)]


class DLManagedTensor(ctypes.Structure):
    _fields_ = [("dl_tensor", DLTensor), ("manager_ctx", ctypes.c_void_p), ("deleter", ctypes.c_void_p)]


def capsule_tensor(capsule):
    """The DLManagedTensor a "dltensor" capsule holds, read with the spec's layout."""
    get = ctypes.pythonapi.PyCapsule_GetPointer
    get.restype, get.argtypes = ctypes.c_void_p, [ctypes.py_object, ctypes.c_char_p]
    valid = ctypes.pythonapi.PyCapsule_IsValid
    valid.restype, valid.argtypes = ctypes.c_int, [ctypes.py_object, ctypes.c_char_p]
    assert valid(capsule, b"dltensor") == 1
    return DLManagedTensor.from_address(get(capsule, b"dltensor"))


def test_handles_are_the_fields_in_slot_order_and_equal_get():
    sim = soak.Simulation(xml=SHEET, device="cpu")
    sim.step(3)
    arrays = sim.device_arrays()
    assert list(arrays) == [f for f in sim.fields() if f != "density"]
    for name, h in arrays.items():
        view = h.numpy()
        assert view.shape == h.shape == sim.get(name).shape, name
        assert view.dtype == sim.get(name).dtype == np.dtype(h.dtype), name
        assert np.array_equal(view, sim.get(name)), name
        assert view.flags.writeable == h.writable, name
        assert h.device == "cpu" and h.__dlpack_device__() == (1, 0) and h.step_index == 3
        assert not hasattr(h, "__cuda_array_interface__")  # a CPU array is not a GPU one
    assert [n for n, h in arrays.items() if h.writable] == ["position", "velocity"] + [
        f for f in sim.fields() if f not in ("position", "velocity", "inverse_mass", "mass", "radius", "density",
                                             "phase", "id")]


def test_views_share_the_simulations_memory():
    sim = soak.Simulation(xml=SHEET, device="cpu")
    arrays = sim.device_arrays()
    position, inverse_mass = arrays["position"], arrays["inverse_mass"]
    # position and inverse_mass are the xyz and w of one float4 array: strided views of it.
    assert position.strides == (16, 4) and inverse_mass.strides == (16,)
    assert inverse_mass.ptr == position.ptr + 12
    view = position.numpy()
    assert view.__array_interface__["data"][0] == position.ptr
    assert np.shares_memory(view, np.asarray(position))
    from_dlpack = np.from_dlpack(position)
    assert from_dlpack.__array_interface__["data"][0] == position.ptr
    assert from_dlpack.strides == (16, 4)


def test_a_write_through_a_view_moves_the_cloth():
    sim = soak.Simulation(xml=SHEET, device="cpu")
    arrays = sim.device_arrays()
    ident, phase = arrays["id"].numpy(), arrays["phase"].numpy()
    slot = int(np.flatnonzero((phase == 1) & (ident == 220))[0])  # the sheet's middle vertex
    arrays["position"].numpy()[slot] += np.float32([0.0, 0.25, 0.0])
    before = sim.cloth("sheet")["position"][220]
    assert before[1] == pytest.approx(0.75, abs=1e-6)  # seen by the simulation's own copies at once
    arrays["saturation"].numpy()[slot] = 0.5
    assert sim.cloth("sheet")["saturation"][220] == pytest.approx(0.5)
    with pytest.raises(ValueError):
        arrays["mass"].numpy()[slot] = 1.0  # a read-only array gives read-only views
    # The step goes on from the written state: as from the same write made with set_cloth(), and not as
    # from the untouched state.
    same, untouched = soak.Simulation(xml=SHEET, device="cpu"), soak.Simulation(xml=SHEET, device="cpu")
    for field in ("position", "saturation"):
        same.set_cloth("sheet", field, sim.cloth("sheet")[field])
    for s in (sim, same, untouched):
        s.step(2)
    moved = sim.cloth("sheet")["position"]
    assert np.array_equal(moved, same.cloth("sheet")["position"])
    assert np.abs(moved - untouched.cloth("sheet")["position"]).max() > 1e-3


def test_a_handle_used_after_a_step_raises():
    sim = soak.Simulation(xml=SHEET, device="cpu")
    arrays = sim.device_arrays()
    h = arrays["position"]
    assert h.valid
    sim.step(1)
    assert not h.valid and "stale" in repr(h)
    for use in (h.numpy, lambda: h.__array_interface__, h.__dlpack__, h.__dlpack_device__, lambda: np.asarray(h),
                lambda: h.ptr, lambda: hasattr(h, "__cuda_array_interface__")):
        with pytest.raises(soak.StaleArrayError, match="call device_arrays"):
            use()
    assert issubclass(soak.StaleArrayError, RuntimeError)
    fresh = sim.device_arrays()["position"]
    assert fresh.valid and fresh.step_index == 1
    assert np.array_equal(fresh.numpy(), sim.get("position"))
    sim.step(0)  # no step: no change
    assert fresh.valid
    sim.close()
    with pytest.raises(soak.StaleArrayError):
        fresh.numpy()


def test_a_run_makes_handles_stale(tmp_path):
    sim = soak.Simulation(xml=SHEET, device="cpu")
    h = sim.device_arrays()["velocity"]
    sim.run(str(tmp_path / "run"), frames=1)
    with pytest.raises(soak.StaleArrayError):
        h.numpy()


def test_the_dlpack_capsule_has_the_specs_layout():
    sim = soak.Simulation(xml=SHEET, device="cpu")
    n = sim.particle_count
    arrays = sim.device_arrays()
    for name, shape, strides, code in (("position", (n, 3), (4, 1), 2), ("phase", (n,), (1,), 0),
                                       ("inverse_mass", (n,), (4,), 2), ("velocity", (n, 3), (3, 1), 2)):
        capsule = arrays[name].__dlpack__()
        t = capsule_tensor(capsule).dl_tensor
        assert (t.device.device_type, t.device.device_id) == (1, 0)
        assert t.ndim == len(shape) and tuple(t.shape[k] for k in range(t.ndim)) == shape, name
        assert tuple(t.strides[k] for k in range(t.ndim)) == strides, name
        assert (t.dtype.code, t.dtype.bits, t.dtype.lanes) == (code, 32, 1)
        assert t.data == arrays[name].ptr and t.byte_offset == 0
        del capsule  # never consumed: its destructor frees it
    with pytest.raises(BufferError):
        arrays["position"].__dlpack__(copy=True)


def test_handles_keep_the_simulation_alive():
    arrays = soak.Simulation(xml=SHEET, device="cpu").device_arrays()
    gc.collect()
    h = arrays["position"]
    assert h.valid
    view = h.numpy()
    assert view.shape[1] == 3 and np.isfinite(view).all() and view[:, 1].max() > 0.4
