# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds the Python module with the project's own CMake build.

`pip install .` (see pyproject.toml) runs this: the extension expmap._expmap
is the CMake target expmap_python, configured with only the module enabled
(no tests, tools, examples or benchmarks) against the system's C++
dependencies, for the interpreter that runs pip. Extra CMake arguments can be
given in the environment as EXPMAP_CMAKE_ARGS (split like a shell command
line); CMAKE_BUILD_PARALLEL_LEVEL sets the number of compile jobs.
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent


def project_version():
    """The library's version, written once in include/expmap/version.h."""
    header = (SOURCE_DIR / "include" / "expmap" / "version.h").read_text()
    match = re.search(r'#define EXPMAP_VERSION_STRING "([^"]+)"', header)
    if not match:
        raise RuntimeError("include/expmap/version.h defines no EXPMAP_VERSION_STRING")
    return match.group(1)


class CMakeExtension(Extension):
    """An extension that the CMake target `target` builds."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            raise RuntimeError(
                "expmap: building the Python module needs CMake 3.18 or newer on PATH "
                "(Debian: apt install cmake; see README.md, Dependencies)")
        build_dir = Path(self.build_temp).resolve() / "cmake"
        build_dir.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(SOURCE_DIR), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DEXPMAP_BUILD_PYTHON=ON",
            "-DEXPMAP_BUILD_TESTS=OFF",
            "-DEXPMAP_BUILD_TOOLS=OFF",
            "-DEXPMAP_BUILD_EXAMPLES=OFF",
            "-DEXPMAP_BUILD_BENCHMARKS=OFF",
            f"-DPython3_EXECUTABLE={sys.executable}",
        ]
        try:
            # In an isolated build pybind11 comes from the build requirements;
            # otherwise CMake finds the system's (Debian: pybind11-dev).
            import pybind11
            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass
        configure += shlex.split(os.environ.get("EXPMAP_CMAKE_ARGS", ""))
        build = ["cmake", "--build", str(build_dir), "--target", ext.target]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        self._run(configure, "configure the build (are CGAL, Eigen, SuiteSparse, METIS, "
                             "LAPACK, Boost and pybind11 installed? README.md, Dependencies)")
        self._run(build, "compile the module")

        built = sorted((build_dir / "python" / "expmap").glob("_expmap*.so")) + \
            sorted((build_dir / "python" / "expmap").glob("_expmap*.pyd"))
        if not built:
            raise RuntimeError(f"expmap: CMake built no _expmap module in {build_dir}")
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], destination)

    @staticmethod
    def _run(command, what):
        print(" ".join(shlex.quote(c) for c in command), flush=True)
        if subprocess.call(command) != 0:
            raise RuntimeError(f"expmap: CMake could not {what}; its messages are above")


setup(
    version=project_version(),
    ext_modules=[CMakeExtension("expmap._expmap", target="expmap_python")],
    cmdclass={"build_ext": CMakeBuild},
    # The checkout's build/ is the CMake build tree of scripts/build.sh;
    # setuptools works in a folder of its own inside it.
    options={"build": {"build_base": "build/python-package"}},
    zip_safe=False,
)
