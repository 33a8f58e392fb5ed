"""Every call has a real signature (inspect.signature shows its keywords and defaults, help() its
types), and a wrong type for any keyword of any call raises TypeError naming the call, the keyword
and the expected type, before any work; a right type with a wrong value raises dtwin.InputError."""
import inspect
import os
import pathlib
import unittest

import numpy as np

import dtwin
from dtwin_testing import DEMO_STUDY, scratch

STUDY = dtwin.Study(DEMO_STUDY)

# Each call with valid values for its required arguments (never used: a type error comes first).
CALLS = {
    "Study": (dtwin.Study, {}),
    "simulate": (STUDY.simulate, {}),
    "calibrate": (STUDY.calibrate, {"data": "lab.csv", "out": "calib"}),
    "compare": (STUDY.compare, {"calibration": "calib/M1", "data": "drive.csv"}),
    "diagnose": (STUDY.diagnose, {"data": "drive.csv"}),
    "import_log": (dtwin.import_log, {"log": "log.csv", "out": "drive"}),
}


class Unconvertible:
    """No call accepts it: not a str, path, number, bool, sequence, mapping or callable."""

    def __repr__(self):
        return "<unconvertible>"


class Signatures(unittest.TestCase):
    def test_every_call_has_a_signature_with_its_defaults(self):
        sig = inspect.signature(dtwin.Study.simulate)
        self.assertEqual(list(sig.parameters)[:4], ["self", "assembly", "scenario", "set"])
        self.assertEqual(sig.parameters["assembly"].default, "M1")
        self.assertEqual(sig.parameters["accuracy"].default, None)
        self.assertEqual(sig.parameters["accuracy"].kind, inspect.Parameter.KEYWORD_ONLY)
        self.assertEqual(sig.parameters["scenario"].kind, inspect.Parameter.POSITIONAL_OR_KEYWORD)
        diagnose = inspect.signature(STUDY.diagnose)  # bound: no self
        self.assertEqual(list(diagnose.parameters)[0], "data")
        self.assertIs(diagnose.parameters["data"].default, inspect.Parameter.empty)
        self.assertEqual(diagnose.parameters["confirm_within"].default, 2.0)
        self.assertEqual(diagnose.parameters["all_intervals"].default, False)
        self.assertEqual(diagnose.parameters["candidates"].default, 6)
        calibrate = inspect.signature(dtwin.Study.calibrate)
        self.assertIs(calibrate.parameters["out"].default, inspect.Parameter.empty)  # required, keyword-only
        self.assertEqual(calibrate.parameters["out"].kind, inspect.Parameter.KEYWORD_ONLY)
        self.assertEqual(list(inspect.signature(dtwin.Study).parameters), ["path"])
        self.assertEqual(str(inspect.signature(dtwin.default_study)), "()")
        self.assertEqual(inspect.signature(dtwin.import_log).parameters["scenario"].default, "drive")
        for name, (call, _) in CALLS.items():
            self.assertTrue(inspect.signature(call).parameters, name)

    def test_docstrings_say_the_types(self):
        doc = dtwin.Study.simulate.__doc__
        self.assertIn("accuracy: float | None = None", doc)
        self.assertIn("assembly: str = 'M1'", doc)
        self.assertIn("window: tuple[float, float] | None = None", doc)
        self.assertIn("out: str | os.PathLike[str]", dtwin.Study.calibrate.__doc__)
        self.assertIn("progress: Callable[[str, int, int], object] | None = None", dtwin.import_log.__doc__)
        self.assertFalse(doc.startswith("simulate("), "the text signature belongs in __text_signature__, not the docstring")


