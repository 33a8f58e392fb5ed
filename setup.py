"""The wheel of the Python module dtwin (pyproject.toml; docs/install.md).

`python3 -m build --wheel --no-isolation` (Debian's python3-build) runs this: it builds the CMake
target dtwin_python in the build folder DTWIN_BUILD_DIR (default build/, configured as
scripts/build.sh --demo does when it is not), installs the component `wheel` (the package dtwin/:
the module, its stub, py.typed, the data, the licences and the bundled Release Simbody) into the
wheel's tree, and setuptools packs that tree. The wheel is for the Python the module is built for
(Debian's /usr/bin/python3)."""
import importlib.machinery
import os
import re
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_ext import build_ext
from setuptools.dist import Distribution

HERE = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(HERE, "CMakeLists.txt")) as f:
        return re.search(r"project\(dtwin VERSION ([0-9.]+)", f.read()).group(1)


class CMakeBuild(build_ext):
    """The package dtwin/ as CMake installs it, in place of setuptools' compilation of extensions."""

    def run(self):
        build_dir = os.path.abspath(os.environ.get("DTWIN_BUILD_DIR", os.path.join(HERE, "build")))
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", HERE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                            "-DDTWIN_BUILD_TESTS=OFF", "-DPython3_EXECUTABLE=" + sys.executable], check=True)
        subprocess.run(["cmake", "--build", build_dir, "-j", str(os.cpu_count() or 1), "--target", "dtwin_python"],
                       check=True)
        tree = os.path.abspath(self.build_lib)
        shutil.rmtree(os.path.join(tree, "dtwin"), ignore_errors=True)
        subprocess.run(["cmake", "--install", build_dir, "--component", "wheel", "--prefix", tree], check=True)
        modules = [n for n in os.listdir(os.path.join(tree, "dtwin")) if n.startswith("dtwin.") and n.endswith(".so")]
        if len(modules) != 1 or not any(modules[0].endswith(s) for s in importlib.machinery.EXTENSION_SUFFIXES):
            sys.exit(f"setup.py: the module built in {build_dir} ({', '.join(modules) or 'none'}) is not for "
                     f"this Python ({sys.executable}, {' '.join(importlib.machinery.EXTENSION_SUFFIXES)}); "
                     "build the wheel with the Python CMake built the module for")


class BinaryDistribution(Distribution):
    """A compiled module: the wheel is tagged with this Python and platform."""

    def has_ext_modules(self):
        return True


# setuptools' own folders (the tree it packs, its egg-info) under build/wheel, not in the sources.
SETUPTOOLS_DIR = os.path.join(HERE, "build", "wheel")
os.makedirs(SETUPTOOLS_DIR, exist_ok=True)
setup(version=project_version(), packages=[], cmdclass={"build_ext": CMakeBuild}, distclass=BinaryDistribution,
      options={"build": {"build_base": SETUPTOOLS_DIR}, "egg_info": {"egg_base": SETUPTOOLS_DIR}})
