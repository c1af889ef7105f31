#!/usr/bin/env bash
# IR against the reference path tracer at equal transient error on issue
# 42's fog box (configs/fog_box.yaml: a closed 2 m box, fog sigma_s 1 /m,
# sigma_a 0.02 /m, isotropic), whole processes. The truth: two reference
# renders of TRUTH_SPP paths a pixel (seeds 1001, 1002) averaged (its own
# transient relative L1 error is about half the L1 between the two, printed).
# Then the reference at each of SPPS paths a pixel and IR at the config's
# settings on each BACKENDS, each timed (/usr/bin/time: wall and user +
# system CPU) and compared with the truth (`tofsim compare`: transient
# relative L1). Last, the reference's wall time at IR's error, interpolated
# in log-log between the two counts around it (extrapolated as error ~
# 1 / sqrt(time) from the nearest count outside the range), over IR's.
# A truth already in OUTDIR (OUTDIR/truth) is reused: rerunning into the same
# folder after a change to IR costs only the sweep and IR.
# Usage: bench/fog_box/run.sh [RES=32] [TRUTH_SPP=32768] [SPPS="16 64 256 1024 4096"]
#        [BACKENDS="cpu gl"] [OUTDIR]   (PYTHON: a python3 with numpy, /usr/bin/python3)
set -euo pipefail
cd "$(dirname "$0")/../.."
res=${1:-32}
truth_spp=${2:-32768}
spps=${3:-"16 64 256 1024 4096"}
backends=${4:-"cpu gl"}
out=${5:-$(mktemp -d)}
py=${PYTHON:-/usr/bin/python3}
tofsim=${TOFSIM:-./build/apps/cli/tofsim}
mkdir -p "$out"
: >"$out/rows.txt"
: >"$out/table.txt"
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "${res}x${res}, truth ${truth_spp} paths x 2, reference at ${spps}, IR on ${backends}"
common=(--set "camera.resolution=[$res, $res]" -q)
reference() {  # SPP SEED: the reference's settings
  echo --set render.renderer=reference --set "render.reference.samples_per_pixel=$1" --set "render.seed=$2"
}
transient_l1() {  # A B: A's transient relative L1 against B
  "$tofsim" compare "$1" "$2" -o "$1.compare" 2>/dev/null | awk '/^transient relative L1/ { print $4 }'
}
timed() {  # NAME DIR SETTINGS...: renders the box into DIR timed, appends "NAME wall cpu" to rows.txt
  local name=$1 dir=$2
  shift 2
  /usr/bin/time -f "%e %U %S" -o "$dir.time" "$tofsim" render configs/fog_box.yaml "${common[@]}" \
    -o "$dir" "$@" >/dev/null 2>&1
  read -r wall user sys <"$dir.time"
  echo "$name $wall $(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }')" >>"$out/rows.txt"
}
if [ ! -f "$out/truth/transient.npy" ]; then
  timed truth_a "$out/truth_a" $(reference "$truth_spp" 1001)
  timed truth_b "$out/truth_b" $(reference "$truth_spp" 1002)
  rm -rf "$out/truth" && cp -r "$out/truth_a" "$out/truth"
  "$py" -c 'import numpy as np, sys
a, b = (np.load(sys.argv[i] + "/transient.npy") for i in (1, 2))
np.save(sys.argv[3] + "/transient.npy", (0.5 * (a.astype(np.float64) + b)).astype(np.float32))' \
    "$out/truth_a" "$out/truth_b" "$out/truth"
fi
echo "truth's own transient L1 ~ $(awk -v e="$(transient_l1 "$out/truth_a" "$out/truth_b")" 'BEGIN { print e / 2 }') (half the L1 of its two halves)"
echo "| renderer | paths / settings | wall s | CPU s | transient relative L1 |"
echo "|---|---|---|---|---|"
for spp in $spps; do
  timed "reference_$spp" "$out/ref$spp" $(reference "$spp" 1)
  echo "| reference | $spp | $(tail -1 "$out/rows.txt" | cut -d' ' -f2) | $(tail -1 "$out/rows.txt" | cut -d' ' -f3) | $(transient_l1 "$out/ref$spp" "$out/truth") |" |
    tee -a "$out/table.txt"
done
for b in $backends; do
  timed "ir_$b" "$out/ir_$b" --backend "$b"
  echo "| ir ($b) | config | $(tail -1 "$out/rows.txt" | cut -d' ' -f2) | $(tail -1 "$out/rows.txt" | cut -d' ' -f3) | $(transient_l1 "$out/ir_$b" "$out/truth") |" |
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

print("\nthe reference's time at IR's transient error, over IR's (wall; CPU):")
for r in rows:
    if not r[0].startswith("ir"):
        continue
    err = float(r[4])
    line = f"{r[0]}: error {err:.4g}"
    for col, label in ((2, "wall"), (3, "CPU")):
        t, how = at_error(sorted((float(q[col]), float(q[4])) for q in rows if q[0] == "reference"), err)
        line += f"; {label}: reference {t:.3g} s ({how}), IR {float(r[col]):.3g} s, {t / float(r[col]):.2f}x"
    print(line)
PY
