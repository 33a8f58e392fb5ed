"""`cmake --install` gives a self-contained, relocatable install (docs/install.md): a project outside
the source tree finds the package with find_package(dtwin), links every exported target and runs
one call of each library (tests/install/consumer/); the prefix moved elsewhere still runs (bin/twin,
the Python module), its run paths are relative ($ORIGIN), no installed file names the Simbody
cache, the licences of what it ships are there, and another user runs the installed program.

CTest sets DTWIN_BUILD_DIR (the build to install), DTWIN_SOURCE_DIR and DTWIN_SIMBODY_RELEASE (the
cache's Release Simbody the build links, empty for Debian's binary package)."""
import os
import re
import shutil
import stat
import subprocess
import sys
import tempfile
import unittest

BUILD = os.environ["DTWIN_BUILD_DIR"]
SOURCE = os.environ["DTWIN_SOURCE_DIR"]
SIMBODY_RELEASE = os.environ.get("DTWIN_SIMBODY_RELEASE", "")
CONSUMER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "consumer")
OTHER_USER = "dtwin-install-test"


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install_testing import resolved, run  # noqa: E402,F401


def elf_files(root):
    for d, _, names in os.walk(root):
        for n in names:
            p = os.path.join(d, n)
            if os.path.isfile(p) and not os.path.islink(p):
                with open(p, "rb") as f:
                    if f.read(4) == b"\x7fELF":
                        yield p


def run_paths(path):
    """The RUNPATH and RPATH entries of an ELF file (readelf -d)."""
    out = run(["readelf", "-d", path])
    entries = []
    for m in re.finditer(r"\((?:RUNPATH|RPATH)\)\s+Library r(?:un)?path: \[(.*)\]", out):
        entries += [e for e in m.group(1).split(":") if e]
    return entries


