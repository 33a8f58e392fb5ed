"""dtwin.import_log with each wheel's own motion as keywords (road_fl, road_fr, road_rl, road_rr):
the same road.csv as `twin import --road-fl ...`, and the same one-line errors, the keyword named
where the command names its flag."""
import math
import os
import unittest

import dtwin
from dtwin_testing import cli_error, scratch, twin

WHEELS = {"road_fl": "a_fl:g:1", "road_fr": "a_fr:g:1", "road_rl": "a_rl:g:1", "road_rr": "a_rr:g:1"}


def write_log(path):
    """6 s at 100 Hz, 8 m/s; each wheel's accelerometer reads 1 g plus its own sine."""
    with open(path, "w") as f:
        f.write("t,v,a_fl,a_fr,a_rl,a_rr,az\n")
        for k in range(601):
            t = 0.01 * k
            wheels = ",".join("%.9f" % (1.0 + 0.05 * math.sin(2 * math.pi * (2.0 + c) * t)) for c in range(4))
            f.write("%.2f,8,%s,0\n" % (t, wheels))


def flags(keywords):
    out = []
    for key, value in keywords.items():
        out += ["--" + key.replace("_", "-"), value]
    return out


class ImportWheels(unittest.TestCase):
    def test_the_four_wheels_as_keywords_are_the_commands_road(self):
        with scratch() as tmp:
            log = os.path.join(tmp, "log.csv")
            write_log(log)
            common = ["--time", "t:s", "--speed", "v:m/s", "--channel", "az:chassis_heave_acc_mps2:m/s^2"]
            cli_out = os.path.join(tmp, "cli")
            rc, _, err = twin("import", "--log", log, "--out", cli_out, "--quiet", *common, *flags(WHEELS))
            self.assertEqual(rc, 0, err)
            py_out = os.path.join(tmp, "py")
            meta = dtwin.import_log(log, out=py_out, time="t:s", speed="v:m/s",
                                    channel=["az:chassis_heave_acc_mps2:m/s^2"], quiet=True, **WHEELS)
            self.assertEqual(meta["mapping"]["road"]["tracks"], "four corners")
            self.assertEqual(meta["mapping"]["road"]["form"], "acceleration")
            with open(os.path.join(cli_out, "road.csv")) as a, open(os.path.join(py_out, "road.csv")) as b:
                text = a.read()
                self.assertTrue(text.startswith("time_s,fl_mps2,fr_mps2,rl_mps2,rr_mps2\n"))
                self.assertEqual(text, b.read())

    def test_three_wheels_are_refused_as_the_command_refuses_them(self):
        with scratch() as tmp:
            log = os.path.join(tmp, "log.csv")
            write_log(log)
            out = os.path.join(tmp, "drive")
            three = dict(WHEELS)
            del three["road_rr"]
            common = ["--time", "t:s", "--speed", "v:m/s", "--channel", "az:chassis_heave_acc_mps2:m/s^2"]
            rc, _, err = twin("import", "--log", log, "--out", out, *common, *flags(three))
            self.assertEqual(rc, 2, err)
            expected = cli_error(err).replace("--road-rr", "road_rr", 1)
            self.assertTrue(expected.startswith("road_rr: is required"), expected)
            with self.assertRaises(dtwin.InputError) as caught:
                dtwin.import_log(log, out=out, time="t:s", speed="v:m/s",
                                 channel=["az:chassis_heave_acc_mps2:m/s^2"], quiet=True, **three)
            self.assertEqual(str(caught.exception), expected)
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
