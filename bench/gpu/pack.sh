#!/usr/bin/env bash
# Packs what bench/gpu/run.sh needs on a GPU machine that has no build tools
# (bench/README.md, "gpu"): the three programs, the shared libraries ldd
# finds for them (less the C runtime and the GL/EGL loaders, which the NVIDIA
# driver's machine provides), configs/ and the scenes.
# Usage: bash bench/gpu/pack.sh [DEST=.gpu-bench]
#   PACK_CLI=0: leave out tofsim; PACK_GL=1: add the glvnd loader .debs
set -euo pipefail
cd "$(dirname "$0")/../.."
dest=${1:-.gpu-bench}
bins=(build/bench/tofsim_equal_error build/bench/tofsim_cpu_gather)
[ "${PACK_CLI:-1}" = 1 ] && bins=(build/apps/cli/tofsim "${bins[@]}")
for b in "${bins[@]}"; do [ -x "$b" ] || { echo "pack: $b not built (cmake --build build)" >&2; exit 1; }; done
rm -rf "$dest" && mkdir -p "$dest/bin" "$dest/lib"
cp "${bins[@]}" "$dest/bin/"
cp -r configs "$dest/configs"  # holds scenes/ too: the configs name them relative to themselves
cp bench/gpu/run.sh "$dest/run.sh"
# The driver provides the C runtime and the GL/EGL/GLdispatch loaders: carrying
# Mesa's glvnd copies would shadow nothing useful and the libc must match the kernel's.
skip='/(libc|libm|libdl|libpthread|librt|ld-linux[^/]*|libEGL|libGL[^/]*|libOpenGL|libGLdispatch)\.so'
ldd "${bins[@]}" | awk '/=> \//{print $3}' | sort -u | grep -Ev "$skip" | xargs -r cp -L -t "$dest/lib/"
# PACK_GL=1: also the glvnd loaders as amd64 .debs (device/README.md's trick);
# run.sh unpacks them where the machine has no libEGL.so.1.
if [ "${PACK_GL:-0}" = 1 ]; then
  mkdir -p "$dest/gl" /tmp/amd64/partial
  o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64)
  apt-get "${o[@]}" update >/dev/null
  (cd "$dest/gl" && apt-get "${o[@]}" download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)
fi
git rev-parse --short HEAD >"$dest/COMMIT"
size=$(du -sm "$dest" | cut -f1)
echo "packed $dest: ${#bins[@]} programs, $(ls "$dest/lib" | wc -l) libraries, ${size} MiB"
if [ "$size" -gt 60 ]; then
  echo "pack: WARNING ${size} MiB is over what one device call carries (64 MiB);" \
       "PACK_CLI=0 leaves out tofsim (and its OpenCV/FFmpeg/GDAL libraries)" >&2
fi
