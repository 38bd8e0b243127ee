#!/usr/bin/env bash
# The sanitizer stage of CI (docs/testing.md, "Under the sanitizers"): what AddressSanitizer and
# UndefinedBehaviorSanitizer can judge, the project's own C++, and nothing twice.
# 1. Builds build-sanitize with VTKSTYLIZE_SANITIZE (the project's modules, vtkstylize and the C++
#    tests instrumented; the tests' own tools compiled as in the release build, which ccache then
#    shares) and only what this stage runs: no Python wrapping, no ParaView plugin, no benchmark.
# 2. Runs the tiers unit, render, cli, corpus and fuzz there (the C++ units and regression images,
#    the filters, the program's renders, refusals and hostile corpus, the fuzz corpus replayed),
#    with halt_on_error: any report fails its test. Not realdata, paraview or the Python tests:
#    their time is llvmpipe's and the interpreter's, and they run once, in scripts/test.sh.
# 3. The leak stage: the program refusing broken input (the tests labelled leaks: cli.bad.*, where
#    no OpenGL context opens) with LeakSanitizer; Testing/Sanitizers/lsan.supp suppresses leaks
#    inside libraries the project cannot fix.
# 4. ThreadSanitizer (build-tsan: VTKSTYLIZE_SANITIZE_THREAD, only the targets it runs): the
#    multithreaded code, the feature-line, hidden-line and curvature filters' tests and the
#    reader's caller side in a busy multithreaded host (reader.threaded_host), with vtkSMPTools on
#    its STDThread backend, whose pool synchronises through pthread calls the sanitizer sees. Not
#    on TBB: Debian's libtbb is not instrumented, so the sanitizer cannot see a task's start and
#    end as synchronisation and reports every handed-over value (in TBB's own headers too), and
#    TBB's source, to build it instrumented, is not among what CI can reach. No suppression.
# 5. The libFuzzer targets (Testing/Fuzz, built with clang in build-fuzz) fuzz the format checks,
#    the isolated reader and the validation of what a reader gave, at once, from a copy of the
#    committed seed corpus, for STYLIZE_FUZZ_SECONDS (default 60) of one core each. A crash, a
#    hang, a leak or a sanitizer report fails the stage and leaves the input in
#    build-fuzz/artifacts (add it to Testing/Fuzz/corpus once fixed).
# Arguments go to the first ctest (e.g. -R comic).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
STYLIZE_BUILD="${STYLIZE_SANITIZE_BUILD:-$STYLIZE_ROOT/build-sanitize}"
stylize_stage install stylize_install_dependencies
stylize_start_display

sanitizer_build() {
  echo "== configuring and building with the sanitizers in $STYLIZE_BUILD"
  cmake -S "$STYLIZE_ROOT" -B "$STYLIZE_BUILD" -DCMAKE_BUILD_TYPE=Release \
    -DVTKSTYLIZE_SANITIZE=ON -DVTKSTYLIZE_PARAVIEW_PLUGIN=OFF -DVTKSTYLIZE_WRAP_PYTHON=OFF \
    -DVTKSTYLIZE_BUILD_BENCHMARK=OFF >/dev/null || return
  cmake --build "$STYLIZE_BUILD" -j "$STYLIZE_JOBS"
}
stylize_stage "sanitizer build" sanitizer_build

