#!/usr/bin/env bash
# Makes `import soak` work for Debian's python3: writes soak.pth into its
# site folder (/usr/local/lib/python3.X/dist-packages), pointing at the
# module built in BUILD/python (default build/release). Idempotent. Needs
# root (or sudo) for that folder; otherwise prints the PYTHONPATH to set.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build/release}
python=/usr/bin/python3
moddir="$(pwd)/$build/python"
if ! ls "$moddir"/soak.cpython-*.so >/dev/null 2>&1; then
  echo "install-python-module: no soak module in $moddir (is pybind11-dev installed? see the configure output)" >&2
  exit 1
fi
site=$("$python" -c 'import site; print(site.getsitepackages()[0])')
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then sudo=sudo; else
    echo "install-python-module: cannot write $site; use: export PYTHONPATH=$moddir" >&2
    exit 0
  fi
fi
$sudo mkdir -p "$site"
echo "$moddir" | $sudo tee "$site/soak.pth" >/dev/null
"$python" -c 'import soak' && echo "install-python-module: 'import soak' works for $python ($site/soak.pth -> $moddir)"
