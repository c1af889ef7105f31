#!/usr/bin/env bash
# Sourced by the build scripts: compiles through ccache when it is installed
# (scripts/install-deps.sh installs it), so that a rebuild in a fresh clone of
# the same sources, as CI's, takes the objects from the cache instead of
# compiling them again. The clone's own directory is left out of the hash
# (base_dir + no hash_dir): clones at different paths share the cache.
# Sets cache_flags, the CMake arguments to pass at configure time.
cache_flags=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$PWD"
  export CCACHE_NOHASHDIR=1
  cache_flags=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
