"""The compiled parts of `pip install --no-build-isolation .` (pyproject.toml holds the rest).

CMake builds the pybind11 module (plyimpact._core) and the command; both go into the package, the
command as plyimpact/_bin/plyimpact, which the `plyimpact` entry point (plyimpact/_command.py) runs.
PLYIMPACT_CMAKE_BUILD_DIR names an existing, configured build folder to build in (a developer's
build/release: nothing compiled twice); otherwise a Release build is configured under build/pip.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build = os.environ.get("PLYIMPACT_CMAKE_BUILD_DIR")
        if build is None:
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
        command = target.parent / "_bin" / "plyimpact"
        command.parent.mkdir(exist_ok=True)
        shutil.copy2(Path(build) / "plyimpact", command)


setup(ext_modules=[CMakeExtension("plyimpact._core")], cmdclass={"build_ext": CMakeBuild})
