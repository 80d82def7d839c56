"""setup.py, the build that `pip install --no-build-isolation .` runs: a Python that cannot make a wheel is
told so at once, with what to do (issue 82: "invalid command 'bdist_wheel'" after 3 s).

Run by ctest (Python.pytest); PLYIMPACT_SOURCE_DIR is the repository.
"""
import importlib.util
import os
from pathlib import Path

import setuptools

SOURCE = Path(os.environ.get("PLYIMPACT_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def load_setup():
    """setup.py as a module: its setup() call runs only as __main__, as pip's build backend runs it."""
    spec = importlib.util.spec_from_file_location("plyimpact_setup", SOURCE / "setup.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_a_setuptools_older_than_70_1_without_wheel_is_refused_with_what_to_do(monkeypatch):
    setup = load_setup()
    real_find_spec = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "wheel" else real_find_spec(name, *a))
    monkeypatch.setattr(setuptools, "__version__", "65.5.0")
    said = setup.missing_build_tools()
    assert said is not None
    assert "lacks the 'wheel' package" in said
    assert "setuptools 65.5.0" in said
    assert "/usr/bin/python3 -m pip install --no-build-isolation ." in said
    # setuptools 70.1 and later make wheels themselves
    monkeypatch.setattr(setuptools, "__version__", "70.1.0")
    assert setup.missing_build_tools() is None


def test_debians_python_has_what_the_build_needs():
    # The suite runs on Debian's interpreter (scripts/install-deps installs python3-wheel beside
    # python3-setuptools 66): nothing is missing.
    assert load_setup().missing_build_tools() is None
