#!/usr/bin/env bash
# Runs the GPU benchmark from a folder packed by bench/gpu/pack.sh (no build
# tools needed) and prints ONE Markdown table: device, figure, command.
#   (a) the paper's TABLE configuration, tofsim render --backend gl
#   (b) the Cornell box equal-error case, tofsim_equal_error ... gl
#   (c) gathers per second, tofsim_cpu_gather (CPU and GL backends)
# Usage: bash run.sh [--quick] [TABLE_FILE=$OUT/gpu_table.md]
# GPU_BENCH_PLATFORM=device|surfaceless (default device); GPU_BENCH_DIR = the
# packed folder (default: this script's folder if it holds bin/, else .gpu-bench).
set -uo pipefail
quick=0
[ "${1:-}" = --quick ] && { quick=1; shift; }
here=$(cd "$(dirname "$0")" && pwd)
pack=${GPU_BENCH_DIR:-$([ -d "$here/bin" ] && echo "$here" || echo .gpu-bench)}
pack=$(cd "$pack" && pwd) || { echo "run: no packed folder (bash bench/gpu/pack.sh)" >&2; exit 1; }
table=${1:-${OUT:-.}/gpu_table.md}
platform=${GPU_BENCH_PLATFORM:-device}
export TOFSIM_EGL_PLATFORM=$platform LD_LIBRARY_PATH="$pack/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
nvidia_egl=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f $nvidia_egl ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nvidia_egl
# A bare machine may lack the glvnd loaders: unpack the packed .debs (pack.sh PACK_GL=1).
if ! ldconfig -p | grep -q 'libEGL.so.1 ' && compgen -G "$pack/gl/*.deb" >/dev/null; then
  for f in "$pack"/gl/*.deb; do dpkg -x "$f" /; done && ldconfig
fi
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
cd "$pack"
rows=()
row() { rows+=("| $1 | $2 | \`$3\` |"); }
device=""
# The first "KEY": value of a transient.json, without quotes or trailing comma.
jsonField() { sed -n "s/^ *\"$2\": *//p" "$1" | head -1 | sed 's/,$//; s/^"//; s/"$//'; }

# tofsim render of the Cornell box; prints nothing, leaves $work/$1/transient.json.
render() {
  local name=$1 limit=$2; shift 2
  local cmd=(bin/tofsim render configs/cornell_box.yaml -q -o "$work/$name" --backend gl
    --egl-platform "$platform" --set 'sensors=[]' --set output.video=false
    --set 'output.components=[]' --set output.steady=false --set output.depth=false "$@")
  last=$(printf '%q ' "${cmd[@]}" | sed "s|$work/|OUTDIR/|; s/ $//")
  timeout "$limit" "${cmd[@]}" >"$work/$name.log" 2>&1
}

# Check: a tiny render must run on the chosen platform before the long ones.
if [ -x bin/tofsim ]; then
  if ! render check 20 --set 'camera.resolution=[16,16]' --set time.bins=16; then
    cat "$work/check.log" >&2; echo "run: EGL platform '$platform' does not render" >&2; exit 1
  fi
  device=$(jsonField "$work/check/transient.json" device)
else
  device=$(timeout 20 bin/tofsim_cpu_gather 1 8 4 2>&1 | sed -n 's/^GL: //p')
  [ -n "$device" ] || { echo "run: EGL platform '$platform' does not render" >&2; exit 1; }
fi
echo "device: $device" >&2

# (a) The paper's TABLE configuration (GTX 1060: 131.76 s).
if [ $quick = 1 ]; then side=64 rsm=16 ism=16 points=500; else side=1024 rsm=256 ism=256 points=24000; fi
if [ -x bin/tofsim ]; then
  if render table 110 --set "camera.resolution=[$side,$side]" --set time.bins=250 \
      --set 'time.bin_width=8 mm' --set render.indirect.rsm_resolution=$rsm \
      --set render.indirect.ism_resolution=$ism --set render.indirect.points_per_vpl=$points \
      --set "render.memory_budget=${GPU_BENCH_BUDGET:-8 GiB}"; then
    j="$work/table/transient.json"
    row "(a) TABLE ${side}^2, 250 bins, RSM ${rsm}^2, ISM ${ism}^2, ${points} pts/VPL (paper: 131.76 s, GTX 1060)" \
      "$(jsonField "$j" seconds) s render, $(jsonField "$j" vpls) VPLs, $(jsonField "$j" vpl_batches) batches" "$last"
  else
    row "(a) TABLE configuration" "failed or over 110 s (rc $?): $(tail -c 200 "$work/table.log" | tr '\n|' ' /')" "$last"
  fi
  rm -rf "$work/table"
else
  row "(a) TABLE configuration" "not run: tofsim not packed (PACK_CLI=0)" "-"
fi

# (b) IR against the reference path tracer at equal error, IR on the GL backend.
res=$([ $quick = 1 ] && echo 16 || echo 64)
cmd="bin/tofsim_equal_error configs/scenes/cornell_box.gltf $res gl"
if timeout 45 $cmd >"$work/eq.log" 2>&1; then
  # The last table: | IR setting | IR seconds | reference seconds | speed-up |
  while IFS='|' read -r _ setting irs refs speed _; do
    setting=$(echo $setting)  # trimmed
    row "(b) equal error ${res}^2: ${setting}" "IR ${irs// /} s, reference at equal error ${refs// /} s, speed-up ${speed// /}" "$cmd"
  done < <(awk '/^\| IR setting/{t=1; next} t && /^\| IR/' "$work/eq.log")
else
  row "(b) equal error" "failed or over 45 s: $(tail -c 200 "$work/eq.log" | tr '\n|' ' /')" "$cmd"
fi

# (c) Gather pairs per second, CPU (all cores) and GL, through the backend interface.
threads=$(nproc)
if [ $quick = 1 ]; then sweep="32:8"; else sweep="128:32 256:32 256:64"; fi
for c in $sweep; do
  cmd="bin/tofsim_cpu_gather $threads ${c%:*} ${c#*:}"
  if timeout 20 $cmd >"$work/g.log" 2>&1; then
    while IFS='|' read -r _ vis pairs cpu gl ratio _; do
      row "(c) gathers ${c%:*}^2, RSM ${c#*:}^2, ${vis// /}" \
        "${pairs// /} pairs: cpu ${cpu// /} M/s, gl ${gl// /} M/s, cpu/gl ${ratio// /}" "$cmd"
    done < <(grep -E '^\| (none|exact|ism) ' "$work/g.log")
  else
    row "(c) gathers ${c%:*}^2" "failed or over 20 s: $(tail -c 200 "$work/g.log" | tr '\n|' ' /')" "$cmd"
  fi
done

{
  echo "commit: $(cat COMMIT 2>/dev/null), device: $device, EGL platform: $platform, $(nproc) CPU threads$([ $quick = 1 ] && echo ', --quick sizes')"
  echo
  echo "| case | figure | command (in the packed folder) |"
  echo "|---|---|---|"
  printf '%s\n' "${rows[@]}"
} | tee "$table"
