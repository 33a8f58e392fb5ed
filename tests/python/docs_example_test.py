"""docs/python.md's example runs as written: its python block, in a new folder where data/ is the
repository's, writes the plot and names the effect the demonstration drive hides."""
import os
import subprocess
import sys
import unittest

from dtwin_testing import SOURCE_DIR, docs_example, scratch


class DocsExample(unittest.TestCase):
    def test_the_example_runs_as_written(self):
        with scratch() as tmp:
            os.symlink(os.path.join(SOURCE_DIR, "data"), os.path.join(tmp, "data"))
            script = os.path.join(tmp, "example.py")
            with open(script, "w") as f:
                f.write(docs_example())
            r = subprocess.run([sys.executable, script], cwd=tmp, capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stdout[-3000:] + r.stderr[-3000:])
            with open(os.path.join(tmp, "measured_vs_predicted.png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            self.assertIn("wrote measured_vs_predicted.png", r.stdout)
            self.assertIn("tire.stiffness", r.stdout)
            self.assertIn("damper_asymmetry", r.stdout)  # the effect the drive hides
            self.assertTrue(os.path.exists(os.path.join(tmp, "out", "py", "calib", "M1", "summary.json")))


if __name__ == "__main__":
    unittest.main()
