"""What the Python module's tests share: the source tree, the twin program and a scratch folder.

CTest runs each test script with Debian's /usr/bin/python3 and sets PYTHONPATH (the built module),
DTWIN_SOURCE_DIR and DTWIN_TWIN_EXE (tests/CMakeLists.txt)."""
import os
import re
import subprocess
import tempfile

SOURCE_DIR = os.environ.get("DTWIN_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
TWIN = os.environ.get("DTWIN_TWIN_EXE", os.path.join(SOURCE_DIR, "build", "cli", "twin"))
DEMO_STUDY = os.path.join(SOURCE_DIR, "data", "studies", "demo.toml")


def twin(*args):
    """Runs the twin program; returns (exit code, stdout, stderr)."""
    r = subprocess.run([TWIN, *args], capture_output=True, text=True, cwd=SOURCE_DIR)
    return r.returncode, r.stdout, r.stderr


def cli_error(stderr):
    """The one line after 'twin: error: ' of a failed command."""
    lines = [l for l in stderr.splitlines() if l.startswith("twin: error: ")]
    assert len(lines) == 1, stderr
    return lines[0][len("twin: error: "):]


def scratch():
    """A new temporary folder, removed at exit."""
    return tempfile.TemporaryDirectory(prefix="dtwin-py-test-")


def docs_example():
    """The python block of docs/python.md's example section, as written."""
    with open(os.path.join(SOURCE_DIR, "docs", "python.md")) as f:
        text = f.read()
    section = text[text.index("## Example"):]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert blocks, "no python block in docs/python.md's example"
    return blocks[0]
