"""Calls mypy must reject with python/dtwin.pyi (tests/python/mypy_test.py): each line whose comment
says it is rejected holds one wrong call, and mypy reports an error on each and on no other line.
Never run."""
import pathlib

import dtwin

study = dtwin.Study(5)  # rejected: a path is a str or an os.PathLike
study.simulate(accuracy="abc")  # rejected: a float
study.simulate(window="a")  # rejected: a pair of floats
study.simulate(set=5)  # rejected: a dict or a list of str
study.simulate("M1", "lab", None)  # rejected: set is keyword-only
study.simulate(acuracy=1e-4)  # rejected: no such keyword
study.calibrate("lab.csv")  # rejected: out is required
study.calibrate("lab.csv", out="calib", threads="2")  # rejected: an int
study.calibrate("lab.csv", out="calib", progress=print, quiet="yes")  # rejected: a bool
study.diagnose(["a.csv", 3])  # rejected: a list of paths
study.compare("calib/M1", "drive.csv", draws=2.5)  # rejected: an int
dtwin.import_log("log.csv", out=pathlib.Path("drive"), window=(0, "10"))  # rejected: two floats
name: int = study.name  # rejected: the name is a str

# Right calls: no error.
study.simulate("M1", "lab", set={"tire.stiffness": 2.0e5}, effects={"bump_stop": {"stiffness": 5e6}, "damper_asymmetry": None})
study.simulate(channels=["time_s"], window=(0, 5), out=pathlib.Path("run.csv"), seed=3)
study.calibrate(pathlib.Path("lab.csv"), assembly=["M1", "M3"], out="calib", progress=lambda stage, done, total: None)
study.diagnose("drive.csv", effects="bump_stop,damper_asymmetry", holdout=("b.csv",))
