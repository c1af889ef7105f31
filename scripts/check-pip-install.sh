#!/usr/bin/env bash
# Checks `pip install .` end to end in a scratch venv (not in CI: it builds
# the whole project again): a venv from Debian's python3 that sees Debian's
# numpy, pip install . (scikit-build-core from PyPI as the build backend;
# ccache when installed), then `import tofsim`, `python -m tofsim --help`,
# the `tofsim` command and a small render into a scratch folder.
set -euo pipefail
cd "$(dirname "$0")/.."
venv="$(mktemp -d)/venv"
trap 'rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
source scripts/compiler-cache.sh
CMAKE_ARGS="${cache_flags[*]:-}" "$venv/bin/pip" install --quiet .
cd "$(dirname "$venv")"
"$venv/bin/python" -c "import tofsim, numpy; print('import tofsim:', tofsim.__file__)"
"$venv/bin/python" -m tofsim --help | head -n 3
"$venv/bin/tofsim" presets | head -n 3
# The CLI with its video module (inside the package: tofsim/lib).
"$venv/bin/tofsim" render "$OLDPWD/configs/cornell_box.yaml" -o out --set 'camera.resolution=[16,16]' \
  --set 'sensors=[]' --set time.bins=64
ls out/transient.npy out/transient.mp4
"$venv/bin/python" - "$OLDPWD" <<'PY'
import sys, tofsim
config = tofsim.load_config(sys.argv[1] + "/configs/cornell_box.yaml",
                            overrides={"camera.resolution": [16, 16], "time.bins": 64,
                                       "sensors": []})
result = tofsim.render(config)
print("render:", result.transient.shape)
PY
echo "check-pip-install: ok"
