"""Soak's PEP 517 build backend (PEP 660 for editable installs). Standard
library only, so that pip's isolated build needs nothing from an index:
pyproject.toml names it with `requires = []` and `backend-path`.

It configures and builds the project's CMake for the interpreter running
it (settings.py: the build folder, CUDA or not) and packs the module, the
core library and the plugins into a wheel for that interpreter. Doc/python.md
says how to use it.
"""
import os

from . import cmake, layout, metadata, settings, sdist, tags
from .wheel import WheelWriter

__all__ = [
    "build_wheel", "build_editable", "build_sdist", "get_requires_for_build_wheel",
    "get_requires_for_build_editable", "get_requires_for_build_sdist",
    "prepare_metadata_for_build_wheel", "prepare_metadata_for_build_editable",
]


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return metadata.write_dist_info(metadata_directory)


def prepare_metadata_for_build_editable(metadata_directory, config_settings=None):
    return metadata.write_dist_info(metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    s = settings.read(config_settings)
    build_dir = cmake.build(s)
    wheel = WheelWriter(wheel_directory, tags.wheel_tag())
    for arcname, path in layout.files(build_dir):
        wheel.add_file(arcname, path)
    return wheel.finish()


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    """A wheel whose .pth puts the build folder's python/ on sys.path: the
    module there finds the core library and the plugins in the build's lib/.
    After a change to the C++ sources, `pip install -e .` again (or
    `cmake --build BUILD --target soak_python`) rebuilds it."""
    s = settings.read(config_settings)
    build_dir = cmake.build(s)
    module_dir = os.path.dirname(layout.module_path(build_dir))
    wheel = WheelWriter(wheel_directory, tags.wheel_tag())
    wheel.add_bytes("__editable__.%s-%s.pth" % (metadata.DIST_NAME, metadata.version()),
                    (module_dir + "\n").encode("utf-8"))
    return wheel.finish()


def build_sdist(sdist_directory, config_settings=None):
    return sdist.write(sdist_directory)
