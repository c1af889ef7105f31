# Sourced by the install tests: what a tofsim installed under a prefix must
# do. Arguments of the tests: BUILD_DIR SOURCE_DIR VERSION PYTHON_DIR (the
# Python package's folder under the prefix, "none" when not built).
set -euo pipefail
build_dir=$1
source_dir=$2
version=$3
python_dir=$4
config="$source_dir/examples/consumer/plane.yaml"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# A temporary folder, removed on exit (KEEP_WORK=1 keeps it for a look);
# nothing is installed into the system.
work=$(mktemp -d "${TMPDIR:-/tmp}/tofsim-install-test.XXXXXX")
trap '[ -n "${KEEP_WORK:-}" ] || rm -rf "$work"' EXIT

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi

# check_installed PREFIX: the CLI's version; a render with a video whose
# module comes from PREFIX and whose transient.json records the version;
# examples/consumer configured with CMAKE_PREFIX_PATH=PREFIX, built and run;
# the Python package imported from PREFIX.
check_installed() {
  local prefix
  prefix=$(realpath "$1")
  local tofsim="$prefix/bin/tofsim"
  [ -x "$tofsim" ] || fail "no $tofsim"
  local printed
  printed=$("$tofsim" --version)
  [ "$printed" = "tofsim $version" ] || fail "$tofsim --version: '$printed', expected 'tofsim $version'"
  echo "$printed"

  local module
  module=$(find "$prefix" -name libtofsim_video_module.so | head -n1)
  [ -n "$module" ] || fail "no video module under $prefix"
  # The installed module, not the build tree's (which also exists here).
  LD_DEBUG=files "$tofsim" render "$config" -o "$work/render" --set output.video=true -q \
    2>"$work/ld_cli.log" || { tail -n 20 "$work/ld_cli.log"; fail "tofsim render"; }
  grep -q "file=$module .*dynamically loaded" "$work/ld_cli.log" ||
    fail "the installed CLI did not load $module: $(grep -m1 'file=.*video_module' "$work/ld_cli.log")"
  [ -s "$work/render/transient.mp4" ] || fail "no transient.mp4"
  /usr/bin/python3 - "$work/render/transient.json" "$version" <<'PY' || fail "transient.json's tofsim_version"
import json, sys
meta = json.load(open(sys.argv[1]))
assert meta["tofsim_version"] == sys.argv[2], meta["tofsim_version"]
PY
  echo "render: $module loaded, transient.json tofsim_version $version"

  cmake -S "$source_dir/examples/consumer" -B "$work/consumer" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" >"$work/consumer.log" 2>&1 ||
    { cat "$work/consumer.log"; fail "configuring examples/consumer"; }
  grep -q "^tofsim_DIR:PATH=$prefix/" "$work/consumer/CMakeCache.txt" ||
    fail "examples/consumer found another tofsim: $(grep '^tofsim_DIR' "$work/consumer/CMakeCache.txt")"
  cmake --build "$work/consumer" >>"$work/consumer.log" 2>&1 ||
    { cat "$work/consumer.log"; fail "building examples/consumer"; }
  local out
  out=$("$work/consumer/consumer" "$config") || fail "examples/consumer exited $?"
  echo "$out"
  grep -q "^tofsim $version, CPU" <<<"$out" || fail "examples/consumer: no render on the CPU"
  grep -q "^spad/spad_counts: 8192 values" <<<"$out" || fail "examples/consumer: no SPAD counts"

  if [ "$python_dir" != none ]; then
    local pythondir="$prefix/$python_dir"
    [ -d "$pythondir/tofsim" ] || fail "no Python package in $pythondir"
    LD_DEBUG=files PYTHONPATH="$pythondir" /usr/bin/python3 - "$config" "$work/python" "$prefix" \
      2>"$work/ld_python.log" <<'PY' || { tail -n 20 "$work/ld_python.log"; fail "Python"; }
import sys
import tofsim
assert tofsim.__file__.startswith(sys.argv[3]), tofsim.__file__
config = tofsim.load_config(sys.argv[1], {"output.video": True})
r = tofsim.render(config, output_dir=sys.argv[2])
print("python:", tofsim.__file__, r.transient.shape)
PY
    grep -q "file=$module .*dynamically loaded" "$work/ld_python.log" ||
      fail "the installed Python module did not load $module"
  fi
}
