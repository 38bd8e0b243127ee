#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite (CTest), every
# tier once (docs/testing.md). Arguments go to ctest (e.g. -L unit, the quick loop).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
stylize_stage install stylize_install_dependencies
stylize_start_display
stylize_stage build stylize_build
echo "== running the test suite"
cd "$STYLIZE_BUILD"
stylize_stage suite ctest --output-on-failure -j "$STYLIZE_JOBS" --timeout 600 "$@"
