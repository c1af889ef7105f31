#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then what that tree must do
# (common.sh: the CLI, its video module, examples/consumer, Python).
# ctest's install.consumer: BUILD_DIR SOURCE_DIR VERSION PYTHON_DIR.
source "$(dirname "$0")/common.sh"
cmake --install "$build_dir" --prefix "$work/prefix" >"$work/install.log" ||
  { cat "$work/install.log"; fail "cmake --install"; }
echo "installed $(find "$work/prefix" -type f | wc -l) files, $(du -sh "$work/prefix" | cut -f1)"
check_installed "$work/prefix"
echo "install.consumer: ok"
