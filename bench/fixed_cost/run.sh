#!/usr/bin/env bash
# The whole run of the demo against its gathers (issue 27, item 2): the
# Cornell box demo (configs/cornell_box.yaml, 128x128, 640 bins, direct and
# indirect components) on the CPU backend without video and sensors,
# RUNS times. Per run: the process's wall, user and system seconds and max
# RSS (/usr/bin/time), the render's stats.seconds and its passes
# (transient.json pass_seconds: the gathers, "other" is everything else:
# buffers, the non-finite check, writing the volumes), the bytes written
# and the writing's MB/s over "other"; then `dd` writing as many bytes to
# the same folder with an fsync, buffered and direct, the disk's own speed
# for the comparison.
# Usage: bench/fixed_cost/run.sh [RUNS=5] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
runs=${1:-5}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| run | wall s | user s | sys s | max RSS MB | stats.seconds | gathers s | other s | MB written | MB/s over other |"
echo "|---|---|---|---|---|---|---|---|---|---|"
bytes=0
for ((r = 1; r <= runs; ++r)); do
  dir="$out/demo.$r"
  /usr/bin/time -f "%e %U %S %M" -o "$dir.time" ./build/apps/cli/tofsim render \
    configs/cornell_box.yaml --backend cpu --set output.video=false --set 'sensors=[]' -q -o "$dir"
  read -r wall user sys rss <"$dir.time"
  bytes=$(du -sb "$dir" | cut -f1)
  python3 - "$dir/transient.json" "$r" "$wall" "$user" "$sys" "$rss" "$bytes" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))["stats"]
p = stats["pass_seconds"]
run, wall, user, sys_s, rss, written = sys.argv[2:8]
other = p["other"]
gathers = stats["seconds"] - other
mb = int(written) / 1e6
print(f"| {run} | {wall} | {user} | {sys_s} | {int(rss) / 1024:.0f} | {stats['seconds']:.3f} | "
      f"{gathers:.3f} | {other:.3f} | {mb:.0f} | {mb / other:.0f} |")
PY
  rm -rf "$dir" "$dir.time"
done
echo
# Buffered (through the page cache) and direct (O_DIRECT, as tofsim writes
# files past 8 MiB where the file system takes it): on a virtual machine
# whose host reclaims free pages the first differs from run to run by seconds.
echo "dd, the same bytes to the same folder, buffered with an fsync:"
dd if=/dev/zero of="$out/dd.bin" bs=1M count=$((bytes / 1048576)) conv=fsync 2>&1 | tail -1
rm -f "$out/dd.bin"
echo "dd, the same bytes to the same folder, O_DIRECT with an fsync:"
dd if=/dev/zero of="$out/dd.bin" bs=4M count=$((bytes / 4194304)) oflag=direct conv=fsync 2>&1 | tail -1
rm -f "$out/dd.bin"
