#!/usr/bin/env bash
# Second command of the README (and what CI runs): install what is missing,
# build, and run the whole test suite. GPU tests skip visibly without a GPU.
# Then the sanitizer build runs the CPU tests again, and the fuzzers.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Demos/scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release "$@"
# The CPU tests again under AddressSanitizer and UndefinedBehaviorSanitizer
# (clang), and each libFuzzer target for 30 s (Doc/reliability.md).
# SOAK_SKIP_SANITIZE=1 skips this part.
if [ "${SOAK_SKIP_SANITIZE:-0}" != 1 ]; then
  cmake --preset sanitize >/dev/null
  cmake --build --preset sanitize
  ctest --preset sanitize "$@"
fi
