#!/usr/bin/env bash
# The cost of a medium over vacuum (issue 42), whole processes: the demo
# (configs/cornell_box.yaml as README.md's main job runs it: sensors and
# video) and configs/fog_lidar.yaml, each in vacuum (`medium={}`) and in fog
# (fog_lidar's own, `visibility: 40 m`; the demo gets the same fog), and
# fog_lidar with the fog's extinction all absorbed (sigma_a = sigma_t,
# sigma_s = 0: attenuation the same, no light scattered), on the cpu and gl
# backends, the variants interleaved within each round (the ratios come from
# one run). Per render: /usr/bin/time -v's wall, user + system CPU and max
# RSS, the render's stats.seconds and its direct pass (transient.json
# pass_seconds.direct: the surfaces' direct light and, with a medium, the
# single-scattering pass along the camera rays, which CpuDirectGather and
# the GL backend run after it). Then medians per variant and their ratios.
# Usage: bench/medium_cost/run.sh [ROUNDS=3] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
rounds=${1:-3}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
: >"$out/samples.txt"
tofsim=${TOFSIM:-./build/apps/cli/tofsim}
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
fog='medium={visibility: 40 m}'
absorbing='medium={sigma_a: 0.0978, sigma_s: 0}'   # 3.912 / 40 m, all absorbed
variants=(
  "demo_vacuum|configs/cornell_box.yaml|medium={}"
  "demo_fog|configs/cornell_box.yaml|$fog"
  "fog_lidar_vacuum|configs/fog_lidar.yaml|medium={}"
  "fog_lidar_fog|configs/fog_lidar.yaml|$fog"
  "fog_lidar_absorbing|configs/fog_lidar.yaml|$absorbing"
)
echo "| round | backend | variant | wall s | CPU s | max RSS MB | stats.seconds | direct pass s |"
echo "|---|---|---|---|---|---|---|---|"
for ((r = 1; r <= rounds; ++r)); do
  for backend in cpu gl; do
    for v in "${variants[@]}"; do
      IFS='|' read -r name config medium <<<"$v"
      dir="$out/$name.$backend.$r"
      /usr/bin/time -v -o "$dir.time" "$tofsim" render "$config" --set "render.backend=$backend" \
        --set "$medium" -q -o "$dir" >/dev/null 2>&1
      python3 - "$dir" "$r" "$backend" "$name" "$out/samples.txt" <<'PY'
import json, re, sys
d, r, backend, name, samples = sys.argv[1:6]
t = open(d + ".time").read()
def field(label):
    return re.search(re.escape(label) + r": (\S+)", t).group(1)
w = field("Elapsed (wall clock) time (h:mm:ss or m:ss)").split(":")
wall = sum(float(x) * 60 ** i for i, x in enumerate(reversed(w)))
cpu = float(field("User time (seconds)")) + float(field("System time (seconds)"))
rss = int(field("Maximum resident set size (kbytes)")) / 1024
stats = json.load(open(d + "/transient.json"))["stats"]
direct = stats["pass_seconds"]["direct"]
print(f"| {r} | {backend} | {name} | {wall:.2f} | {cpu:.2f} | {rss:.0f} | {stats['seconds']:.3f} | {direct:.3f} |")
with open(samples, "a") as f:
    f.write(f"{backend} {name} {wall} {cpu} {rss} {stats['seconds']} {direct}\n")
PY
      rm -rf "$dir" "$dir.time"
    done
  done
done
python3 - "$out/samples.txt" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
med = {}
for b, n, *v in rows:
    med.setdefault((b, n), []).append([float(x) for x in v])
m = {k: [statistics.median(c) for c in zip(*v)] for k, v in med.items()}
print("\nmedians over the rounds; ratios against the variant's vacuum (fog_lidar_absorbing: against its fog)")
print("| backend | variant | wall s | ratio | CPU s | ratio | max RSS MB | stats.seconds | ratio | direct pass s |")
print("|---|---|---|---|---|---|---|---|---|---|")
for (b, n), (wall, cpu, rss, sec, direct) in sorted(m.items()):
    base = n.rsplit("_", 1)[0] + ("_fog" if n.endswith("absorbing") else "_vacuum")
    bw, bc, _, bs, _ = m[(b, base)]
    print(f"| {b} | {n} | {wall:.2f} | {wall / bw:.2f}x | {cpu:.2f} | {cpu / bc:.2f}x | {rss:.0f} | "
          f"{sec:.3f} | {sec / bs:.2f}x | {direct:.3f} |")
PY
