"""The source distribution: the files git tracks (or, outside a git
checkout, the tree without build folders), under soak-<version>/, with
PKG-INFO. A wheel built from it configures a fresh build folder inside it."""
import io
import os
import subprocess
import tarfile

from . import metadata

_SKIP_DIRS = {".git", "__pycache__"}


def _source_files(root):
    try:
        out = subprocess.run(["git", "ls-files", "-z"], cwd=root, check=True, capture_output=True).stdout
        return sorted(p for p in out.decode("utf-8").split("\0") if p and os.path.isfile(os.path.join(root, p)))
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for folder, dirs, names in os.walk(root):
        rel = os.path.relpath(folder, root)
        dirs[:] = [d for d in dirs if d not in _SKIP_DIRS and not (rel == "." and d.startswith(("build", "out")))]
        files += [os.path.normpath(os.path.join(rel, n)) for n in names if not n.endswith(".pyc")]
    return sorted(files)


def write(sdist_directory) -> str:
    root = os.getcwd()
    base = "%s-%s" % (metadata.DIST_NAME, metadata.version())
    name = base + ".tar.gz"
    mtime = int(os.environ.get("SOURCE_DATE_EPOCH", "315532800"))

    def normalise(info):
        info.uid = info.gid = 0
        info.uname = info.gname = ""
        info.mtime = mtime
        return info

    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as tar:
        for rel in _source_files(root):
            tar.add(os.path.join(root, rel), arcname=base + "/" + rel, recursive=False, filter=normalise)
        pkg_info = metadata.metadata_text().encode("utf-8")
        info = normalise(tarfile.TarInfo(base + "/PKG-INFO"))
        info.size = len(pkg_info)
        tar.addfile(info, io.BytesIO(pkg_info))
    return name
