"""`pip install .`, `pip wheel .` and `pip install -e .` into virtual
environments over the Python that ctest names, offline, through the in-tree
backend (pyproject.toml), then soak used from another folder.

Run by ctest (python_pip_install) with:
    SOAK_SOURCE_DIR     the source tree
    SOAK_PIP_PYTHON     the interpreter the venvs are made over (Debian's python3)
    SOAK_PIP_BUILD_DIR  the CMake build folder the backend reuses (the suite's own)
    SOAK_BINARY         the `soak` program, whose frames the venv's module must match
    SOAK_PIP_WORK       a folder for the venvs and runs (emptied first)
Nothing is skipped: a missing venv module, pip or numpy fails the test.
"""
import base64
import csv
import hashlib
import io
import os
import shutil
import subprocess
import sys
import zipfile

import pytest

SOURCE = os.path.abspath(os.environ["SOAK_SOURCE_DIR"])
PYTHON = os.environ["SOAK_PIP_PYTHON"]
BUILD = os.path.abspath(os.environ["SOAK_PIP_BUILD_DIR"])
WORK = os.path.abspath(os.environ["SOAK_PIP_WORK"])
SOAK = os.environ["SOAK_BINARY"]

SCENE = """<Scene><Simulation timeStep="0.01" frameRate="20"/>
<Cloth name="sheet" origin="-0.3 0.5 -0.3" axisU="1 0 0" axisV="0 0 1" width="0.6" height="0.6" cellsU="16"
       cellsV="16" pinCorners="u0v0 u1v0"/>
<WaterBlock min="-0.1 0.53 -0.1" max="0.1 0.63 0.1"/><WetCloth/></Scene>
"""
FRAMES = 3  # 5 steps a frame

# Run in the venv, from a folder outside the source: steps the scene to each
# frame and prints the cloth's positions and saturation (numpy's text).
STEPPER = r"""
import sys, numpy as np, soak
scene, frames = sys.argv[1], int(sys.argv[2])
sim = soak.Simulation(scene, device="cpu")
steps_per_frame = round(1.0 / (sim.frame_rate * sim.time_step))
out = {"module": soak.__file__}
for k in range(frames + 1):
    if k:
        sim.step(steps_per_frame)
    c = sim.cloth("sheet")
    out["position_%d" % k] = c["position"]
    out["saturation_%d" % k] = c["saturation"]
np.savez(sys.argv[3], **out)
with open("/proc/self/maps") as f:
    print("\n".join(sorted({l.split()[-1] for l in f if "libsoak_" in l})))
"""

# Reads the cloth frames `soak run` wrote (VTK's readers, Debian's python3-paraview).
READER = r"""
import sys, numpy as np
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy
out = {}
for k in range(int(sys.argv[2]) + 1):
    r = vtkXMLPolyDataReader()
    r.SetFileName("%s/cloth_sheet/cloth_sheet_%06d.vtp" % (sys.argv[1], k))
    r.Update()
    d = r.GetOutput()
    out["position_%d" % k] = vtk_to_numpy(d.GetPoints().GetData())
    out["saturation_%d" % k] = vtk_to_numpy(d.GetPointData().GetArray("saturation"))
np.savez(sys.argv[3], **out)
"""


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, "%s\n%s\n%s" % (" ".join(map(str, command)), result.stdout, result.stderr)
    return result.stdout


def make_venv(name):
    path = os.path.join(WORK, name)
    shutil.rmtree(path, ignore_errors=True)
    run([PYTHON, "-m", "venv", "--system-site-packages", path])
    python = os.path.join(path, "bin", "python")
    assert os.path.exists(python)
    return path, python


def pip(python, *args):
    return run([python, "-m", "pip", "--disable-pip-version-check", "--no-input", *args],
               cwd=WORK, env=dict(os.environ, PIP_NO_INDEX="1"))


def config():
    return ["--config-settings=build-dir=" + BUILD]


@pytest.fixture(scope="module")
def cli_frames():
    os.makedirs(WORK, exist_ok=True)
    scene = os.path.join(WORK, "sheet.xml")
    with open(scene, "w") as f:
        f.write(SCENE)
    out = os.path.join(WORK, "cli")
    run([SOAK, "run", scene, "--device", "cpu", "--frames", str(FRAMES), "-o", out, "--overwrite", "--quiet"])
    frames = os.path.join(WORK, "cli.npz")
    run([PYTHON, "-c", READER, out, str(FRAMES), frames])
    import numpy as np
    return scene, dict(np.load(frames))


def step_in(python, scene, name):
    """Runs STEPPER with `python` from a folder of its own; returns its arrays and the libsoak_ files it mapped."""
    import numpy as np
    elsewhere = os.path.join(WORK, "elsewhere")
    os.makedirs(elsewhere, exist_ok=True)
    npz = os.path.join(WORK, name + ".npz")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LD_LIBRARY_PATH")}
    mapped = run([python, "-c", STEPPER, scene, str(FRAMES), npz], cwd=elsewhere, env=env).split()
    arrays = dict(np.load(npz))
    return arrays, mapped


