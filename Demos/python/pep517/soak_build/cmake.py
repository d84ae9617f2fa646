"""Runs the project's CMake for the interpreter that runs the build.

A build folder that this backend configured (it holds MARKER) is
reconfigured when the interpreter or the settings change, and otherwise
only built again, incrementally. A build folder configured by hand (say
build/release) is used as it is, when it was configured for this
interpreter: the backend never changes its options.
"""
import os
import shutil
import subprocess
import sys

MARKER = "soak-pip-build.txt"
TARGET = "soak_python"  # the module; it depends on the core library and the plugins


def interpreter() -> str:
    # A venv's python is a link to its base interpreter, which has the headers and
    # outlives the venv (a cached path to a deleted venv would break reconfiguring).
    return os.path.realpath(sys.executable)


def _cache(build_dir):
    values = {}
    path = os.path.join(build_dir, "CMakeCache.txt")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith(("#", "//")) or "=" not in line or ":" not in line.split("=", 1)[0]:
                continue
            key, value = line.rstrip("\n").split("=", 1)
            values[key.split(":", 1)[0]] = value
    return values


def _wanted(settings):
    options = {
        "CMAKE_BUILD_TYPE": "Release",
        "SOAK_CUDA": settings.cuda,
        "SOAK_BUILD_TESTS": "OFF",
        "Python_EXECUTABLE": interpreter(),
    }
    if settings.cuda_arch:
        options["CMAKE_CUDA_ARCHITECTURES"] = settings.cuda_arch
    return options


def _run(command, cwd):
    print("soak_build: " + " ".join(command), file=sys.stderr, flush=True)
    subprocess.run(command, cwd=cwd, check=True)


def _cmake():
    cmake = shutil.which("cmake")
    if not cmake:
        raise RuntimeError("soak_build: cmake not found (Debian: apt-get install cmake ninja-build)")
    return cmake


def _same_file(a, b):
    return bool(a) and bool(b) and os.path.realpath(a) == os.path.realpath(b)


def configure(settings):
    """Configures settings.build_dir when needed; returns it."""
    build = settings.build_dir
    cache = _cache(build)
    owned = os.path.exists(os.path.join(build, MARKER))
    wanted = _wanted(settings)
    if cache is not None and not owned:
        built_for = cache.get("SOAK_PYTHON_EXECUTABLE") or cache.get("Python_EXECUTABLE")
        if not _same_file(built_for, interpreter()):
            raise RuntimeError(
                "soak_build: %s was configured for %s, not for %s; give another build-dir "
                "(--config-settings=build-dir=...) or none for the default" % (build, built_for, interpreter())
            )
        return build
    if cache is not None:
        if not _same_file(cache.get("Python_EXECUTABLE"), interpreter()):
            # Another interpreter's FindPython results are cached: start the cache afresh
            # (object files stay, and ninja rebuilds only what the change touches).
            os.remove(os.path.join(build, "CMakeCache.txt"))
            cache = None
        elif all(cache.get(k) == v for k, v in wanted.items()):
            return build
    os.makedirs(build, exist_ok=True)
    command = [_cmake(), "-S", settings.source_dir, "-B", build]
    if cache is None and shutil.which("ninja"):
        command += ["-G", "Ninja"]
    command += ["-D%s=%s" % kv for kv in wanted.items()]
    _run(command, settings.source_dir)
    with open(os.path.join(build, MARKER), "w") as f:
        f.write("Configured by the soak_build PEP 517 backend (Demos/python/pep517); it may reconfigure this folder.\n")
    return build


def build(settings):
    """Builds the module, the core library and the plugins."""
    build_dir = configure(settings)
    command = [_cmake(), "--build", build_dir, "--target", TARGET]
    if settings.jobs:
        command += ["--parallel", settings.jobs]
    elif "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ and not os.path.exists(os.path.join(build_dir, "build.ninja")):
        command += ["--parallel", str(os.cpu_count() or 1)]
    try:
        _run(command, settings.source_dir)
    except subprocess.CalledProcessError:
        cache = _cache(build_dir) or {}
        if "pybind11_DIR" in cache and cache["pybind11_DIR"].endswith("NOTFOUND"):
            raise RuntimeError("soak_build: pybind11 was not found, so there is no module to build "
                               "(Debian: apt-get install pybind11-dev)") from None
        raise
    return build_dir
