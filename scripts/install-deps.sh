#!/usr/bin/env bash
# Installs the Debian packages tofsim builds and runs with (as root, or with
# sudo; scripts/apt-install.sh). Skips apt-get entirely when everything is
# already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  ccache                                             # rebuilds of the same sources (scripts/compiler-cache.sh)
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri  # headless GL: EGL + Mesa llvmpipe
  libglm-dev libtinygltf-dev nlohmann-json3-dev libyaml-cpp-dev libcli11-dev
  libopenexr-dev libopencv-dev libgtest-dev
  libpng-dev                                         # the PNGs (OpenCV's imgcodecs costs every process 0.05 s to load)
  libembree-dev                                      # the CPU reference path tracer
  libhdf5-dev                                        # NLOS captures in y-tal's HDF5 layout (core/io)
  python3-dev pybind11-dev python3-numpy python3-pytest  # the Python module and its tests
  python3-h5py                                       # tests/io/tal_capture_h5py.py: the captures as h5py sees them
  dpkg-dev file                                      # cpack -G DEB: dpkg-shlibdeps finds the Depends (tests/install)
  chromium                                           # tests/viewer: `tofsim view`'s page in headless Chromium
)

bash "$(dirname "$0")/apt-install.sh" "${packages[@]}"
