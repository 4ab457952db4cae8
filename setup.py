# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds cgal_rrht._core with the project's CMake (option CGAL_RRHT_BUILD_PYTHON),
so that CGAL, Eigen, TBB and pybind11 are found as for the C++ build.

Extra CMake arguments come from the environment variable CMAKE_ARGS, e.g.
``CMAKE_ARGS=-DCGAL_DIR=/path/to/CGAL pip install --no-build-isolation .``
"""

import os
import shlex
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
        module = Path(self.get_ext_fullpath(ext.name)).resolve()
        build = Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DCGAL_RRHT_BUILD_PYTHON=ON",
            "-DCGAL_RRHT_BUILD_TESTS=OFF",
            "-DCGAL_RRHT_BUILD_EXAMPLES=OFF",
            f"-DPython_EXECUTABLE={sys.executable}",
            f"-DCGAL_RRHT_PYTHON_PACKAGE_DIR={module.parent}",
        ] + shlex.split(os.environ.get("CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "cgal_rrht_core", "-j", jobs], check=True)


setup(ext_modules=[CMakeExtension("cgal_rrht._core")], cmdclass={"build_ext": CMakeBuild})
