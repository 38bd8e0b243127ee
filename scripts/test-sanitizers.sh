#!/usr/bin/env bash
# The sanitizer stage of CI: builds the project with AddressSanitizer and
# UndefinedBehaviorSanitizer (VTKSTYLIZE_SANITIZE) in build-sanitize and runs the test suite in
# it (the ParaView plugin is left out: ParaView's processes are not instrumented), then the
# refusals of broken input with leak detection (Testing/Sanitizers/lsan.supp suppresses leaks
# inside libraries the project cannot fix). Any report fails its test.
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
