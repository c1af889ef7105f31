# Sourced by the benches that time whole `tofsim render` processes
# (footprint_cost, camera_optics, capture_loop, medium_vpl_cost,
# scattering_delay): one timed run recorded as a table row and a sample, the
# samples' medians, and the tables' headers. The caller sets `out` (its
# folder), or calls bench_args.
#
# timed_render RUN NAME DIR ARGS...: runs `tofsim render ARGS... -q -o DIR`
# (the binary $TOFSIM, ./build/apps/cli/tofsim unless set)
# under /usr/bin/time, prints "| RUN | NAME | render s | wall s | CPU s | max
# RSS MB |" (render s: transient.json's stats.seconds, nan without it),
# appends "NAME render wall cpu" to $out/samples.txt and removes DIR.
timed_render() {
  local run=$1 name=$2 dir=$3
  shift 3
  /usr/bin/time -f "%e %U %S %M" -o "$dir.time" "${TOFSIM:-./build/apps/cli/tofsim}" render "$@" -q -o "$dir"
  local seconds=nan wall user sys rss cpu
  if [ -f "$dir/transient.json" ]; then
    seconds=$(sed -n 's/.*"seconds": *\([0-9.eE+-]*\).*/\1/p' "$dir/transient.json" | head -1)
  fi
  read -r wall user sys rss <"$dir.time"
  cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
  printf "| %d | %s | %s | %.2f | %s | %.0f |\n" "$run" "$name" "$seconds" "$wall" "$cpu" "$((rss / 1024))"
  echo "$name $seconds $wall $cpu" >>"$out/samples.txt"
  rm -rf "$dir" "$dir.time"
}

# median_of NAME COLUMN: the median of a sample column (2 render, 3 wall, 4 CPU).
median_of() {
  awk -v n="$1" -v c="$2" '$1 == n { print $c }' "$out/samples.txt" | sort -g |
    awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}

# ratio_row NAME BASE: "| NAME | render | ratio | wall | ratio | CPU | ratio |" against BASE's medians.
ratio_row() {
  awk -v n="$1" -v r="$(median_of "$1" 2)" -v w="$(median_of "$1" 3)" -v c="$(median_of "$1" 4)" \
    -v br="$(median_of "$2" 2)" -v bw="$(median_of "$2" 3)" -v bc="$(median_of "$2" 4)" \
    'BEGIN { printf "| %s | %.3f | %.2fx | %.2f | %.2fx | %.2f | %.2fx |\n", n, r, r / br, w, w / bw, c, c / bc }'
}

# bench_args RUNS_DEFAULT [RUNS] [OUTDIR]: sets `runs` and `out` (made; a
# temporary folder unless given) from a bench's last two arguments.
bench_args() {
  runs=${2:-$1}
  out=${3:-$(mktemp -d)}
  mkdir -p "$out"
}

# runs_header: the machine's line and the runs table's header.
runs_header() {
  echo "commit: $(git rev-parse --short HEAD), $(nproc) CPUs, load: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "| run | variant | render s (stats.seconds) | process wall s | process CPU s | max RSS MB |"
  echo "|---|---|---|---|---|---|"
}

# medians_header: the medians table's header, after a blank line.
medians_header() {
  echo
  echo "| variant | median render s | ratio | median process wall s | ratio | median process CPU s | ratio |"
  echo "|---|---|---|---|---|---|---|"
}

# time_variants BASE ARGS...: each of the caller's `variants` ("NAME:EXTRA
# ARGS", split at spaces) rendered `runs` times, interleaved so that the
# machine's load hits them alike, as `tofsim render ARGS... EXTRA...`; the
# two tables, ratios to variant BASE's medians.
time_variants() {
  local base=$1 r v name extra
  shift
  runs_header
  for ((r = 1; r <= runs; ++r)); do
    for v in "${variants[@]}"; do
      IFS=: read -r name extra <<<"$v"
      # shellcheck disable=SC2086
      timed_render "$r" "$name" "$out/$name.$r" "$@" $extra
    done
  done
  medians_header
  for v in "${variants[@]}"; do ratio_row "${v%%:*}" "$base"; done
}
