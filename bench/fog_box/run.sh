#!/usr/bin/env bash
# IR against the reference path tracer at equal transient error on issue
# 42's fog box (configs/fog_box.yaml: a closed 2 m box, fog sigma_s 1 /m,
# sigma_a 0.02 /m, isotropic), whole processes. The truth: two reference
# renders A, B of TRUTH_SPP paths a pixel (seeds 1001, 1002) averaged (its own
# transient relative L1 error is about half the L1 between the two, printed).
# Then the reference at each of SPPS paths a pixel and IR at the config's
# settings (plus IR_SETTINGS, --set arguments) on each BACKENDS, each timed
# (/usr/bin/time: wall and user + system CPU) and compared with the truth:
# transient relative L1 against (A + B) / 2 (`tofsim compare`; it includes the
# truth's own noise), and the noise-corrected relative RMS error against the
# truth A and B estimate (noise_corrected.py: unbiased however noisy A and B
# are, so a cheap pair does at 64^2 or 128^2 what a 32768-path truth does at
# 32^2), and the energy over the truth's. Last, the reference's time at IR's
# error, interpolated in log-log between the two counts around it
# (extrapolated as error ~ 1 / sqrt(time) from the nearest count outside the
# range), over IR's: by L1 and by the noise-corrected RMS.
# A truth already in OUTDIR (OUTDIR/truth_a and truth_b) is reused: rerunning into
# the same folder after a change to IR costs only the sweep and IR (SPPS ""
# skips the sweep, keeping OUTDIR/table.txt's reference rows).
# Usage: bench/fog_box/run.sh [RES=32] [TRUTH_SPP=32768] [SPPS="16 64 256 1024 4096"]
#        [BACKENDS=cpu] [OUTDIR]   (PYTHON: a python3 with numpy, /usr/bin/python3;
#        IR_SETTINGS: e.g. "--set render.indirect.vpls_per_bounce=2048"; NICE: a nice level)
set -euo pipefail
cd "$(dirname "$0")/../.."
res=${1:-32}
truth_spp=${2:-32768}
spps=${3-"16 64 256 1024 4096"}  # "" (given): no sweep, table.txt kept
backends=${4-cpu}  # "" (given): no IR; gl needs IR_SETTINGS="--set render.indirect.gather_pairs=0"
out=${5:-$(mktemp -d)}
py=${PYTHON:-/usr/bin/python3}
tofsim=${TOFSIM:-./build/apps/cli/tofsim}
mkdir -p "$out"
: >"$out/rows.txt"
[ -n "$spps" ] && : >"$out/table.txt"
touch "$out/table.txt"
here=bench/fog_box
read -r -a ir_settings <<<"${IR_SETTINGS:-}"
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "${res}x${res}, truth ${truth_spp} paths x 2, reference at ${spps}, IR on ${backends}"
common=(--set "camera.resolution=[$res, $res]" -q)
reference() {  # SPP SEED: the reference's settings
  echo --set render.renderer=reference --set "render.reference.samples_per_pixel=$1" --set "render.seed=$2"
}
errors() {  # X: "L1 | RMS | energy": X's L1 against the truth, noise-corrected relative RMS, energy
  "$py" "$here/noise_corrected.py" "$1" "$out/truth_a" "$out/truth_b" |
    awk '/rel_rms/ { printf "%.4f | %.4f | %.4f", $5, $3, $7 }'
}
timed() {  # NAME DIR SETTINGS...: renders the box into DIR timed, appends "NAME wall cpu" to rows.txt
  local name=$1 dir=$2
  shift 2
  /usr/bin/time -f "%e %U %S" -o "$dir.time" nice -n "${NICE:-0}" "$tofsim" render configs/fog_box.yaml "${common[@]}" \
    -o "$dir" "$@" >/dev/null 2>&1
  read -r wall user sys <"$dir.time"
  echo "$name $wall $(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" >>"$out/rows.txt"
}
if [ ! -f "$out/truth_a/transient.npy" ] || [ ! -f "$out/truth_b/transient.npy" ]; then
  timed truth_a "$out/truth_a" $(reference "$truth_spp" 1001)
  timed truth_b "$out/truth_b" $(reference "$truth_spp" 1002)
  rm -rf "$out/truth"
fi
if [ ! -f "$out/truth/transient.npy" ]; then
  rm -rf "$out/truth" && cp -r "$out/truth_a" "$out/truth"
  "$py" -c 'import numpy as np, sys
a, b = (np.load(sys.argv[i] + "/transient.npy") for i in (1, 2))
np.save(sys.argv[3] + "/transient.npy", (0.5 * (a.astype(np.float64) + b)).astype(np.float32))' \
    "$out/truth_a" "$out/truth_b" "$out/truth"
fi
"$py" "$here/noise_corrected.py" "$out/truth_a" "$out/truth_a" "$out/truth_b" | awk "NR == 1"
echo "truth's own transient L1 ~ $("$py" "$here/noise_corrected.py" "$out/truth_a" "$out/truth_a" "$out/truth_b" | awk '/rel_rms/ { print $5 }') (half the L1 of its two halves)"
echo "| renderer | paths / settings | wall s | CPU s | transient relative L1 | noise-corrected relative RMS | energy |"
echo "|---|---|---|---|---|---|---|"
for spp in $spps; do
  timed "reference_$spp" "$out/ref$spp" $(reference "$spp" 1)
  echo "| reference | $spp | $(tail -1 "$out/rows.txt" | cut -d' ' -f2) | $(tail -1 "$out/rows.txt" | cut -d' ' -f3) | $(errors "$out/ref$spp") |" |
    tee -a "$out/table.txt"
done
for b in $backends; do
  timed "ir_$b" "$out/ir_$b" --backend "$b" "${ir_settings[@]}"
  echo "| ir ($b) | config ${IR_SETTINGS:-} | $(tail -1 "$out/rows.txt" | cut -d' ' -f2) | $(tail -1 "$out/rows.txt" | cut -d' ' -f3) | $(errors "$out/ir_$b") |" |
    tee -a "$out/table.txt"
done
"$py" - "$out/table.txt" <<'PY'
import math, sys
rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in open(sys.argv[1])]

def at_error(points, err):
    """The reference's time at `err` from (time, error) points: log-log
    between the two around it, else 1 / sqrt(time) from the nearest."""
    below = [p for p in points if p[1] <= err]
    above = [p for p in points if p[1] > err]
    if below and above:
        (t0, e0), (t1, e1) = max(above), min(below)
        return math.exp(math.log(t0) + (math.log(err) - math.log(e0)) * (math.log(t1) - math.log(t0)) /
                        (math.log(e1) - math.log(e0))), "interpolated"
    t0, e0 = max(points) if not below else min(points)
    return t0 * (e0 / err) ** 2, "extrapolated as 1/sqrt(time)"

print("\nthe reference's time at IR's error, over IR's (wall; CPU), by the transient relative L1 "
      "against the truth and by the noise-corrected relative RMS:")
for r in rows:
    if not r[0].startswith("ir"):
        continue
    for ecol, name in ((4, "L1"), (5, "RMS")):
        err = float(r[ecol])
        line = f"{r[0]} {r[1]}: {name} {err:.4g}"
        for col, label in ((2, "wall"), (3, "CPU")):
            t, how = at_error(sorted((float(q[col]), float(q[ecol])) for q in rows if q[0] == "reference"),
                              err)
            line += f"; {label}: reference {t:.3g} s ({how}), IR {float(r[col]):.3g} s, {t / float(r[col]):.2f}x"
        print(line)
PY
