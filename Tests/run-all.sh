#!/usr/bin/env bash
# Second command of the README (and what CI runs): install what is missing,
# build, and run the whole test suite. GPU tests skip visibly without a GPU.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Demos/scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release "$@"
