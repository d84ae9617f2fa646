"""The wheel's compatibility tag (PEP 425) for the interpreter running the
build: the extension module is built for it alone."""
import sys
import sysconfig


def python_tag() -> str:
    if sys.implementation.name != "cpython":
        raise RuntimeError("soak_build: the soak module is a CPython extension; this is %s" % sys.implementation.name)
    return "cp%d%d" % sys.version_info[:2]


def abi_tag() -> str:
    # SOABI is e.g. cpython-311-x86_64-linux-gnu, cpython-313t-... (free-threaded) or cpython-311d-... (debug).
    soabi = sysconfig.get_config_var("SOABI") or ""
    parts = soabi.split("-")
    if len(parts) >= 2 and parts[0] == "cpython":
        return "cp" + parts[1]
    return python_tag()


def platform_tag() -> str:
    return sysconfig.get_platform().replace("-", "_").replace(".", "_")


def wheel_tag() -> str:
    return "%s-%s-%s" % (python_tag(), abi_tag(), platform_tag())


def extension_suffix() -> str:
    return sysconfig.get_config_var("EXT_SUFFIX")
