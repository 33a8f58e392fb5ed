"""What the install tests share: running a command, and where the loader finds a library."""
import os
import re
import subprocess


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}")
    return r.stdout


def resolved(elf, library, env):
    """Where the loader finds `library` for `elf` (ldd), its links resolved."""
    m = re.search(r"(?m)^\s*%s => (\S+)" % re.escape(library), run(["ldd", elf], env=env))
    assert m, f"ldd {elf}: {library} not found"
    return os.path.realpath(m.group(1))
