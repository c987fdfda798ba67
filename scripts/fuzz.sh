#!/usr/bin/env bash
# scripts/fuzz.sh [--runs N | --seconds S] [--jobs J] [HARNESS ...]
# Builds the libFuzzer harnesses of tests/fuzz with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (in build-fuzz/, or $GRAINLOAD_FUZZ_BUILD), seeds each corpus with
# the repository's own files (cases/, tests/data/, tests/fuzz/ with its regressions/), and runs each
# harness: by default 1e6 inputs each (tests/fuzz/README.md has the times), or for S seconds
# (CI: --seconds 5). HARNESS: case gmsh stl keyword checkpoint (default: all). A finding stops
# that harness and leaves the input in build-fuzz/findings/<harness>/; the script then exits 1.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GRAINLOAD_FUZZ_BUILD:-$root/build-fuzz}"
limit=(-runs=1000000)
jobs="${GRAINLOAD_JOBS:-$(nproc)}"
harnesses=()
while (($# > 0)); do
  case "$1" in
    --runs) limit=(-runs="$2"); shift 2 ;;
    --seconds) limit=(-max_total_time="$2"); shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    *) harnesses+=("$1"); shift ;;
  esac
done
if ((${#harnesses[@]} == 0)); then
  harnesses=(case gmsh stl keyword checkpoint)
fi

bash "$root/scripts/ensure_packages.sh"
# One thread: the harnesses are single inputs, and OpenMP's idle threads only cost time.
export OMP_NUM_THREADS=1
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DGRAINLOAD_FUZZ=ON -DGRAINLOAD_BUILD_TESTS=OFF -DGRAINLOAD_BUILD_BENCH=OFF "${launcher[@]}" \
  >/dev/null
targets=()
for h in "${harnesses[@]}"; do targets+=(--target "fuzz_$h"); done
cmake --build "$build" -j "$jobs" "${targets[@]}"

declare -A extension=([case]=.toml [gmsh]=.msh [stl]=.stl [keyword]=.k [checkpoint]=.bin)
status=0
for h in "${harnesses[@]}"; do
  corpus="$build/corpus/$h"
  findings="$build/findings/$h"
  mkdir -p "$corpus" "$findings"
  # Seeds are named by their content's hash, so re-seeding adds nothing twice.
  while IFS= read -r -d '' seed; do
    cp "$seed" "$corpus/seed-$(sha1sum "$seed" | cut -c1-16)"
  done < <(find "$root/cases" "$root/tests/data" "$root/tests/fuzz" \
             -type f -name "*${extension[$h]}" -print0 2>/dev/null;
           find "$root/tests/fuzz/regressions/$h" -type f -print0 2>/dev/null)
  if [[ $h == checkpoint ]]; then
    GRAINLOAD_FUZZ_WRITE_SEEDS="$corpus" "$build/tests/fuzz/fuzz_checkpoint" -runs=0 \
      >/dev/null 2>&1
  fi
  echo "== fuzz_$h: ${limit[*]}, corpus $corpus"
  # -timeout: an input that takes over 10 s is a hang; -rss_limit_mb: one that needs over
  # 2 GiB is an absurd allocation. Both are findings. -max_len: 32 KiB holds a checkpoint of
  # the fuzz scene (17 KiB) and keeps the large meshes among the seeds from slowing every run.
  if ! "$build/tests/fuzz/fuzz_$h" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=32768 \
      -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" 2>"$build/fuzz_$h.log"; then
    status=1
    echo "fuzz_$h: FINDING, see $build/fuzz_$h.log and $findings/" >&2
  fi
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ *DONE)" \
    "$build/fuzz_$h.log" || true
done
exit "$status"
