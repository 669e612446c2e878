"""Builds the compiled part of benchdragon with the project's CMake (pyproject.toml has the rest).

The extension is the CMake target benchdragon_python: CMake configures a build of its own under
setuptools' temporary folder and builds that target alone (the libraries it needs, no tool and
no tests), then the package laid out in that build (the module, the Python files, the assets) is
copied where setuptools packs the wheel. DRAGON_PYTHON_BUILD_DIR names an existing configured
build to use instead (CI installs from the build it has tested).
"""

import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        source = os.path.dirname(os.path.abspath(__file__))
        build = os.environ.get("DRAGON_PYTHON_BUILD_DIR")
        if build:
            build = os.path.abspath(build)
        else:
            build = os.path.join(os.path.abspath(self.build_temp), "cmake")
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(["cmake", "-S", source, "-B", build, *generator, "-DCMAKE_BUILD_TYPE=Release",
                                   "-DDRAGON_BUILD_TESTS=OFF", "-DDRAGON_BUILD_BENCHMARKS=OFF",
                                   "-DDRAGON_WITH_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", build, "--target", "benchdragon_python", "--parallel",
                               str(os.cpu_count() or 1)])
        package = os.path.join(build, "python", "benchdragon")
        target = os.path.dirname(os.path.abspath(self.get_ext_fullpath(ext.name)))
        shutil.copytree(package, target, dirs_exist_ok=True, ignore=shutil.ignore_patterns("__pycache__"))


setup(
    ext_modules=[CMakeExtension("benchdragon._benchdragon")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-python"}},
)