class Install(unittest.TestCase):
    def test_the_install_is_self_contained_and_relocatable(self):
        tmp = tempfile.mkdtemp(prefix="dtwin-install-test-")
        try:
            self.check_install(tmp)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)

    def check_install(self, tmp):
        os.chmod(tmp, 0o755)  # the other user reads the moved prefix
        prefix = os.path.join(tmp, "prefix")
        run(["cmake", "--install", BUILD, "--prefix", prefix])

        # Every package the exported link interfaces name is one the package config finds: the
        # consumer configures, builds and runs against the prefix alone.
        with open(os.path.join(prefix, "lib", "cmake", "dtwin", "dtwinTargets.cmake")) as f:
            targets = f.read()
        exported = set(re.findall(r"add_library\(dtwin::(\w+)", targets))
        self.assertTrue({"common", "distributed", "subsystems", "twin", "dtwin_mdflib", "io", "calibration",
                         "classification", "diagnosis", "study", "report"} <= exported, exported)
        with open(os.path.join(CONSUMER, "CMakeLists.txt")) as f:
            linked = set(re.findall(r"dtwin::(\w+)", f.read()))
        self.assertEqual(exported - linked, set(), "the consumer links every exported target")
        cbuild = os.path.join(tmp, "consumer-build")
        configure = ["cmake", "-S", CONSUMER, "-B", cbuild, "-DCMAKE_BUILD_TYPE=Release",
                     "-DCMAKE_PREFIX_PATH=" + prefix]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        run(configure)
        run(["cmake", "--build", cbuild, "-j2"])
        self.assertEqual(run([os.path.join(cbuild, "consumer")]).strip(), "ok")

        # The licences of what the install ships.
        doc = os.path.join(prefix, "share", "doc", "dtwin")
        licences = ["LICENSE", "licenses/mdflib/LICENSE", "licenses/uplot/LICENSE", "licenses/eigen/copyright",
                    "licenses/nlohmann-json/copyright", "licenses/cli11/copyright"]
        if SIMBODY_RELEASE:
            licences.append("licenses/simbody/copyright")
        for name in licences:
            self.assertTrue(os.path.getsize(os.path.join(doc, name)) > 100, name)

        # Moved elsewhere, the prefix still runs: bin/twin, its help names the moved docs, and the
        # Python module (by its own run path).
        moved = os.path.join(tmp, "elsewhere", "dtwin")
        os.makedirs(os.path.dirname(moved))
        os.chmod(os.path.dirname(moved), 0o755)
        shutil.move(prefix, moved)
        env = {k: v for k, v in os.environ.items() if k not in ("LD_LIBRARY_PATH", "PYTHONPATH")}
        twin = os.path.join(moved, "bin", "twin")
        version = run([twin, "--version"], cwd=tmp, env=env)
        self.assertRegex(version, r"^\d+\.\d+\.\d+ ")
        if SIMBODY_RELEASE:
            self.assertIn("Release", version)
        self.assertIn("installed under " + os.path.join(moved, "share", "doc", "dtwin") + ".", run([twin, "--help"], cwd=tmp, env=env))
        site = [os.path.join(d, "dist-packages") for d in
                (os.path.join(moved, "lib", n) for n in os.listdir(os.path.join(moved, "lib")) if n.startswith("python3"))]
        if site:
            out = run([sys.executable, "-c", "import dtwin; print(dtwin.__file__); print(dtwin.simbody)"],
                      cwd=tmp, env=dict(env, PYTHONPATH=site[0], PYTHONNOUSERSITE="1"))
            self.assertTrue(out.startswith(site[0]), out)

        # Run paths: relative to the file ($ORIGIN), never absolute; the bundled Simbody found.
        for path in elf_files(moved):
            for entry in run_paths(path):
                self.assertTrue(entry.startswith("$ORIGIN"), f"{path}: run path {entry}")
        if SIMBODY_RELEASE:
            libs = os.path.join(moved, "lib", "dtwin", "simbody", "lib")
            for name in ("libSimTKcommon.so.3.7", "libSimTKmath.so.3.7", "libSimTKsimbody.so.3.7"):
                self.assertTrue(os.path.isfile(os.path.join(libs, name)), name)
            self.assertEqual(resolved(twin, "libSimTKsimbody.so.3.7", env), os.path.join(os.path.realpath(libs), "libSimTKsimbody.so.3.7"))

            # No installed file names the cache, but for what Simbody's own build compiled into its
            # libraries: its source files' paths (its exceptions' __FILE__) and the folder where it
            # would look for its visualizer (not built, never started by the twin). The compiler may
            # store that folder's name in overlapping pieces, not as one string ("lib/si" then
            # "simbody/libexec"): after the cache comes a source path in the work folder, or a
            # piece of the visualizer's folder.
            cache = os.path.dirname(SIMBODY_RELEASE).encode()
            visualizer = "/" + os.path.basename(SIMBODY_RELEASE) + "/lib/simbody/libexec"
            work = "/" + os.path.basename(SIMBODY_RELEASE).replace("-release", "-work") + "/"
            for d, _, names in os.walk(moved):
                for n in names:
                    p = os.path.join(d, n)
                    if os.path.islink(p):
                        continue
                    with open(p, "rb") as f:
                        data = f.read()
                    if cache not in data:
                        continue
                    self.assertTrue(d == libs, f"{p} names the cache {cache.decode()}")
                    for m in re.finditer(re.escape(cache) + rb"([^\0]*)", data):
                        after = m.group(1).decode(errors="replace")
                        if after.startswith(work):
                            self.assertRegex(after, r"^/simbody-[^/]+-work/\S*?\.(h|cpp)", p)
                        else:
                            self.assertGreaterEqual(len(os.path.commonprefix([after, visualizer])), len("/simbody-"),
                                                    f"{p}: {after[:80]!r}")

        # Another user runs the installed program (as root, with useradd and runuser).
        if os.geteuid() == 0 and shutil.which("useradd") and shutil.which("runuser"):
            subprocess.run(["useradd", "--system", "--no-create-home", "--shell", "/usr/sbin/nologin", OTHER_USER],
                           capture_output=True)
            try:
                out = run(["runuser", "-u", OTHER_USER, "--", twin, "--version"], cwd="/", env=env)
                self.assertEqual(out, version)
                print(f"install_test: {OTHER_USER} ran {twin} --version")
            finally:
                subprocess.run(["userdel", OTHER_USER], capture_output=True)
        else:
            print("install_test: not root (or no useradd/runuser): the run as another user is left out")


if __name__ == "__main__":
    unittest.main()
