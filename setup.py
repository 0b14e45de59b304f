"""Builds the compiled part of the Python package `cagd` with the project's CMake (pyproject.toml).

The extension `cagd._cagd` is the CMake target cagd_python (python/CMakeLists.txt): setup.py
configures a build tree of its own (library and module only, Release), builds that one target and
copies the module (and the OpenCASCADE plugin libcagd_occt.so, when built) beside python/cagd/__init__.py. The version is the CMake project's.
Environment: CAGD_BUILD_DIR names an existing, configured build tree to build the target in instead
(a no-op when it is up to date; the project's tests use it); CMAKE_BUILD_PARALLEL_LEVEL the jobs.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*cagd_repro\s+VERSION\s+([0-9.]+)", text)
    if not match:
        sys.exit("setup.py: no 'project(cagd_repro VERSION …)' in CMakeLists.txt")
    return match.group(1)


class CMakeModule(Extension):
    """The pybind11 module built by CMake: no sources for setuptools to compile."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class BuildWithCMake(build_ext):
    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        build_dir = os.environ.get("CAGD_BUILD_DIR")
        if build_dir:
            build_dir = Path(build_dir).resolve()
        else:
            build_dir = Path(self.build_temp).resolve() / "cmake"
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release", f"-DPython_EXECUTABLE={sys.executable}",
                 "-DCAGD_BUILD_PYTHON=ON", "-DCAGD_BUILD_TESTS=OFF", "-DCAGD_BUILD_EXPERIMENTS=OFF", "-DCAGD_BUILD_CLI=OFF", "-DCAGD_BUILD_BENCH=OFF", "-DCAGD_BUILD_PEERS=OFF"],
                check=True)
        env = dict(os.environ)
        env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "cagd_python"], check=True, env=env)
        built = sorted((build_dir / "python" / "cagd").glob("_cagd*.so"))
        if not built:
            sys.exit(f"setup.py: CMake built no _cagd module under {build_dir / 'python' / 'cagd'}")
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)
        # The OpenCASCADE plugin (a library built with OpenCASCADE loads it from beside the module).
        plugin = build_dir / "libcagd_occt.so"
        if plugin.exists():
            shutil.copyfile(plugin, target.parent / plugin.name)


setup(version=project_version(), ext_modules=[CMakeModule("cagd._cagd")], cmdclass={"build_ext": BuildWithCMake})