supp="$STYLIZE_ROOT/Testing/Sanitizers"
# Leaks are checked where no OpenGL context opens (below): llvmpipe's JIT-compiled shaders
# allocate from code no stack trace can name (the fast unwinder stops there, the slow one
# deadlocks in LLVM's frame registration), so no suppression can cover them.
# (allocator_may_return_null: an allocation too large fails as it does without the sanitizer,
# which hostile headers rely on being refused)
export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:strict_init_order=1:allocator_may_return_null=1:${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="suppressions=$supp/ubsan.supp:print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
cd "$STYLIZE_BUILD"
echo "== running the tiers unit, render, cli, corpus and fuzz under AddressSanitizer and UndefinedBehaviorSanitizer"
stylize_stage "sanitizer suite" ctest --output-on-failure -j "$STYLIZE_JOBS" --timeout 1200 \
  -L '^(unit|render|cli|corpus|fuzz)$' -LE '^leaks$' "$@"
echo "== leaks: vtkstylize refusing broken input (no window opens)"
ASAN_OPTIONS="${ASAN_OPTIONS}:detect_leaks=1" \
  stylize_stage leaks ctest --output-on-failure -j "$STYLIZE_JOBS" --timeout 1200 -L '^leaks$'

tsan_build="${STYLIZE_TSAN_BUILD:-$STYLIZE_ROOT/build-tsan}"
thread_build() {
  echo "== configuring and building with ThreadSanitizer in $tsan_build"
  cmake -S "$STYLIZE_ROOT" -B "$tsan_build" -DCMAKE_BUILD_TYPE=Release \
    -DVTKSTYLIZE_SANITIZE_THREAD=ON -DVTKSTYLIZE_PARAVIEW_PLUGIN=OFF -DVTKSTYLIZE_WRAP_PYTHON=OFF \
    -DVTKSTYLIZE_BUILD_BENCHMARK=OFF >/dev/null || return
  cmake --build "$tsan_build" -j "$STYLIZE_JOBS" --target vtkStylizeFiltersCxxTests \
    vtkStylizeIOCxxTests vtkstylize-read vtkStylizeCliMakeData
}
stylize_stage "thread build" thread_build
echo "== ThreadSanitizer: the filters and the reader's caller side, vtkSMPTools on STDThread"
stylize_stage "thread suite" env VTK_SMP_BACKEND_IN_USE=STDThread \
  TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:${TSAN_OPTIONS:-}" \
  ctest --test-dir "$tsan_build" --output-on-failure -j 1 --timeout 1200 \
    -R '^(curvature.analytic|lines.analytic|lines.visibility_input|lines.ray_occluder|reader.threaded_host)$'

fuzz_build="$STYLIZE_ROOT/build-fuzz"
fuzz_configure_and_build() {
  echo "== building the fuzz targets (clang, libFuzzer) in $fuzz_build"
  cmake -S "$STYLIZE_ROOT/Testing/Fuzz" -B "$fuzz_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null || return
  cmake --build "$fuzz_build" -j "$STYLIZE_JOBS"
}
stylize_stage "fuzz build" fuzz_configure_and_build

# The three targets run at once, each for its share of the cores: the same processor time as one
# after the other for STYLIZE_FUZZ_SECONDS each, in 1 / STYLIZE_JOBS of the wall time.
fuzz() {
  local targets=(Checks Reader Validate) seeds corpus log target
  local seconds=$(( ${STYLIZE_FUZZ_SECONDS:-60} * ${#targets[@]} / STYLIZE_JOBS ))
  echo "== fuzzing (libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer): ${targets[*]} at once, ${seconds} s"
  rm -rf "$fuzz_build/artifacts" && mkdir -p "$fuzz_build/artifacts"
  local -A pids=()
  for target in "${targets[@]}"; do
    corpus="$fuzz_build/corpus-$target"
    seeds="$STYLIZE_ROOT/Testing/Fuzz/corpus"
    [ "$target" = Validate ] && seeds="$STYLIZE_ROOT/Testing/Fuzz/corpus-validate"
    rm -rf "$corpus" && mkdir -p "$corpus" && cp "$seeds"/* "$corpus/"
    # (the reader's child may use up to its own limits; -rss_limit_mb bounds the caller)
    ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" \
      LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0" \
      "$fuzz_build/vtkStylizeFuzz$target" -max_total_time="$seconds" \
      -timeout=60 -rss_limit_mb=4096 -print_final_stats=1 \
      -artifact_prefix="$fuzz_build/artifacts/$target-" "$corpus" \
      >"$fuzz_build/fuzz-$target.log" 2>&1 &
    pids[$target]=$!
  done
  local failed=0 rc
  for target in "${targets[@]}"; do
    rc=0
    wait "${pids[$target]}" || rc=$?
    log="$fuzz_build/fuzz-$target.log"
    grep -E '^(Done|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb)' \
      "$log" | sed "s/^/$target: /" || true
    if [ "$rc" -ne 0 ]; then
      tail -n 60 "$log"
      echo "fuzzing $target failed (exit $rc): $(ls "$fuzz_build/artifacts")"
      failed=1
    fi
  done
  return "$failed"
}
stylize_stage fuzz fuzz
