"""The distribution's core metadata (METADATA 2.1) and WHEEL file. The
version is the CMake project's, read from the top-level CMakeLists.txt."""
import os
import re

from . import tags

DIST_NAME = "soak"
SUMMARY = "Position-based dynamics with cloth wetting (Shao et al. 2017): scenes, steps and arrays from Python"
REQUIRES_PYTHON = ">=3.9"
# numpy is the one run-time requirement; the C++ libraries the module links
# (VTK, OpenVDB, pugixml, ...) are the machine's own (Demos/scripts/install-deps.sh).
REQUIRES = ["numpy"]


def version(source_dir=None) -> str:
    path = os.path.join(source_dir or os.getcwd(), "CMakeLists.txt")
    with open(path, encoding="utf-8") as f:
        match = re.search(r"project\(\s*Soak\s+VERSION\s+([0-9][0-9.]*)", f.read())
    if not match:
        raise RuntimeError("soak_build: no 'project(Soak VERSION x.y.z' in %s" % path)
    return match.group(1)


def dist_info_name() -> str:
    return "%s-%s.dist-info" % (DIST_NAME, version())


def metadata_text() -> str:
    lines = [
        "Metadata-Version: 2.1",
        "Name: " + DIST_NAME,
        "Version: " + version(),
        "Summary: " + SUMMARY,
        "Requires-Python: " + REQUIRES_PYTHON,
    ]
    lines += ["Requires-Dist: " + r for r in REQUIRES]
    return "\n".join(lines) + "\n"


def wheel_text(tag) -> str:
    return "Wheel-Version: 1.0\nGenerator: soak_build %s\nRoot-Is-Purelib: false\nTag: %s\n" % (version(), tag)


def write_dist_info(directory) -> str:
    """prepare_metadata_for_build_*: the .dist-info folder without RECORD."""
    name = dist_info_name()
    path = os.path.join(directory, name)
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, "METADATA"), "w", encoding="utf-8") as f:
        f.write(metadata_text())
    with open(os.path.join(path, "WHEEL"), "w", encoding="utf-8") as f:
        f.write(wheel_text(tags.wheel_tag()))
    return name
