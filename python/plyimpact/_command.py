"""The `plyimpact` command of a pip installation: the program built beside the module (setup.py)."""

import os
import sys


def main() -> None:
    program = os.path.join(os.path.dirname(__file__), "_bin", "plyimpact")
    if not os.path.exists(program):
        sys.exit("plyimpact: the command is not installed with this package (" + program + "): install with "
                 "`pip install --no-build-isolation .`, or use build/release/plyimpact")
    os.execv(program, [program, *sys.argv[1:]])
