"""Which built files go where in the installed package.

    soak.cpython-311-x86_64-linux-gnu.so   the module (RUNPATH $ORIGIN/soak.libs)
    soak.libs/libsoak_core.so              the core library
    soak.libs/soak-plugins/libsoak_*.so    the plugins (WetCloth, AirDrag)

The core library finds its plugins in soak-plugins beside itself
(Core/Plugins/PluginLoader.cpp), in the build tree (lib/) and in the
installed package (soak.libs/) alike.
"""
import glob
import os

from . import tags

LIBS = "soak.libs"


def module_path(build_dir) -> str:
    path = os.path.join(build_dir, "python", "soak" + tags.extension_suffix())
    if not os.path.exists(path):
        raise RuntimeError("soak_build: the build made no %s" % path)
    return path


def files(build_dir):
    """(path in the wheel, path on disk) for every file of the package."""
    out = [(os.path.basename(module_path(build_dir)), module_path(build_dir))]
    libs = sorted(glob.glob(os.path.join(build_dir, "lib", "*.so")))
    plugins = sorted(glob.glob(os.path.join(build_dir, "lib", "soak-plugins", "libsoak_*.so")))
    if not any(os.path.basename(p) == "libsoak_core.so" for p in libs):
        raise RuntimeError("soak_build: no libsoak_core.so in %s/lib" % build_dir)
    if not plugins:
        raise RuntimeError("soak_build: no plugins in %s/lib/soak-plugins" % build_dir)
    out += [(LIBS + "/" + os.path.basename(p), p) for p in libs]
    out += [(LIBS + "/soak-plugins/" + os.path.basename(p), p) for p in plugins]
    return out
