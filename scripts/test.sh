#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite (CTest).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
stylize_install_dependencies
stylize_start_display
stylize_build
echo "== running the test suite"
cd "$STYLIZE_BUILD"
ctest --output-on-failure -j "$STYLIZE_JOBS" --timeout 600 "$@"
