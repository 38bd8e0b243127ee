#!/usr/bin/env bash
# The sanitizer stage of CI: builds the project with AddressSanitizer and
# UndefinedBehaviorSanitizer (VTKSTYLIZE_SANITIZE) in build-sanitize and runs the test suite in
# it (the ParaView plugin is left out: ParaView's processes are not instrumented), then the
# refusals of broken input with leak detection (Testing/Sanitizers/lsan.supp suppresses leaks
# inside libraries the project cannot fix). Any report fails its test. Last, the libFuzzer targets
# (Testing/Fuzz, built with clang) fuzz the format checks, the isolated reader and the validation
# of what a reader gave for
# STYLIZE_FUZZ_SECONDS each (default 60), from a copy of the committed seed corpus; a crash, a
# hang, a leak or a sanitizer report fails the stage and leaves the input in
# build-fuzz/artifacts (add it to Testing/Fuzz/corpus once fixed).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
STYLIZE_BUILD="${STYLIZE_SANITIZE_BUILD:-$STYLIZE_ROOT/build-sanitize}"
stylize_install_dependencies
stylize_start_display
echo "== configuring and building with the sanitizers in $STYLIZE_BUILD"
cmake -S "$STYLIZE_ROOT" -B "$STYLIZE_BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DVTKSTYLIZE_SANITIZE=ON -DVTKSTYLIZE_PARAVIEW_PLUGIN=OFF >/dev/null
cmake --build "$STYLIZE_BUILD" -j "$STYLIZE_JOBS"
supp="$STYLIZE_ROOT/Testing/Sanitizers"
# Leaks are checked where no OpenGL context opens (below): llvmpipe's JIT-compiled shaders
# allocate from code no stack trace can name (the fast unwinder stops there, the slow one
# deadlocks in LLVM's frame registration), so no suppression can cover them.
# (allocator_may_return_null: an allocation too large fails as it does without the sanitizer,
# which hostile headers rely on being refused)
export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:detect_odr_violation=0:strict_init_order=1:allocator_may_return_null=1:${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
echo "== running the test suite under AddressSanitizer and UndefinedBehaviorSanitizer"
cd "$STYLIZE_BUILD"
ctest --output-on-failure -j "$STYLIZE_JOBS" --timeout 1200 "$@"
echo "== leaks: vtkstylize refusing broken input (no window opens)"
# (no_extent_obj and spacing_zero_vti are refused after a render: a window opens)
ASAN_OPTIONS="${ASAN_OPTIONS}:detect_leaks=1" \
  ctest --output-on-failure -j "$STYLIZE_JOBS" --timeout 1200 -R '^cli\.bad\.' \
  -E '^cli\.bad\.(no_extent_obj|spacing_zero_vti)$'

echo "== fuzzing (libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer)"
fuzz_build="$STYLIZE_ROOT/build-fuzz"
cmake -S "$STYLIZE_ROOT/Testing/Fuzz" -B "$fuzz_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$fuzz_build" -j "$STYLIZE_JOBS"
rm -rf "$fuzz_build/artifacts" && mkdir -p "$fuzz_build/artifacts"
for target in Checks Reader Validate; do
  corpus="$fuzz_build/corpus-$target"
  seeds="$STYLIZE_ROOT/Testing/Fuzz/corpus"
  [ "$target" = Validate ] && seeds="$STYLIZE_ROOT/Testing/Fuzz/corpus-validate"
  rm -rf "$corpus" && mkdir -p "$corpus" && cp "$seeds"/* "$corpus/"
  # (the reader's child may use up to its own limits; -rss_limit_mb bounds the caller)
  log="$fuzz_build/fuzz-$target.log"
  rc=0
  ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1:detect_odr_violation=0" \
    LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0" \
    "$fuzz_build/vtkStylizeFuzz$target" -max_total_time="${STYLIZE_FUZZ_SECONDS:-60}" \
    -timeout=60 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$fuzz_build/artifacts/$target-" "$corpus" >"$log" 2>&1 || rc=$?
  grep -E '^(Done|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb)' \
    "$log" | sed "s/^/$target: /" || true
  if [ "$rc" -ne 0 ]; then
    tail -n 60 "$log"
    echo "fuzzing $target failed (exit $rc): $(ls "$fuzz_build/artifacts")"
    exit 1
  fi
done
