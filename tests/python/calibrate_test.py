"""study.calibrate and study.compare return what `twin calibrate` and `twin compare` write
(summary.json, compare.json), the same numbers, on the imported demonstration drive; the progress
callback sees the stages."""
import json
import os
import unittest

import dtwin
from dtwin_testing import SOURCE_DIR, scratch, twin

SIZES = {"lhs_points": 20, "iterations": 600, "burn_in": 200, "starts": 1, "max_rounds": 0, "ridge_steps": 0}
# What differs between two runs of the same calibration: when and how it was called, and how long it took.
RUN_KEYS = {"program", "command", "created_utc", "stages_wall_s", "median_run_wall_s", "wall_s"}


def differences(a, b, path=""):
    """The paths where two JSON values differ, outside RUN_KEYS."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = [f"{path}/{k}: only in one" for k in set(a) ^ set(b) if k not in RUN_KEYS]
        for k in set(a) & set(b):
            if k not in RUN_KEYS:
                out += differences(a[k], b[k], f"{path}/{k}")
        return out
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: {len(a)} items against {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{path}[{i}]")]
    return [] if a == b else [f"{path}: {a!r} against {b!r}"]


class Calibrate(unittest.TestCase):
    def test_calibrate_and_compare_return_what_the_commands_write(self):
        log = os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go.csv")
        mapping = os.path.join(SOURCE_DIR, "data", "drives", "stop_and_go_map.toml")
        with scratch() as tmp:
            drive = os.path.join(tmp, "drive")
            dtwin.import_log(log, map=mapping, out=drive, quiet=True)
            study_file = os.path.join(drive, "study.toml")
            data = os.path.join(drive, "measurements.csv")
            cli_out, py_out = os.path.join(tmp, "cli"), os.path.join(tmp, "py")
            flags = []
            for k, v in SIZES.items():
                flags += ["--" + k.replace("_", "-"), str(v)]
            rc, _, err = twin("calibrate", "--study", study_file, "--data", data + "@drive", "--assembly", "M1",
                              "--out", cli_out, "--quiet", *flags)
            self.assertEqual(rc, 0, err)

            study = dtwin.Study(study_file)
            stages = []
            fits = study.calibrate(data + "@drive", assembly="M1", out=py_out, quiet=True,
                                   progress=lambda stage, done, total: stages.append((stage, done, total)), **SIZES)
            self.assertEqual(list(fits), ["M1"])
            with open(os.path.join(cli_out, "M1", "summary.json")) as f:
                cli_summary = json.load(f)
            self.assertEqual(differences(fits["M1"], cli_summary), [])
            self.assertTrue(fits["M1"]["command"].startswith("python: dtwin.Study("))
            self.assertTrue(stages)
            self.assertTrue(all(s.startswith("M1 ") for s, _, _ in stages))
            self.assertTrue(any(d == t for _, d, t in stages))

            page_dir = os.path.join(tmp, "compare")
            rc, _, err = twin("compare", "--study", study_file, "--calibration", os.path.join(cli_out, "M1"), "--data", data,
                              "--draws", "5", "--out", page_dir, "--quiet")
            self.assertEqual(rc, 0, err)
            page = study.compare(os.path.join(cli_out, "M1"), data, draws=5, quiet=True)
            with open(os.path.join(page_dir, "compare.json")) as f:
                cli_page = json.load(f)
            self.assertEqual(differences(page, cli_page), [])
            self.assertGreater(page["series"][0]["fit_percent"], 50)


if __name__ == "__main__":
    unittest.main()
