"""Builds the cosserat Python package with the project's CMake and installs it: the compiled
core cosserat._core (python/cosserat_module.cpp) and the Python files of python/cosserat/.

  pip install --no-build-isolation .

The CMake build goes to a temporary directory under build/ of setuptools, Release, library and
module only. COSSERAT_BUILD_DIR=DIR reuses an existing CMake build directory instead (it builds
only what is out of date there): e.g. COSSERAT_BUILD_DIR=build after the README's commands.
COSSERAT_CMAKE_ARGS adds configure arguments.
"""
import glob
import os
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("COSSERAT_BUILD_DIR")
        if build_dir:
            build_dir = os.path.abspath(build_dir)
        else:
            build_dir = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            configure = [
                "cmake", "-S", HERE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                "-DBUILD_TESTING=OFF", "-DCOSSERAT_BUILD_BENCHMARKS=OFF",
                "-DCOSSERAT_BUILD_EXAMPLES=OFF", "-DCOSSERAT_BUILD_PYTHON=ON",
                f"-DPython_EXECUTABLE={sys.executable}",
            ] + shlex.split(os.environ.get("COSSERAT_CMAKE_ARGS", ""))
            subprocess.check_call(configure)
        jobs = str(os.cpu_count() or 1)
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "cosserat_python",
                               "-j", jobs])
        built = glob.glob(os.path.join(build_dir, "python", "cosserat", "_core*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one built core in {build_dir}/python/cosserat, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        # Where the package was built from: the live view serves that repository's web/.
        with open(os.path.join(os.path.dirname(target), "_source.py"), "w") as f:
            f.write(f"# Written by setup.py: the repository this package was built from.\n"
                    f"SOURCE_DIR = {HERE!r}\n")


setup(packages=["cosserat"], package_dir={"cosserat": "python/cosserat"},
      ext_modules=[CMakeExtension("cosserat._core")], cmdclass={"build_ext": CMakeBuild},
      zip_safe=False)
