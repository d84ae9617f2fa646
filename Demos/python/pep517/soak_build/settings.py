"""What a build is asked for: pip's --config-settings, or environment
variables for frontends that cannot pass them.

    build-dir   SOAK_PIP_BUILD_DIR   the CMake build folder, kept between builds
                                     (default build/pip-<abi tag>, relative to the source)
    cuda        SOAK_PIP_CUDA        auto (default: where nvcc is found), on, off
    cuda-arch   SOAK_PIP_CUDA_ARCH   CMAKE_CUDA_ARCHITECTURES (default 90: H100/H200)
    jobs        SOAK_PIP_JOBS        parallel compile jobs (default: CMake's)
"""
import os
from dataclasses import dataclass
from typing import Optional

from . import tags

_KEYS = {
    "build-dir": "SOAK_PIP_BUILD_DIR",
    "cuda": "SOAK_PIP_CUDA",
    "cuda-arch": "SOAK_PIP_CUDA_ARCH",
    "jobs": "SOAK_PIP_JOBS",
}


@dataclass
class Settings:
    source_dir: str
    build_dir: str
    cuda: str  # AUTO, ON or OFF: SOAK_CUDA's values
    cuda_arch: Optional[str]
    jobs: Optional[str]


def _value(config_settings, key):
    if config_settings and key in config_settings:
        value = config_settings[key]
        if isinstance(value, list):  # given twice: the last one wins
            value = value[-1]
        return str(value)
    return os.environ.get(_KEYS[key]) or None


def read(config_settings) -> Settings:
    unknown = sorted(set(config_settings or {}) - set(_KEYS))
    if unknown:
        raise ValueError(
            "soak_build: unknown config setting(s) %s; known: %s" % (", ".join(unknown), ", ".join(sorted(_KEYS)))
        )
    source = os.path.abspath(os.getcwd())
    build = _value(config_settings, "build-dir") or os.path.join("build", "pip-" + tags.abi_tag())
    cuda = (_value(config_settings, "cuda") or "auto").upper()
    if cuda not in ("AUTO", "ON", "OFF"):
        raise ValueError("soak_build: cuda must be auto, on or off, not %r" % cuda.lower())
    return Settings(
        source_dir=source,
        build_dir=os.path.abspath(os.path.join(source, build)),
        cuda=cuda,
        cuda_arch=_value(config_settings, "cuda-arch"),
        jobs=_value(config_settings, "jobs"),
    )
