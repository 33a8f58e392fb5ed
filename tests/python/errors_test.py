"""Bad input raises dtwin.InputError (a ValueError) with the one line `twin` prints after
'twin: error: ' (exit code 2): the same text for a file, the keyword instead of the flag for an
argument."""
import os
import unittest

import dtwin
from dtwin_testing import DEMO_STUDY, SOURCE_DIR, cli_error, scratch, twin


class Errors(unittest.TestCase):
    def assertRaisesCliText(self, call, cli_args, flag_to_keyword=None):
        rc, _, err = twin(*cli_args)
        self.assertEqual(rc, 2, err)
        expected = cli_error(err)
        if flag_to_keyword:
            expected = expected.replace(*flag_to_keyword, 1)
        with self.assertRaises(dtwin.InputError) as caught:
            call()
        self.assertIsInstance(caught.exception, ValueError)
        self.assertEqual(str(caught.exception), expected)
        self.assertNotIn("\n", str(caught.exception))

    def test_a_bad_study_file(self):
        with scratch() as tmp:
            with open(DEMO_STUDY) as f:
                text = f.read()
            bad = os.path.join(tmp, "bad.toml")
            vehicle = os.path.join(SOURCE_DIR, "data", "vehicle", "midsize_sedan.toml")
            # An accuracy out of its range: the file, the line and the field named.
            text = text.replace('"../vehicle/midsize_sedan.toml"', '"' + vehicle + '"', 1).replace("accuracy = 3e-4", "accuracy = -3e-4", 1)
            self.assertIn("accuracy = -3e-4", text)
            with open(bad, "w") as f:
                f.write(text)
            self.assertRaisesCliText(lambda: dtwin.Study(bad), ["list", "--study", bad])

    def test_malformed_toml(self):
        with scratch() as tmp:
            bad = os.path.join(tmp, "broken.toml")
            with open(bad, "w") as f:
                f.write("name = \"x\"\n[simulation\naccuracy = 1e-3\n")
            self.assertRaisesCliText(lambda: dtwin.Study(bad), ["list", "--study", bad])

    def test_a_missing_study_file(self):
        missing = os.path.join(SOURCE_DIR, "no_such_study.toml")
        self.assertRaisesCliText(lambda: dtwin.Study(missing), ["list", "--study", missing])

    def test_an_unknown_assembly_and_a_bad_argument(self):
        study = dtwin.Study(DEMO_STUDY)
        with scratch() as tmp:
            out = os.path.join(tmp, "x.csv")
            self.assertRaisesCliText(lambda: study.simulate("M9", "lab"),
                                     ["simulate", "--study", DEMO_STUDY, "--assembly", "M9", "--out", out])
            self.assertRaisesCliText(lambda: study.simulate("M1", "lab", accuracy=-1),
                                     ["simulate", "--study", DEMO_STUDY, "--accuracy", "-1", "--out", out],
                                     ("--accuracy", "accuracy"))
            self.assertRaisesCliText(lambda: study.simulate("M1", "lab", effects=["no_such_effect"]),
                                     ["simulate", "--study", DEMO_STUDY, "--effect", "no_such_effect", "--out", out],
                                     ("--effect", "effects"))
            self.assertFalse(os.path.exists(out))

    def test_calibrate_refuses_a_missing_data_file_before_any_work(self):
        study = dtwin.Study(DEMO_STUDY)
        with scratch() as tmp:
            data = os.path.join(tmp, "none.csv")
            out = os.path.join(tmp, "calib")
            self.assertRaisesCliText(lambda: study.calibrate(data, assembly="M1", out=out, quiet=True),
                                     ["calibrate", "--study", DEMO_STUDY, "--data", data, "--assembly", "M1", "--out", out])

    def test_import_needs_a_mapping(self):
        log = os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go.csv")
        with scratch() as tmp:
            out = os.path.join(tmp, "drive")
            self.assertRaisesCliText(lambda: dtwin.import_log(log, out=out, quiet=True),
                                     ["import", "--log", log, "--out", out], ("--map", "map"))
            self.assertFalse(os.path.exists(out))

    def test_the_exception_classes(self):
        self.assertTrue(issubclass(dtwin.InputError, ValueError))
        self.assertTrue(issubclass(dtwin.StorageError, OSError))
        self.assertTrue(issubclass(dtwin.SimulationError, RuntimeError))


if __name__ == "__main__":
    unittest.main()
