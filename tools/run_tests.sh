#!/usr/bin/env bash
# The whole test suite: format check, release build with every test, then the sanitizer
# (ASan + UBSan) build with the unit and command-line tests (the long physics runs are
# release only), then the deck fuzzer (clang, libFuzzer) built alone and run briefly.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}

echo "== clang-format check"
git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run -Werror

echo "== release build and tests"
cmake --preset release >/dev/null
cmake --build --preset release -j"$jobs"
ctest --preset release -j"$jobs"

echo "== sanitizer build (ASan + UBSan) and tests"
cmake --preset asan >/dev/null
cmake --build --preset asan -j"$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --preset asan -j"$jobs" -LE "verification|regression"

echo "== deck fuzzer (clang, libFuzzer + ASan + UBSan): build and short run"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$jobs"
ctest --preset fuzz
