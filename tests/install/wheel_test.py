"""The wheel (pyproject.toml, setup.py; docs/install.md): `python3 -m build --wheel --no-isolation`
packs the package dtwin/ (the module, its stub, py.typed, the data, the licences, the bundled
Simbody); installed offline into a fresh virtual environment (`pip install --no-index`), `import
dtwin` needs no setting and docs/python.md's example runs there as written.

CTest sets DTWIN_BUILD_DIR (the build whose module is packed), DTWIN_SOURCE_DIR and
DTWIN_SIMBODY_RELEASE (empty for Debian's binary Simbody)."""
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import zipfile

BUILD = os.environ["DTWIN_BUILD_DIR"]
SOURCE = os.environ["DTWIN_SOURCE_DIR"]
SIMBODY_RELEASE = os.environ.get("DTWIN_SIMBODY_RELEASE", "")
sys.path.insert(0, os.path.join(SOURCE, "tests", "python"))
from dtwin_testing import docs_example  # noqa: E402


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install_testing import resolved, run  # noqa: E402,F401


class Wheel(unittest.TestCase):
    def test_the_wheel_installs_offline_and_runs_the_example(self):
        for module, package in (("build", "python3-build"), ("setuptools", "python3-setuptools"), ("wheel", "python3-wheel"),
                                ("ensurepip", "python3-venv")):
            self.assertIsNotNone(importlib.util.find_spec(module),
                                 f"{module} is missing: bash scripts/setup.sh installs Debian's {package}")
        with tempfile.TemporaryDirectory(prefix="dtwin-wheel-test-") as tmp:
            dist = os.path.join(tmp, "dist")
            run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", dist, SOURCE],
                env=dict(os.environ, DTWIN_BUILD_DIR=BUILD))
            wheels = os.listdir(dist)
            self.assertEqual(len(wheels), 1, wheels)
            tag = "cp%d%d" % sys.version_info[:2]
            self.assertRegex(wheels[0], r"^dtwin-\d+\.\d+\.\d+-%s-%s-linux_\w+\.whl$" % (tag, tag))
            names = set(zipfile.ZipFile(os.path.join(dist, wheels[0])).namelist())
            for name in ("dtwin/__init__.py", "dtwin/__init__.pyi", "dtwin/py.typed", "dtwin/data/studies/demo.toml",
                         "dtwin/licenses/LICENSE", "dtwin/licenses/mdflib/LICENSE"):
                self.assertIn(name, names)
            self.assertEqual(len([n for n in names if re.fullmatch(r"dtwin/dtwin\.cpython-.*\.so", n)]), 1, names)
            if SIMBODY_RELEASE:
                for lib in ("libSimTKcommon.so.3.7", "libSimTKmath.so.3.7", "libSimTKsimbody.so.3.7"):
                    self.assertIn("dtwin/lib/" + lib, names)
                self.assertIn("dtwin/licenses/simbody/copyright", names)

            # A fresh environment (Debian's numpy and matplotlib seen through its system site), the
            # wheel installed with no index and no download.
            env_dir = os.path.join(tmp, "env")
            run([sys.executable, "-m", "venv", "--system-site-packages", env_dir])
            python = os.path.join(env_dir, "bin", "python")
            run([python, "-m", "pip", "install", "--no-index", "--no-build-isolation", os.path.join(dist, wheels[0])])
            clean = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LD_LIBRARY_PATH")}
            where = run([python, "-c", "import dtwin, sys; print(dtwin.__file__); print(dtwin.SimulationError.__module__)"],
                        cwd=tmp, env=clean).split()
            self.assertTrue(where[0].startswith(os.path.join(env_dir, "lib")), where)
            self.assertEqual(where[1], "dtwin")
            if SIMBODY_RELEASE:
                self.assertEqual(resolved(where[0], "libSimTKsimbody.so.3.7", clean),
                                 os.path.join(os.path.realpath(os.path.dirname(where[0])), "lib", "libSimTKsimbody.so.3.7"))

            # docs/python.md's example, as written, in a folder where data/ is the repository's.
            work = os.path.join(tmp, "work")
            os.makedirs(work)
            os.symlink(os.path.join(SOURCE, "data"), os.path.join(work, "data"))
            with open(os.path.join(work, "example.py"), "w") as f:
                f.write(docs_example())
            r = subprocess.run([python, "example.py"], cwd=work, capture_output=True, text=True,
                               env=dict(clean, MPLBACKEND="Agg"))
            self.assertEqual(r.returncode, 0, r.stdout[-3000:] + r.stderr[-3000:])
            self.assertIn("wrote measured_vs_predicted.png", r.stdout)
            self.assertIn("damper_asymmetry", r.stdout)  # the effect the demonstration drive hides
            with open(os.path.join(work, "measured_vs_predicted.png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
