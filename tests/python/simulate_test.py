"""study.simulate gives the columns and rows `twin simulate --out` writes, the same values to the
last bit (the CSV holds the shortest exact form of each double, so float() reads them back exactly)."""
import csv
import os
import pathlib
import unittest

import numpy as np

import dtwin
from dtwin_testing import DEMO_STUDY, scratch, twin


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return header, {name: np.array([float(r[i]) for r in body]) for i, name in enumerate(header)}


class Simulate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.study = dtwin.Study(DEMO_STUDY)

    def assertSameAsCli(self, python_kwargs, cli_args, assembly="M1", scenario="lab"):
        with scratch() as tmp:
            out = os.path.join(tmp, "run.csv")
            rc, _, err = twin("simulate", "--study", DEMO_STUDY, "--assembly", assembly, "--scenario", scenario,
                              "--out", out, "--quiet", *cli_args)
            self.assertEqual(rc, 0, err)
            header, cli = read_csv(out)
        got = self.study.simulate(assembly, scenario, **python_kwargs)
        self.assertEqual(list(got.keys()), header)  # the same columns, in the same order
        for name in header:
            self.assertIsInstance(got[name], np.ndarray)
            self.assertEqual(got[name].dtype, np.float64)
            self.assertEqual(got[name].shape, cli[name].shape, name)
            # bit for bit: the same doubles (NaN would compare unequal, and there is none)
            self.assertTrue(np.array_equal(got[name].view(np.uint64), cli[name].view(np.uint64)), name)
        return got

    def test_the_default_run_equals_the_cli_csv(self):
        got = self.assertSameAsCli({}, [])
        self.assertIn("time_s", got)
        self.assertIn("hub_force_fl_N", got)

    def test_settings_effects_channels_and_window_equal_the_cli_csv(self):
        got = self.assertSameAsCli(
            {"set": {"tire.stiffness": 2.0e5}, "effects": {"bump_stop": {"stiffness": 5e6, "gap_m": 0.03}},
             "channels": ["hub_force_fl_N", "susp_defl_fl_m"], "window": (0.5, 1.5), "output_rate": 500},
            ["--set", "tire.stiffness=2.0e5", "--effect", "bump_stop:stiffness=5e6,gap_m=0.03",
             "--channels", "hub_force_fl_N,susp_defl_fl_m", "--window", "0.5,1.5", "--output-rate", "500"])
        self.assertEqual(list(got.keys()), ["time_s", "hub_force_fl_N", "susp_defl_fl_m"])
        self.assertGreaterEqual(got["time_s"][0], 0.5 - 1e-12)
        self.assertLessEqual(got["time_s"][-1], 1.5 + 1e-12)

    def test_out_writes_the_same_csv_as_the_cli(self):
        with scratch() as tmp:
            a, b = os.path.join(tmp, "py.csv"), os.path.join(tmp, "cli.csv")
            self.study.simulate("M1", "lab", out=pathlib.Path(a))  # a str or a path
            rc, _, err = twin("simulate", "--study", DEMO_STUDY, "--out", b, "--quiet")
            self.assertEqual(rc, 0, err)
            with open(a) as fa, open(b) as fb:
                self.assertEqual(fa.read(), fb.read())
            self.assertTrue(os.path.exists(os.path.join(tmp, "py.json")))

    def test_the_study_describes_itself(self):
        self.assertEqual(self.study.path, DEMO_STUDY)
        self.assertIn("M1", self.study.assemblies)
        self.assertIn("lab", self.study.scenarios)
        self.assertEqual(self.study.to_dict()["name"], self.study.name)


if __name__ == "__main__":
    unittest.main()
