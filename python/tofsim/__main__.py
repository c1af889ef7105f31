"""`python -m tofsim ARGS` (and the `tofsim` command of a pip install) runs
the tofsim CLI with ARGS: the binary installed inside the package by
`pip install .` (tofsim/bin/tofsim), else the one on PATH (the Debian package,
`cmake --install`)."""

import os
import shutil
import sys
from pathlib import Path


def cli_path():
    inside = Path(__file__).resolve().parent / "bin" / "tofsim"
    if inside.is_file() and os.access(inside, os.X_OK):
        return str(inside)
    # Not this script itself: a pip install's `tofsim` on PATH is this module.
    found = shutil.which("tofsim")
    if found and Path(found).resolve() != Path(sys.argv[0]).resolve():
        return found
    return None


def main():
    path = cli_path()
    if path is None:
        sys.stderr.write("tofsim: the tofsim command is not installed beside this module "
                         "(pip install . installs both; see README)\n")
        return 1
    os.execv(path, [path] + sys.argv[1:])


if __name__ == "__main__":
    sys.exit(main())