class WrongTypes(unittest.TestCase):
    def assertTypeError(self, call, message, **kwargs):
        with self.assertRaises(TypeError) as caught:
            call(**kwargs)
        self.assertNotIsInstance(caught.exception, dtwin.InputError)
        self.assertEqual(str(caught.exception), message)

    def test_the_reported_cases(self):
        self.assertTypeError(STUDY.simulate, "simulate(): accuracy expects a float, got str 'abc'", accuracy="abc")
        self.assertTypeError(STUDY.simulate, "simulate(): window expects a pair of floats (t0, t1), got str 'a'", window="a")
        self.assertTypeError(STUDY.simulate, "simulate(): set expects a dict {name: value} or a list of 'NAME=VALUE', got int 5", set=5)

    def test_every_keyword_of_every_call(self):
        checked = 0
        for name, (call, required) in CALLS.items():
            for keyword in inspect.signature(call).parameters:
                kwargs = dict(required)
                kwargs[keyword] = Unconvertible()
                with self.subTest(call=name, keyword=keyword):
                    with self.assertRaises(TypeError) as caught:
                        call(**kwargs)
                    text = str(caught.exception)
                    self.assertTrue(text.startswith(f"{name}(): {keyword} expects "), text)
                    self.assertTrue(text.endswith(", got Unconvertible <unconvertible>"), text)
                    checked += 1
        self.assertGreater(checked, 70)

    def test_near_misses(self):
        # A bool is no number, an int no bool, a float no int, a str no list of paths' element.
        self.assertTypeError(STUDY.calibrate, "calibrate(): threads expects an int, got bool True", data="x", out="y", threads=True)
        self.assertTypeError(STUDY.calibrate, "calibrate(): quiet expects a bool, got int 1", data="x", out="y", quiet=1)
        self.assertTypeError(STUDY.calibrate, "calibrate(): lhs_points expects an int, got float 20.0", data="x", out="y", lhs_points=20.0)
        self.assertTypeError(STUDY.diagnose, "diagnose(): data expects a path or a list of paths, got list ['a.csv', 3]", data=["a.csv", 3])
        self.assertTypeError(STUDY.simulate, "simulate(): window expects a pair of floats (t0, t1), got tuple (0, 1, 2)", window=(0, 1, 2))
        self.assertTypeError(STUDY.simulate, "simulate(): set expects a dict {name: value} or a list of 'NAME=VALUE', got dict {'tire.stiffness': [1]}",
                             set={"tire.stiffness": [1]})
        self.assertTypeError(STUDY.simulate, "simulate(): effects expects a dict {name: {parameter: value}} or a list of 'NAME[:p=v,...]', got dict {'bump_stop': 5}",
                             effects={"bump_stop": 5})
        self.assertTypeError(STUDY.calibrate, "calibrate(): progress expects a callable (stage, done, total), got str 'x'", data="x", out="y", progress="x")
        self.assertTypeError(dtwin.Study, "Study(): path expects a str or a path, got int 5", path=5)
        self.assertTypeError(STUDY.calibrate, "calibrate(): out expects a str or a path, got NoneType None", data="x", out=None)

    def test_the_binding_of_arguments(self):
        with self.assertRaises(TypeError) as caught:
            STUDY.simulate(acuracy=1e-4)
        self.assertEqual(str(caught.exception), "simulate() got an unexpected keyword argument 'acuracy'")
        with self.assertRaises(TypeError) as caught:
            STUDY.calibrate("lab.csv")
        self.assertEqual(str(caught.exception), "calibrate() missing required argument 'out'")
        with self.assertRaises(TypeError) as caught:
            STUDY.simulate("M1", "lab", None)
        self.assertEqual(str(caught.exception), "simulate() takes at most 2 positional arguments (3 given)")
        with self.assertRaises(TypeError) as caught:
            STUDY.simulate("M1", assembly="M1")
        self.assertEqual(str(caught.exception), "simulate() got multiple values for argument 'assembly'")

    def test_right_types_run(self):
        # numpy numbers, a pathlib.Path, a tuple, a str for a list: accepted as their Python kin.
        plain = STUDY.simulate("M1", "lab", channels=["hub_force_fl_N"], accuracy=1e-4, seed=3, window=(0.0, 1.0))
        numpy = STUDY.simulate("M1", "lab", channels="hub_force_fl_N", accuracy=np.float64(1e-4), seed=np.int64(3),
                               window=[np.float32(0), 1])
        self.assertEqual(list(plain), ["time_s", "hub_force_fl_N"])
        for name in plain:
            self.assertTrue(np.array_equal(plain[name], numpy[name]), name)
        self.assertEqual(dtwin.Study(pathlib.Path(DEMO_STUDY)).path, STUDY.path)


class WrongValues(unittest.TestCase):
    def test_a_right_type_with_a_wrong_value_is_an_input_error(self):
        with self.assertRaises(dtwin.InputError) as caught:
            STUDY.simulate(seed=-1)
        self.assertEqual(str(caught.exception), "seed: must be an integer in [0, 18446744073709551615], got -1")
        with self.assertRaises(dtwin.InputError) as caught:
            STUDY.simulate(accuracy=-1)
        self.assertEqual(str(caught.exception), "accuracy: must lie in [1e-10, 1), got -1")
        with scratch() as tmp:
            with self.assertRaises(dtwin.InputError) as caught:
                STUDY.compare(os.path.join(tmp, "calib"), "drive.csv", draws=2**40, quiet=True)
            self.assertEqual(str(caught.exception), "draws: must be an integer in [-2147483648, 2147483647], got 1099511627776")


if __name__ == "__main__":
    unittest.main()
