#!/usr/bin/env bash
# Renders every example config on both IR backends with two tofsim binaries
# and compares the arrays and pictures they write byte for byte: the check
# that a refactor keeps the output (issue 40). JSON and HDF5 files are left
# out (their render statistics hold times), and the folder's lock .tofsim.lock
# (it holds the pid of its last writer); everything else must be equal.
#
#   bash scripts/same-bytes.sh BEFORE_TOFSIM AFTER_TOFSIM [config.yaml ...]
#
# Prints one line per config and backend, "same" or the files that differ,
# and exits 1 when any differ. Default: every configs/*.yaml.
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 BEFORE_TOFSIM AFTER_TOFSIM [config.yaml ...]" >&2
  exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
shift 2
cd "$(dirname "$0")/.."
configs=("$@")
[[ ${#configs[@]} -gt 0 ]] || configs=(configs/*.yaml)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for config in "${configs[@]}"; do
  name=$(basename "$config" .yaml)
  for backend in gl cpu; do
    for side in before after; do
      bin=$before
      [[ $side == after ]] && bin=$after
      if ! "$bin" render "$config" --backend "$backend" -o "$work/$side/$name-$backend" \
          > "$work/$side-$name-$backend.log" 2>&1; then
        echo "$name $backend: $side failed (log below)"
        tail -5 "$work/$side-$name-$backend.log"
        status=1
        continue 2
      fi
    done
    differ=$(cd "$work/before/$name-$backend" &&
      find . -type f ! -name '.tofsim.lock' ! -name '*.json' ! -name '*.h5' ! -name '*.hdf5' ! -name '*.yaml' ! -name '*.txt' | sort |
      while read -r f; do
        cmp -s "$f" "$work/after/$name-$backend/$f" || echo "$f"
      done)
    if [[ -z $differ ]]; then
      echo "$name $backend: same"
    else
      echo "$name $backend: differ: $(echo $differ)"
      status=1
    fi
  done
done
exit $status
