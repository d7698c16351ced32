#!/usr/bin/env bash
# Builds the whole tree once more with AddressSanitizer and UndefinedBehaviorSanitizer (GCC) in
# build-sanitize/ and runs the whole test suite there, the fuzz corpus replays (fuzz_*_corpus)
# included. A sanitizer report ends its program with a failure, so the test that met it fails.
#
#   bash tools/sanitize.sh          build and run every test
#   bash tools/sanitize.sh build    build only
#
# -O0 without debug information builds in about the CPU time of the normal -O2 -g build (0.96 of
# it, measured on tests/core/all; -O1 -g1 took 1.38 of it); reports name functions, and
# SANITIZE_CXX_FLAGS="-O1 -g1" gives file:line. The benchmarks (bench/) are not built: ctest does
# not run them.
# Test code (the test programs and their support library) is built with AddressSanitizer and
# LeakSanitizer but without UBSan's checks, which made it compile 1.3 to 1.7 times as long; the
# code under test keeps all three (cmake/precompiledheaders.cmake).
# Warnings are not errors here: the normal build (CI's first stage) checks them, and GCC warns
# differently with the instrumentation.
# Test time limits are three times the normal ones (DRIVEBENCH_TEST_TIMEOUT_SCALE): the
# instrumented programs run slower.
# Environment: SANITIZE_BUILD_DIR (default: build-sanitize), SANITIZE_CXX_FLAGS (default: -O0 -g0),
# DRIVEBENCH_CMAKE_ARGS: more options for cmake (.ci/run: precompiled headers, mold).
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=${SANITIZE_BUILD_DIR:-build-sanitize}
flags=${SANITIZE_CXX_FLAGS:--O0 -g0}
# shellcheck disable=SC2086 # DRIVEBENCH_CMAKE_ARGS is a list of options
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$flags -DNDEBUG" -DDRIVEBENCH_SANITIZE=address,undefined \
    -DDRIVEBENCH_BUILD_BENCH=OFF -DDRIVEBENCH_WERROR=OFF -DDRIVEBENCH_TEST_TIMEOUT_SCALE=3 \
    ${DRIVEBENCH_CMAKE_ARGS:-} >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
[ "${1:-}" = build ] && exit 0

# Leaks count as findings too (LeakSanitizer runs at the exit of each test program).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
# Leaks inside system libraries only (see the file); our own code is never suppressed.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tools/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
cd "$build_dir"
QT_QPA_PLATFORM=offscreen ctest --output-on-failure --parallel "$(nproc)" --timeout 600
