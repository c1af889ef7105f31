#!/usr/bin/env bash
# `cpack -G DEB` (cmake/Packaging.cmake): the packages tofsim and tofsim-dev,
# their Depends, then both unpacked (dpkg-deb -x, no root, nothing installed
# on the system) into a temporary folder and checked as an installed tree
# (common.sh). ctest's install.deb: BUILD_DIR SOURCE_DIR VERSION PYTHON_DIR.
source "$(dirname "$0")/common.sh"
for tool in dpkg-deb dpkg-shlibdeps file; do
  command -v "$tool" >/dev/null 2>&1 || { echo "skipped: no $tool (dpkg-dev, file)"; exit 77; }
done
cpack -G DEB --config "$build_dir/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack -G DEB"; }
runtime=$(ls "$work"/pkg/tofsim_*.deb)
dev=$(ls "$work"/pkg/tofsim-dev_*.deb)
ls -l "$runtime" "$dev"

field() { dpkg-deb -f "$1" "$2"; }
[ "$(field "$runtime" Version)" = "$version" ] || fail "Version $(field "$runtime" Version)"
depends=$(field "$runtime" Depends)
echo "tofsim Depends: $depends"
# What dpkg-shlibdeps finds the CLI, the video module and Python module link.
for package in libc6 libstdc\\+\\+6 libembree3 libopenexr libhdf5 libyaml-cpp libopencv-core \
               libopencv-videoio libpng16 libegl1 libopengl0; do
  grep -Eq "(^|, )$package" <<<"$depends" || fail "tofsim's Depends lack $package"
done
dev_depends=$(field "$dev" Depends)
echo "tofsim-dev Depends: $dev_depends"
grep -q "tofsim (= $version)" <<<"$dev_depends" || fail "tofsim-dev does not depend on tofsim $version"
for deb in "$runtime" "$dev"; do
  outside=$(dpkg-deb -c "$deb" | awk '{print $6}' | grep -v '^\./usr/' | grep -v '^\./$' || true)
  [ -z "$outside" ] || fail "$deb installs outside /usr: $outside"
  dpkg-deb -x "$deb" "$work/root"
done
check_installed "$work/root/usr"
echo "install.deb: ok"
