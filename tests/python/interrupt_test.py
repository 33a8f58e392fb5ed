"""Ctrl-C stops a long call: a script that calibrates or diagnoses, sent SIGINT once the call runs,
gets KeyboardInterrupt out of the call within 2 s (of the signal), and the output folder holds no
partial file: no temporary file of an atomic write, every JSON file whole. A second call with the
same arguments resumes in that folder."""
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
import unittest

import dtwin
from dtwin_testing import SOURCE_DIR, scratch

CHILD = textwrap.dedent("""
    import signal, sys, time
    import dtwin
    signal.signal(signal.SIGINT, signal.default_int_handler)  # even if the parent's shell ignores SIGINT
    kind, study_file, data, out = sys.argv[1:5]
    study = dtwin.Study(study_file)
    first = []
    def progress(stage, done, total):
        if not first:
            first.append(stage)
            print("progress", flush=True)
    callback = progress if kind.endswith("+progress") else None
    print("calling", flush=True)
    try:
        if kind.startswith("calibrate"):
            study.calibrate(data + "@drive", assembly="M1", out=out, quiet=True, progress=callback, force=True)
        else:
            study.diagnose(data, assembly="M1", out=out, quiet=True, progress=callback, lhs_points=20, iterations=600,
                           burn_in=200, starts=1, force=True)
    except KeyboardInterrupt:
        print("interrupted", flush=True)
        sys.exit(3)
    print("finished", flush=True)
""")

LIMIT_S = 2.0


class Interrupt(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = scratch()
        root = cls.tmp.name
        drive = os.path.join(root, "drive")
        dtwin.import_log(os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go.csv"),
                         map=os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go_map.toml"), out=drive, quiet=True)
        cls.study_file = os.path.join(drive, "study.toml")
        cls.data = os.path.join(drive, "measurements.csv")
        cls.script = os.path.join(root, "child.py")
        with open(cls.script, "w") as f:
            f.write(CHILD)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def interrupt(self, kind, wait_for, delay_s, out):
        """Starts the child, sends SIGINT `delay_s` after it printed `wait_for`; returns the seconds
        from the signal to the child's exit."""
        child = subprocess.Popen([sys.executable, self.script, kind, self.study_file, self.data, out],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            seen = []
            while wait_for not in seen:
                line = child.stdout.readline()
                self.assertTrue(line, f"the child ended before '{wait_for}': {seen} {child.stderr.read()[-2000:]}")
                seen.append(line.strip())
            time.sleep(delay_s)
            self.assertIsNone(child.poll(), "the call ended before the signal: make it longer")
            sent = time.monotonic()
            child.send_signal(signal.SIGINT)
            rest, err = child.communicate(timeout=120)
            elapsed = time.monotonic() - sent
        finally:
            if child.poll() is None:
                child.kill()
                child.wait()
        self.assertIn("interrupted", rest.split(), f"{rest}\n{err[-3000:]}")
        self.assertEqual(child.returncode, 3, err[-3000:])
        return elapsed

    def assertNoPartialFile(self, out):
        self.assertTrue(os.path.isdir(out), "the call wrote nothing before the signal: send it later")
        files = 0
        for folder, _, names in os.walk(out):
            for name in names:
                path = os.path.join(folder, name)
                files += 1
                self.assertNotIn(".tmp.", name, f"a temporary file of an atomic write was left: {path}")
                if name.endswith(".json"):
                    with open(path) as f:
                        json.load(f)  # whole
                elif os.path.getsize(path) > 0 and name.endswith((".csv", ".journal", ".txt")):
                    with open(path, "rb") as f:
                        f.seek(-1, os.SEEK_END)
                        self.assertEqual(f.read(1), b"\n", f"{path} ends inside a line")
        self.assertGreater(files, 0)

    def test_calibrate_with_a_progress_callback(self):
        with scratch() as tmp:
            out = os.path.join(tmp, "calib")
            elapsed = self.interrupt("calibrate+progress", "progress", 1.5, out)
            self.assertLess(elapsed, LIMIT_S)
            self.assertNoPartialFile(out)

    def test_quiet_calibrate_then_resume(self):
        with scratch() as tmp:
            out = os.path.join(tmp, "calib")
            elapsed = self.interrupt("calibrate", "calling", 3.0, out)
            self.assertLess(elapsed, LIMIT_S)
            self.assertNoPartialFile(out)
            # The stopped call's folder is a resumable one: a second stop later, still whole.
            elapsed = self.interrupt("calibrate", "calling", 2.0, out)
            self.assertLess(elapsed, LIMIT_S)
            self.assertNoPartialFile(out)

    def test_quiet_diagnose(self):
        with scratch() as tmp:
            out = os.path.join(tmp, "diagnosis")
            elapsed = self.interrupt("diagnose", "calling", 4.0, out)
            self.assertLess(elapsed, LIMIT_S)
            self.assertNoPartialFile(out)


if __name__ == "__main__":
    unittest.main()
