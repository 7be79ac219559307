#!/usr/bin/env bash
# A longer run of the deck fuzzer (tests/fuzz/fuzz_deck.cpp) than the test suite's short one.
#   tools/fuzz.sh [SECONDS] [extra libFuzzer flags]      (default 600 s, one process)
# Builds the fuzz preset (clang, libFuzzer + ASan + UBSan; tools/setup.sh installs clang and
# libclang-rt-dev), then fuzzes from the checked-in seed corpus. New interesting inputs go to
# build/fuzz/corpus_long (kept between runs, never into the checked-in corpus); a crash, leak,
# sanitizer report or timeout stops the run and leaves its input as build/fuzz/crash-*,
# leak-*, timeout-* or oom-*, which `build/fuzz/tests/fuzz/fuzz_deck FILE` replays.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"${JOBS:-1}"
mkdir -p build/fuzz/corpus_long
exec build/fuzz/tests/fuzz/fuzz_deck -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=16384 -print_final_stats=1 -dict=tests/fuzz/deck.dict -artifact_prefix=build/fuzz/ \
  "$@" build/fuzz/corpus_long tests/fuzz/corpus
