"""The soak Python module: loading, stepping, arrays, runs, errors.

Run by ctest (python_soak_module) with PYTHONPATH at the built module and
SOAK_BINARY, SOAK_SOURCE_DIR set; or by hand:
    PYTHONPATH=build/release/python SOAK_SOURCE_DIR=. SOAK_BINARY=build/release/bin/soak \\
        python3 -m pytest Tests/Python
"""
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import soak

SOURCE = os.environ.get("SOAK_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SCENES = os.path.join(SOURCE, "Scenes")

FALLING = """<Scene><Simulation timeStep="0.01"/><Water spacing="0.05"/>
<WaterBlock min="-0.2 1 -0.2" max="0.2 1.2 0.2"/></Scene>"""

WET_SHEET = """<Scene><Simulation timeStep="0.01"/>
<Cloth name="sheet" origin="-0.3 0.5 -0.3" axisU="1 0 0" axisV="0 0 1" width="0.6" height="0.6" cellsU="20"
       cellsV="20" pinCorners="u0v0 u1v0 u0v1 u1v1"/>
<WaterBlock min="-0.1 0.53 -0.1" max="0.1 0.63 0.1"/><WetCloth/></Scene>"""


def test_loads_a_scene_file_and_an_xml_string():
    sim = soak.Simulation(os.path.join(SCENES, "fig7_small.xml"), device="cpu")
    assert sim.device == "cpu"
    assert sim.particle_count > 0
    assert sim.cloth_names() == ["sheet"]
    assert "saturation" in sim.fields()
    other = soak.Simulation(xml=FALLING, device="cpu")
    assert other.time_step == pytest.approx(0.01)


def test_overrides_have_set_semantics_and_errors_carry_file_line_and_suggestion():
    sim = soak.Simulation(xml=FALLING, device="cpu", overrides={"Water.spacing": 0.1, "Simulation.gravity": [0, -5, 0]})
    coarse = soak.Simulation(xml=FALLING, device="cpu")
    assert sim.particle_count < coarse.particle_count  # a coarser spacing: fewer particles
    with pytest.raises(soak.InputError) as bad_name:
        soak.Simulation(xml=FALLING, device="cpu", overrides={"Water.spacng": 0.1})
    assert "did you mean 'spacing'" in str(bad_name.value)
    with pytest.raises(soak.InputError) as bad_line:
        soak.Simulation(xml="<Scene>\n<Water\n spacing='-1'/></Scene>", device="cpu")
    assert "<xml string>:2" in str(bad_line.value) or "<xml string>:3" in str(bad_line.value)
    assert issubclass(soak.InputError, ValueError)
    with pytest.raises(soak.InputError) as missing:
        soak.Simulation("/nonexistent/scene.xml", device="cpu")
    assert "/nonexistent/scene.xml" in str(missing.value)


def test_step_and_advance_move_time_and_water_falls_freely():
    sim = soak.Simulation(xml=FALLING, device="cpu", overrides={"Simulation.gravity": [0, -9.81, 0]})
    y0 = sim.get("position")[:, 1].mean()
    sim.step(10)
    assert sim.step_index == 10
    assert sim.time == pytest.approx(0.1)
    taken = sim.advance(0.05)
    assert taken == 5 and sim.time == pytest.approx(0.15)
    # Free fall for 0.15 s: the block's centre drops g t^2 / 2 = 0.110 m (PBD's
    # symplectic Euler drops g dt^2 n(n+1)/2 = 0.118 m).
    drop = y0 - sim.get("position")[:, 1].mean()
    assert drop == pytest.approx(0.5 * 9.81 * 0.01 ** 2 * 15 * 16, rel=0.02)
    assert sim.get("velocity")[:, 1].mean() == pytest.approx(-9.81 * 0.15, rel=0.02)


def test_water_budget_is_conserved_while_the_cloth_wets():
    sim = soak.Simulation(xml=WET_SHEET, device="cpu")
    start = sim.water_budget()
    assert start["held"] == 0.0
    sim.step(60)
    budget = sim.water_budget()
    assert budget["held"] > 0.05 * start["total"]  # the sheet took water
    assert budget["total"] == pytest.approx(start["total"], rel=1e-5)
    stats = sim.stats()
    assert stats["water_particles"] < 2000 and "max_saturation" in stats


def test_arrays_are_numpy_in_the_documented_orders():
    sim = soak.Simulation(xml=WET_SHEET, device="cpu")
    sim.step(3)
    n = sim.particle_count
    pos, phase, ident = sim.get("position"), sim.get("phase"), sim.get("id")
    assert pos.shape == (n, 3) and pos.dtype == np.float32
    assert phase.dtype == np.int32 and ident.shape == (n,)
    water = sim.water()
    assert np.all(np.diff(water["id"]) > 0)  # by id
    assert len(water["id"]) == np.count_nonzero(phase == 0)
    sheet = sim.cloth("sheet")
    assert sheet["position"].shape == (441, 3)
    assert sheet["triangles"].shape == (800, 3) and sheet["triangles"].max() == 440
    # Vertex order: vertex k of the sheet is the slot whose id is k (the sheet's first vertex is 0).
    cloth_slots = np.flatnonzero(phase == 1)
    k = 17
    slot = cloth_slots[np.flatnonzero(ident[cloth_slots] == k)[0]]
    assert np.array_equal(sheet["position"][k], pos[slot])


def test_writes_reach_the_simulation():
    sim = soak.Simulation(xml=WET_SHEET, device="cpu")
    # Held water written on one vertex shows up in the budget.
    held = np.zeros(441, dtype=np.float32)
    held[220] = 0.01
    sim.set_cloth("sheet", "held_water", held)
    assert sim.water_budget()["held"] == pytest.approx(0.01, rel=1e-6)
    # A pinned corner moved by hand stays where it was put: pinned vertices are scripted.
    pos = sim.cloth("sheet")["position"].copy()
    pos[0] += np.array([0.0, 0.2, 0.0], dtype=np.float32)
    sim.set_cloth("sheet", "position", pos)
    sim.step(5)
    assert np.allclose(sim.cloth("sheet")["position"][0], pos[0], atol=1e-6)
    # Velocities set to zero and one step: free water gains g dt downwards.
    sim.set("velocity", np.zeros((sim.particle_count, 3)))  # float64 is converted
    sim.step(1)
    free = sim.water()["velocity"]
    assert np.median(free[:, 1]) == pytest.approx(-9.81 * 0.01, rel=0.05)


def test_misuse_raises_exceptions_not_crashes():
    sim = soak.Simulation(xml=WET_SHEET, device="cpu")
    with pytest.raises(ValueError, match="read-only"):
        sim.set("mass", np.ones(sim.particle_count))
    with pytest.raises(ValueError, match="no field 'colour'"):
        sim.get("colour")
    with pytest.raises(ValueError, match="takes"):
        sim.set("position", np.zeros((3, 3)))
    with pytest.raises(ValueError, match="takes"):
        sim.set("velocity", np.zeros(sim.particle_count))
    with pytest.raises(TypeError):
        sim.set("saturation", np.array(["a"] * sim.particle_count))
    with pytest.raises(ValueError, match="no cloth 'shirt'"):
        sim.cloth("shirt")
    with pytest.raises(ValueError):
        sim.step(-1)
    with pytest.raises(ValueError):
        soak.Simulation(device="cpu")  # neither a path nor xml
    with pytest.raises(ValueError, match="unknown device"):
        soak.Simulation(xml=FALLING, device="tpu")
    sim.close()
    with pytest.raises(RuntimeError, match="closed"):
        sim.step()
    with pytest.raises(RuntimeError, match="closed"):
        sim.get("position")
    with soak.Simulation(xml=FALLING, device="cpu") as s:
        s.step()
    with pytest.raises(RuntimeError, match="closed"):
        s.time


def test_cuda_is_refused_cleanly_without_a_gpu():
    if soak.cuda_available():
        pytest.skip("a GPU is present")
    with pytest.raises(soak.DeviceError):
        soak.Simulation(xml=FALLING, device="cuda")


def test_stepping_releases_the_gil():
    sim = soak.Simulation(xml=WET_SHEET, device="cpu")
    done = threading.Event()

    def work():
        sim.step(150)
        done.set()

    t = threading.Thread(target=work)
    t.start()
    spins = 0
    while not done.is_set():
        spins += 1  # Python runs here only while the step has let go of the GIL
    t.join()
    assert sim.step_index == 150
    assert spins > 10000


def test_stage_times_after_profiled_steps():
    sim = soak.Simulation(xml=WET_SHEET, device="cpu")
    sim.step(4, profile=True)
    times = sim.stage_times()
    assert {"predict", "fluid.solve", "cloth.solve", "wet.absorb"} <= set(times)
    assert all(v >= 0.0 for v in times.values()) and sum(times.values()) > 0.0


def test_run_writes_what_soak_run_writes(tmp_path):
    scene = os.path.join(SCENES, "fig7_small.xml")
    cli = tmp_path / "cli"
    py = tmp_path / "py"
    subprocess.run([os.environ["SOAK_BINARY"], "run", scene, "--device", "cpu", "--frames", "4", "-o", str(cli),
                    "--quiet"], check=True)
    result = soak.Simulation(scene, device="cpu").run(str(py), frames=4)
    assert result["frames_written"] == 5
    files = sorted(p.relative_to(cli) for p in cli.rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(py) for p in py.rglob("*") if p.is_file())
    for f in files:
        if f.name == "stats.csv":  # step_ms, the last column, is a timing
            a = [line.rsplit(",", 1)[0] for line in (cli / f).read_text().splitlines()]
            b = [line.rsplit(",", 1)[0] for line in (py / f).read_text().splitlines()]
            assert a == b
        elif f.suffix in (".vtu", ".vtp", ".pvd", ".xml"):
            assert (cli / f).read_bytes() == (py / f).read_bytes(), f
    stepped = soak.Simulation(scene, device="cpu")
    stepped.step()
    with pytest.raises(RuntimeError, match="initial state"):
        stepped.run(str(tmp_path / "again"), frames=1)


def test_run_never_replaces_a_run_unless_asked(tmp_path):
    scene = os.path.join(SCENES, "fig7_small.xml")
    out = tmp_path / "run"
    soak.Simulation(scene, device="cpu").run(str(out), frames=3, checkpoint_every=1)
    before = (out / "water.pvd").read_bytes()
    with pytest.raises(soak.InputError, match="already holds a Soak run"):
        soak.Simulation(scene, device="cpu").run(str(out), frames=1)
    assert (out / "water.pvd").read_bytes() == before
    (out / "notes.txt").write_text("mine")
    result = soak.Simulation(scene, device="cpu").run(str(out), frames=1, overwrite=True)
    assert result["frames_written"] == 2
    assert not (out / "checkpoint.soak").exists()  # the earlier run's checkpoint is gone
    assert sorted(p.name for p in (out / "water").iterdir()) == ["water_000000.vtu", "water_000001.vtu"]
    assert (out / "notes.txt").read_text() == "mine"  # what is not a run's stays
