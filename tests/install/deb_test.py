"""The Debian package (CPack's DEB generator; docs/install.md): `cpack -G DEB` of the build makes
dtwin_<version>_<arch>.deb whose Depends dpkg-shlibdeps computed, holding bin/twin, the Python
module where Debian's Python looks, the bundled Release Simbody and the docs; extracted anywhere
(`dpkg-deb -x`), its twin runs and finds the bundled Simbody by its run path.

CTest sets DTWIN_BUILD_DIR, DTWIN_SOURCE_DIR and DTWIN_SIMBODY_RELEASE (empty for Debian's binary
Simbody)."""
import os
import re
import sys
import tempfile
import unittest

BUILD = os.environ["DTWIN_BUILD_DIR"]
SIMBODY_RELEASE = os.environ.get("DTWIN_SIMBODY_RELEASE", "")


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from install_testing import resolved, run  # noqa: E402,F401


class Deb(unittest.TestCase):
    def test_the_package_depends_on_what_it_links_and_runs_extracted(self):
        with tempfile.TemporaryDirectory(prefix="dtwin-deb-test-") as tmp:
            run(["cpack", "-G", "DEB", "--config", os.path.join(BUILD, "CPackConfig.cmake"), "-B", tmp], cwd=BUILD)
            debs = [n for n in os.listdir(tmp) if n.endswith(".deb")]
            self.assertEqual(len(debs), 1, os.listdir(tmp))
            deb = os.path.join(tmp, debs[0])
            self.assertRegex(debs[0], r"^dtwin_\d+\.\d+\.\d+_\w+\.deb$")

            info = run(["dpkg-deb", "-I", deb])
            self.assertRegex(info, r"(?m)^ Package: dtwin$")
            version = re.search(r"(?m)^ Version: (\S+)$", info).group(1)
            depends = re.search(r"(?m)^ Depends: (.*)$", info).group(1)
            # Computed by dpkg-shlibdeps from the ELF files: every shared library the programs and the
            # bundled Simbody link, with the version the build saw.
            for package in ("libc6", "libstdc++6", "libnlopt", "libmuparser", "libtomlplusplus", "zlib1g", "libexpat1"):
                self.assertRegex(depends, r"(^|, )%s[\w.+-]* \(>= " % re.escape(package), depends)
            if SIMBODY_RELEASE:
                self.assertNotIn("libsimbody", depends)  # bundled
                self.assertRegex(depends, r"liblapack3|liblapack\.so\.3")  # the bundled Simbody's own
            else:
                self.assertIn("libsimbody", depends)
            self.assertIn("python3-numpy", depends)

            listing = run(["dpkg-deb", "-c", deb])
            files = set(re.findall(r"\s\./(\S+)$", listing, re.M))
            for name in ("usr/bin/twin", "usr/share/doc/dtwin/README.md", "usr/share/doc/dtwin/LICENSE",
                         "usr/share/doc/dtwin/docs/usage.md", "usr/share/doc/dtwin/licenses/mdflib/LICENSE",
                         "usr/share/dtwin/data/studies/demo.toml", "usr/lib/cmake/dtwin/dtwinConfig.cmake"):
                self.assertIn(name, files)
            self.assertTrue(any(re.fullmatch(r"usr/lib/python3/dist-packages/dtwin\.cpython-.*\.so", f) for f in files), listing)
            if SIMBODY_RELEASE:
                self.assertIn("usr/lib/dtwin/simbody/lib/libSimTKsimbody.so.3.7", files)

            # Extracted elsewhere, the packaged program runs, with the packaged Simbody.
            root = os.path.join(tmp, "root")
            run(["dpkg-deb", "-x", deb, root])
            env = {k: v for k, v in os.environ.items() if k not in ("LD_LIBRARY_PATH", "PYTHONPATH")}
            twin = os.path.join(root, "usr", "bin", "twin")
            out = run([twin, "--version"], cwd=tmp, env=env)
            self.assertTrue(out.startswith(version + " "), out)
            self.assertIn("installed under " + os.path.join(root, "usr", "share", "doc", "dtwin") + ".",
                          run([twin, "--help"], cwd=tmp, env=env))
            if SIMBODY_RELEASE:
                self.assertEqual(resolved(twin, "libSimTKsimbody.so.3.7", env),
                                 os.path.join(root, "usr", "lib", "dtwin", "simbody", "lib", "libSimTKsimbody.so.3.7"))
            site = os.path.join(root, "usr", "lib", "python3", "dist-packages")
            out = run([sys.executable, "-c", "import dtwin; print(dtwin.__file__)"], cwd=tmp,
                      env=dict(env, PYTHONPATH=site, PYTHONNOUSERSITE="1"))
            self.assertTrue(out.startswith(site), out)


if __name__ == "__main__":
    unittest.main()
