"""The compiled parts of `pip install --no-build-isolation .` (pyproject.toml holds the rest).

CMake builds the pybind11 module (plyimpact._core) and the command; both go into the package, the
command as plyimpact/_bin/plyimpact, which the `plyimpact` entry point (plyimpact/_command.py) runs.
PLYIMPACT_CMAKE_BUILD_DIR names an existing, configured build folder to build in (a developer's
build/release: nothing compiled twice); otherwise a Release build is configured under build/pip.
The example decks go into the package too (plyimpact/examples). pip shows a build backend's output only
with -v, so the build says what it is doing on the terminal itself (issue 82: ten minutes of "Building
wheel... still running").
"""

import importlib.util
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def missing_build_tools() -> str | None:
    """What this Python lacks to build a wheel without build isolation, in words; None when nothing.

    setuptools makes wheels with the `wheel` package before version 70.1 and by itself after; a Python
    without either stopped pip after 3 s with "invalid command 'bdist_wheel'" (issue 82)."""
    import setuptools

    version = tuple(int(p) for p in setuptools.__version__.split(".")[:2] if p.isdigit())
    if version >= (70, 1) or importlib.util.find_spec("wheel") is not None:
        return None
    return (f"plyimpact: this Python ({sys.executable}, setuptools {setuptools.__version__}) cannot build a "
            "wheel: it lacks the 'wheel' package (setuptools older than 70.1 needs it). Use Debian's Python "
            "(/usr/bin/python3 -m pip install --no-build-isolation .; scripts/install-deps --dev "
            "installs python3-wheel), or install 'wheel' into this one first (docs/install.md, \"pip install\").")


def say(line: str) -> None:
    """A progress line on the terminal, which pip leaves to the build (it shows our output only with -v)."""
    try:
        with open("/dev/tty", "w", encoding="utf-8") as tty:
            tty.write(line + "\n")
    except OSError:
        print(line, file=sys.stderr, flush=True)


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        start = time.monotonic()
        build = os.environ.get("PLYIMPACT_CMAKE_BUILD_DIR")
        if build is None:
            say("plyimpact: building the engine, the Python module and the command with CMake in build/pip: "
                "about 10 minutes on two cores the first time (pip install -v shows each compiler line)")
            build = str(ROOT / "build" / "pip")
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                 "-DPLYIMPACT_BUILD_TESTS=OFF", "-DPLYIMPACT_BUILD_BENCH=OFF", "-DPLYIMPACT_PYTHON=ON",
                 f"-DPython_EXECUTABLE={sys.executable}"],
                check=True)
        subprocess.run(["cmake", "--build", build, "--target", "plyimpact_python", "plyimpact"], check=True)
        module = next((Path(build) / "python" / "plyimpact").glob("_core*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(module, target)
        # The command and the examples beside the module; an editable install (pip install -e) copies only
        # the module into the sources, so they go straight there (ignored by git, as the module is).
        package = ROOT / "python" / "plyimpact" if getattr(self, "editable_mode", False) else target.parent
        command = package / "_bin" / "plyimpact"
        command.parent.mkdir(exist_ok=True)
        shutil.copy2(Path(build) / "plyimpact", command)
        shutil.copytree(ROOT / "examples", package / "examples", dirs_exist_ok=True)
        say(f"plyimpact: built in {time.monotonic() - start:.0f} s")


if __name__ == "__main__":  # as pip's build backend runs it; tests import missing_build_tools alone
    if (missing := missing_build_tools()) is not None:
        sys.exit(missing)
    setup(ext_modules=[CMakeExtension("plyimpact._core")], cmdclass={"build_ext": CMakeBuild})
