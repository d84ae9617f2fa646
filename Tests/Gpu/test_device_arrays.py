"""Simulation.device_arrays() on the GPU, shared with PyTorch and CuPy
without copies. Needs a GPU, torch and cupy: without any of them it fails.

Run on the GPU machine with the module built for its Python (Doc/python.md,
"Sharing device arrays"), e.g.
    PYTHONPATH=BUNDLE/bin LD_LIBRARY_PATH=BUNDLE/lib python3 -m pytest -q Tests/Gpu/test_device_arrays.py
"""
import cupy  # required: a missing one fails the test, never skips it
import numpy as np
import pytest
import torch

import soak

SHEET = """<Scene><Simulation timeStep="0.01"/>
<Cloth name="sheet" origin="-0.3 0.5 -0.3" axisU="1 0 0" axisV="0 0 1" width="0.6" height="0.6" cellsU="20"
       cellsV="20" pinCorners="u0v0 u1v0 u0v1 u1v1"/>
<WaterBlock min="-0.1 0.53 -0.1" max="0.1 0.63 0.1"/><WetCloth/></Scene>"""


@pytest.fixture
def sim():
    assert soak.cuda_available(), "this test needs the CUDA backend and a GPU"
    assert torch.cuda.is_available(), "this test needs PyTorch with CUDA"
    s = soak.Simulation(xml=SHEET, device="cuda")
    assert s.device == "cuda"
    s.step(3)
    return s


def test_torch_and_cupy_read_the_simulations_memory(sim):
    arrays = sim.device_arrays()
    h = arrays["position"]
    assert h.__dlpack_device__() == (2, 0)
    cai = h.__cuda_array_interface__
    assert cai["version"] == 3 and cai["typestr"] == "<f4" and cai["shape"] == (sim.particle_count, 3)
    assert cai["strides"] == (16, 4) and cai["data"] == (h.ptr, False) and cai["stream"] == 2
    t = torch.from_dlpack(h)
    assert t.is_cuda and t.data_ptr() == h.ptr and t.shape == (sim.particle_count, 3)
    c = cupy.asarray(h)  # through __cuda_array_interface__
    assert c.data.ptr == h.ptr
    c2 = cupy.from_dlpack(arrays["velocity"])
    assert c2.data.ptr == arrays["velocity"].ptr
    for name, handle in arrays.items():
        shared = torch.from_dlpack(handle)
        assert shared.data_ptr() == handle.ptr, name
        assert np.array_equal(shared.cpu().numpy(), sim.get(name)), name
        assert np.array_equal(cupy.asnumpy(cupy.asarray(handle)), sim.get(name)), name


def test_a_write_through_torch_moves_the_cloth(sim):
    arrays = sim.device_arrays()
    phase, ident = torch.from_dlpack(arrays["phase"]), torch.from_dlpack(arrays["id"])
    slot = int(torch.nonzero((phase == 1) & (ident == 220))[0, 0])
    position = torch.from_dlpack(arrays["position"])
    before = sim.cloth("sheet")["position"][220].copy()
    position[slot, 1] += 0.25  # on the legacy default stream, which Soak's stream waits for
    written = sim.cloth("sheet")["position"]
    assert written[220][1] == pytest.approx(before[1] + 0.25, abs=1e-6)  # in the simulation's memory
    # The steps go on from the written state: as from the same write made with set_cloth(), and not as from
    # the untouched state (GPU runs agree within round-off, not bit for bit).
    same, untouched = soak.Simulation(xml=SHEET, device="cuda"), soak.Simulation(xml=SHEET, device="cuda")
    for s in (same, untouched):
        s.step(3)
    same.set_cloth("sheet", "position", written)
    for s in (sim, same, untouched):
        s.step(2)
    moved = sim.cloth("sheet")["position"]
    assert np.allclose(moved, same.cloth("sheet")["position"], atol=1e-4)
    assert np.abs(moved - untouched.cloth("sheet")["position"]).max() > 1e-3


def test_a_handle_used_after_a_step_raises(sim):
    h = sim.device_arrays()["saturation"]
    sim.step(1)
    with pytest.raises(soak.StaleArrayError):
        torch.from_dlpack(h)
    with pytest.raises(soak.StaleArrayError):
        cupy.asarray(h)
    with pytest.raises(soak.StaleArrayError):
        h.__cuda_array_interface__
    with pytest.raises(TypeError):
        sim.device_arrays()["saturation"].numpy()  # GPU memory is no numpy view


def test_saturation_each_step_on_the_gpu_equals_the_copies(sim):
    for _ in range(5):
        sim.step(2)
        saturation = torch.from_dlpack(sim.device_arrays()["saturation"])
        host = sim.get("saturation")
        assert float(saturation.sum()) == pytest.approx(float(host.astype(np.float64).sum()), rel=1e-5, abs=1e-7)
        assert np.array_equal(saturation.cpu().numpy(), host)
    assert float(saturation.max()) > 0.0  # the sheet is wet: the sums compared something


def test_another_stream_sees_the_step_done(sim):
    stream = torch.cuda.Stream()
    with torch.cuda.stream(stream):
        sim.step(4)  # queued on Soak's stream; __dlpack__(stream=...) below waits for it
        position = torch.from_dlpack(sim.device_arrays()["position"])
        copy = position.clone()
    stream.synchronize()
    assert np.array_equal(copy.cpu().numpy(), sim.get("position"))
