"""Long calls release the GIL: two Python threads simulate at the same time while the main thread
keeps running Python code, and each gets the result a lone call gets."""
import threading
import time
import unittest

import numpy as np

import dtwin
from dtwin_testing import DEMO_STUDY

SCENARIO = "field"  # a random road over the demo's field drive, at a fine accuracy: about 0.5 s a run,
ACCURACY = 1e-7    # long enough to see a held GIL stop the main thread


class Threads(unittest.TestCase):
    def test_two_threads_simulate_while_the_main_thread_runs(self):
        study = dtwin.Study(DEMO_STUDY)
        t0 = time.monotonic()
        reference = study.simulate("M1", SCENARIO, channels=["hub_force_fl_N"], accuracy=ACCURACY)
        alone = time.monotonic() - t0
        # A call that held the GIL would stop the main thread for its whole length.
        self.assertGreater(alone, 0.2, "the run is too short to tell a held GIL from a released one")

        results, spans = {}, {}

        def work(k):
            start = time.monotonic()
            results[k] = study.simulate("M1", SCENARIO, channels=["hub_force_fl_N"], accuracy=ACCURACY)
            spans[k] = (start, time.monotonic())

        threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
        beats = [time.monotonic()]
        for t in threads:
            t.start()
        while any(t.is_alive() for t in threads):
            sum(range(1000))  # Python work on the main thread
            beats.append(time.monotonic())
            time.sleep(0.002)
        for t in threads:
            t.join()
        longest_gap = max(np.diff(beats))
        self.assertLess(longest_gap, max(0.1, alone / 4), f"the main thread stood still {longest_gap:.3f} s (a run: {alone:.3f} s)")
        self.assertGreater(len(beats), 20)
        # Both ran at once: each began before the other ended.
        self.assertLess(spans[0][0], spans[1][1])
        self.assertLess(spans[1][0], spans[0][1])
        for k in range(2):
            for name, column in reference.items():
                self.assertTrue(np.array_equal(results[k][name], column), name)

    def test_a_progress_callback_that_raises_stops_the_call(self):
        # The import reports progress; the callback's exception comes back out of the call.
        import os
        import tempfile
        from dtwin_testing import SOURCE_DIR
        log = os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go.csv")
        mapping = os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go_map.toml")

        class Stop(Exception):
            pass

        def progress(stage, done, total):
            self.assertIsInstance(stage, str)
            raise Stop(stage)

        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "drive")
            with self.assertRaises(Stop):
                dtwin.import_log(log, map=mapping, out=out, quiet=True, progress=progress)
            self.assertFalse(os.path.exists(out))
            calls = []
            meta = dtwin.import_log(log, map=mapping, out=out, quiet=True, progress=lambda s, d, t: calls.append((s, d, t)))
            self.assertTrue(calls)
            self.assertEqual(calls[-1][1], calls[-1][2])
            self.assertTrue(os.path.exists(os.path.join(out, "study.toml")))
            self.assertIsInstance(meta, dict)


if __name__ == "__main__":
    unittest.main()
