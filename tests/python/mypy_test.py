"""mypy (Debian's package `mypy`, installed by scripts/setup.sh) checks calls against
python/dtwin.pyi, the stub beside the built module: docs/python.md's example (extracted from the
page, as docs_example_test runs it) has no error, and every wrong call of mypy_misuse.py is one."""
import os
import re
import shutil
import subprocess
import unittest

import dtwin
from dtwin_testing import docs_example, scratch

HERE = os.path.dirname(os.path.abspath(__file__))
MISUSE = os.path.join(HERE, "mypy_misuse.py")
# matplotlib (Debian's 3.6) has no type information; numpy and dtwin do.
CONFIG = """[mypy]
strict = True
[mypy-matplotlib.*]
ignore_missing_imports = True
"""


class Mypy(unittest.TestCase):
    def test_the_example_passes_and_the_misuse_fails(self):
        mypy = shutil.which("mypy")
        self.assertIsNotNone(mypy, "mypy is missing: bash scripts/setup.sh installs Debian's package mypy")
        with scratch() as tmp:
            example = os.path.join(tmp, "example.py")
            with open(example, "w") as f:
                f.write(docs_example())
            config = os.path.join(tmp, "mypy.ini")
            with open(config, "w") as f:
                f.write(CONFIG)
            env = dict(os.environ, MYPYPATH=os.path.dirname(dtwin.__file__))
            r = subprocess.run([mypy, "--config-file", config, "--cache-dir", os.path.join(tmp, "cache"), "--no-error-summary",
                                "--show-error-codes", example, MISUSE], capture_output=True, text=True, env=env, cwd=tmp)
        output = r.stdout + r.stderr
        self.assertEqual(r.returncode, 1, output)  # 1: errors found (2: mypy itself failed)
        errors = {}
        for line in output.splitlines():
            m = re.match(r"(.+?):(\d+): error: (.*)", line)
            if m:
                errors.setdefault(os.path.basename(m.group(1)), set()).add(int(m.group(2)))
        self.assertNotIn("example.py", errors, output)
        with open(MISUSE) as f:
            marked = {i for i, line in enumerate(f, start=1) if "# rejected" in line}
        self.assertGreaterEqual(len(marked), 12)
        self.assertEqual(errors.get("mypy_misuse.py", set()), marked, output)


if __name__ == "__main__":
    unittest.main()
