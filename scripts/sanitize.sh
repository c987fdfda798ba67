#!/usr/bin/env bash
# scripts/sanitize.sh [ctest options]
# Builds grainload and its tests with AddressSanitizer and UndefinedBehaviorSanitizer
# (GRAINLOAD_SANITIZE, in build-sanitize/ or $GRAINLOAD_SANITIZE_BUILD) and runs the unit and
# verification tests there; the CLI the tests start is the sanitized one. Any sanitizer report
# fails the test that triggered it: undefined behaviour aborts (-fno-sanitize-recover), and so
# do memory errors and, at exit, leaks. Default ctest selection: -L 'unit|verification';
# CI does not run it (it needs a second, sanitized build of everything); run it before a release.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GRAINLOAD_SANITIZE_BUILD:-$root/build-sanitize}"
jobs="${GRAINLOAD_JOBS:-$(nproc)}"
start=$(date +%s)

bash "$root/scripts/ensure_packages.sh"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRAINLOAD_SANITIZE=ON \
  -DGRAINLOAD_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$jobs"
built=$(date +%s)

if [[ $# -eq 0 ]]; then
  set -- -L 'unit|verification'
fi
# Leaks are reported at exit; OpenMP's thread pool is not one of ours and frees at exit.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build"
set +e
ctest --output-on-failure -j "$jobs" "$@"
status=$?
set -e
end=$(date +%s)
echo "scripts/sanitize.sh: build $((built - start)) s, tests $((end - built)) s"
exit "$status"
