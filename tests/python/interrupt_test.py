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
    import signal, sys
    import dtwin
    signal.signal(signal.SIGINT, signal.default_int_handler)  # even if the parent's shell ignores SIGINT
    kind, study_file, data, out = sys.argv[1:5]
    study = dtwin.Study(study_file)
    stages = []
    def progress(stage, done, total):
        if not stages or stages[-1] != stage:
            stages.append(stage)
            print("stage", stage, flush=True)
    callback = progress if kind.endswith("+progress") else None
    sizes = dict(lhs_points=20, iterations=600, burn_in=200, starts=1)
    print("calling", flush=True)
    try:
        if kind.startswith("calibrate"):
            study.calibrate(data + "@drive", assembly="M1", out=out, quiet=True, progress=callback, max_rounds=0, **sizes)
        else:
            study.diagnose(data, assembly="M1", out=out, quiet=True, progress=callback, candidates=1, causes=1, propose=0, **sizes)
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
            while not any(wait_for in line for line in seen):
                line = child.stdout.readline()
                if not line:
                    self.fail(f"the child ended before '{wait_for}': {seen} {child.stderr.read()[-2000:]}")
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
        print(f"{kind}: out of the call {elapsed:.2f} s after SIGINT", file=sys.stderr)
        self.assertIn("interrupted", rest.split(), f"{rest}\n{err[-3000:]}")
        self.assertEqual(child.returncode, 3, err[-3000:])
        return elapsed

    def assertNoPartialFile(self, out, at_least=0):
        files = 0
        for folder, _, names in os.walk(out):
            for name in names:
                path = os.path.join(folder, name)
                files += 1
                self.assertNotIn(".tmp.", name, f"a temporary file of an atomic write was left: {path}")
                if name.endswith(".json"):
                    with open(path) as f:
                        json.load(f)  # whole
                elif os.path.getsize(path) > 0 and name.endswith(".csv"):
                    with open(path, "rb") as f:
                        f.seek(-1, os.SEEK_END)
                        self.assertEqual(f.read(1), b"\n", f"{path} ends inside a line")
        self.assertGreaterEqual(files, at_least, "the call had written less than expected before the signal")

    def test_calibrate_while_it_runs_the_optimiser(self):
        # 3 s in: the optimiser's starts, seconds between two progress reports (none here: quiet).
        with scratch() as tmp:
            out = os.path.join(tmp, "calib")
            self.assertLess(self.interrupt("calibrate", "calling", 3.0, out), LIMIT_S)
            self.assertNoPartialFile(out)

    def test_calibrate_while_it_writes_its_design_then_again_on_resuming(self):
        # In the design round the journal gains a line per run (20 runs, about 0.07 s each): the
        # stop leaves whole lines.
        with scratch() as tmp:
            out = os.path.join(tmp, "calib")
            self.assertLess(self.interrupt("calibrate+progress", "stage M1 design round 0", 0.5, out), LIMIT_S)
            self.assertNoPartialFile(out, at_least=3)  # the optimum, the box and region, the journal
            self.assertTrue(os.path.exists(os.path.join(out, "M1", "design_journal.csv")))
            # The same call resumes from the stopped one's stages (the first report is the design's).
            self.assertLess(self.interrupt("calibrate+progress", "stage M1 design", 0.3, out), LIMIT_S)
            self.assertNoPartialFile(out, at_least=3)

    def test_diagnose(self):
        with scratch() as tmp:
            out = os.path.join(tmp, "diagnosis")
            self.assertLess(self.interrupt("diagnose", "calling", 4.0, out), LIMIT_S)
            self.assertNoPartialFile(out)
            # The base calibration's design rounds: its stages written, its journal growing.
            self.assertLess(self.interrupt("diagnose+progress", "design round 1", 0.3, out), LIMIT_S)
            self.assertNoPartialFile(out, at_least=3)


if __name__ == "__main__":
    unittest.main()
