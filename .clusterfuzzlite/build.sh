#!/bin/bash -eu
# Builds the libFuzzer targets of fuzz/ the way ClusterFuzzLite and OSS-Fuzz do: the engine's
# compile step runs this with CC, CXX, CFLAGS and CXXFLAGS (sanitizers and
# -fsanitize=fuzzer-no-link), LIB_FUZZING_ENGINE, SRC, WORK and OUT in the environment, and
# takes from $OUT each target with its dictionary (<target>.dict), libFuzzer options
# (<target>.options) and seed corpus (<target>_seed_corpus.zip).
# scripts/fuzz runs this script too (with RASTRULES_SRC, RASTRULES_FUZZ_BUILD_DIR and
# RASTRULES_FUZZ_CMAKE_ARGS), so every CI run builds its fuzz targets through it.
src="${RASTRULES_SRC:-$SRC/rastrules}"
build="${RASTRULES_FUZZ_BUILD_DIR:-$WORK/build}"
targets=(fuzz_scene_parser fuzz_kernel_vs_oracle fuzz_external_protocol fuzz_driver_output
         fuzz_pipeline fuzz_cli_args fuzz_path)

# Flags come from CFLAGS/CXXFLAGS (CMake reads them on the first configure); the project's own
# RASTRULES_SANITIZE stays empty. No build type: the engine's flags (-O1, line tables) decide.
if [[ ! -f "$build/build.ninja" ]]; then
  # shellcheck disable=SC2086 # RASTRULES_FUZZ_CMAKE_ARGS is a list of words
  cmake -S "$src" -B "$build" -G Ninja -DRASTRULES_BUILD_FUZZ=ON \
    -DRASTRULES_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" -DRASTRULES_BUILD_TOOLS=ON \
    -DRASTRULES_BUILD_TESTS=OFF -DRASTRULES_BUILD_PROPERTIES=OFF -DRASTRULES_BUILD_PROOFS=OFF \
    -DRASTRULES_BUILD_BENCH=OFF -DRASTRULES_BUILD_PYTHON=OFF ${RASTRULES_FUZZ_CMAKE_ARGS:-}
fi
cmake --build "$build" --parallel "${RASTRULES_JOBS:-$(nproc)}" --target "${targets[@]}"

mkdir -p "$OUT"
for t in "${targets[@]}"; do
  cp "$build/fuzz/$t" "$OUT/"
  dict="" max_len=""
  case "$t" in
    fuzz_scene_parser) dict=scene.dict max_len=16384 ;;
    fuzz_kernel_vs_oracle | fuzz_path) max_len=512 ;;
    fuzz_external_protocol | fuzz_driver_output) dict=protocol.dict max_len=4096 ;;
    fuzz_pipeline) dict=pipeline.dict max_len=8192 ;;
    fuzz_cli_args) dict=cli.dict max_len=2048 ;;
  esac
  [[ -n "$dict" ]] && cp "$src/fuzz/$dict" "$OUT/$t.dict"
  printf '[libfuzzer]\nmax_len = %s\ntimeout = 10\nrss_limit_mb = 2048\n' "$max_len" >"$OUT/$t.options"
  rm -f "$OUT/${t}_seed_corpus.zip"
  (cd "$src/fuzz/corpus/$t" && zip -q -r "$OUT/${t}_seed_corpus.zip" .)
done