def assert_matches_cli(arrays, frames):
    import numpy as np
    for k in range(FRAMES + 1):
        for field in ("position", "saturation"):
            key = "%s_%d" % (field, k)
            assert arrays[key].shape == frames[key].shape, key
            assert np.array_equal(arrays[key], frames[key]), (key, np.abs(arrays[key] - frames[key]).max())
    # The comparison means something: the cloth sagged and wetted between the frames.
    assert np.abs(frames["position_%d" % FRAMES] - frames["position_0"]).max() > 1e-3
    assert frames["saturation_%d" % FRAMES].max() > 0.0


def test_pip_install_into_a_venv_matches_soak_run(cli_frames):
    scene, frames = cli_frames
    venv, python = make_venv("venv-install")
    pip(python, "install", *config(), SOURCE)
    shown = pip(python, "show", "-f", "soak")
    assert "Requires: numpy" in shown
    arrays, mapped = step_in(python, scene, "install")
    site = os.path.join(venv, "lib")
    assert str(arrays["module"]).startswith(site), arrays["module"]
    # The core library and both plugins came from the installed package, not the build tree.
    names = sorted(os.path.basename(m) for m in mapped)
    assert names == ["libsoak_AirDrag.so", "libsoak_WetCloth.so", "libsoak_core.so"], mapped
    assert all(m.startswith(site) and "/soak.libs/" in m for m in mapped), mapped
    assert_matches_cli(arrays, frames)
    pip(python, "uninstall", "-y", "soak")
    assert not any("soak" in n for n in os.listdir(os.path.dirname(str(arrays["module"])))
                   if not n.startswith("__")), "uninstall left files behind (RECORD)"


def test_pip_wheel_installs_into_a_second_venv(cli_frames):
    scene, frames = cli_frames
    dist = os.path.join(WORK, "dist")
    shutil.rmtree(dist, ignore_errors=True)
    pip(PYTHON, "wheel", "--no-deps", "-w", dist, *config(), SOURCE)  # the base Python's pip: no venv needed
    wheels = os.listdir(dist)
    assert len(wheels) == 1
    tag = run([PYTHON, "-c", "import sys, sysconfig; print('cp%d%d' % sys.version_info[:2], "
                             "sysconfig.get_platform().replace('-', '_').replace('.', '_'))"]).split()
    assert wheels[0] == "soak-%s-%s-%s-%s.whl" % (version(), tag[0], tag[0], tag[1])
    check_wheel(os.path.join(dist, wheels[0]))
    venv, python = make_venv("venv-wheel")
    pip(python, "install", os.path.join(dist, wheels[0]))
    arrays, mapped = step_in(python, scene, "wheel")
    assert str(arrays["module"]).startswith(venv)
    assert len(mapped) == 3 and all(m.startswith(venv) for m in mapped), mapped
    assert_matches_cli(arrays, frames)


def test_editable_install_uses_the_build_folder(cli_frames):
    scene, frames = cli_frames
    venv, python = make_venv("venv-editable")
    pip(python, "install", *config(), "-e", SOURCE)
    arrays, mapped = step_in(python, scene, "editable")
    assert os.path.dirname(str(arrays["module"])) == os.path.join(BUILD, "python")
    assert all(m.startswith(os.path.join(BUILD, "lib")) for m in mapped), mapped
    assert_matches_cli(arrays, frames)


def version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        text = f.read()
    return text.split("project(Soak VERSION ", 1)[1].split()[0]


def check_wheel(path):
    """PEP 427: every file in RECORD with its sha256 and size, the module, the core library and the plugins."""
    with zipfile.ZipFile(path) as z:
        names = z.namelist()
        info = "soak-%s.dist-info" % version()
        record = list(csv.reader(io.StringIO(z.read(info + "/RECORD").decode())))
        assert sorted(r[0] for r in record) == sorted(names)
        for name, digest, size in record:
            if name == info + "/RECORD":
                assert digest == "" and size == ""
                continue
            data = z.read(name)
            expected = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            assert digest == "sha256=" + expected and int(size) == len(data), name
        assert "Requires-Dist: numpy" in z.read(info + "/METADATA").decode()
        assert "Root-Is-Purelib: false" in z.read(info + "/WHEEL").decode()
        assert {"soak.libs/libsoak_core.so", "soak.libs/soak-plugins/libsoak_WetCloth.so",
                "soak.libs/soak-plugins/libsoak_AirDrag.so"} <= set(names)
        assert any(n.startswith("soak.cpython-") and n.endswith(".so") for n in names)


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))
