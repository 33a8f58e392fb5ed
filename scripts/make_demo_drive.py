#!/usr/bin/env python3
"""Makes the demonstration drive data/drives/stop_and_go.csv (docs/measurements.md): a logger's
wide CSV as a test car would record it, made by the twin itself with a hidden effect.

  python3 scripts/make_demo_drive.py [TWIN] [OUT_DIR]

The drive: 60 s of stop-and-go (0 to 20 m/s, two stops) on an ISO 8608 class C road with
independent tracks, its wavelengths kept above 2 m (band 0.011-0.5 cycles/m: a road logged at
100 Hz under a car at 20 m/s cannot hold shorter ones, and the wheels stay on the road); M1 (PAC2002 + MacPherson) with the study's calibrated truths and the hidden
effect below; a body accelerometer at (0.9, -0.4, 0.3) m sampled at 100 Hz by a jittered clock
(+-1.5 ms), in g with its 1 g offset and noise of 0.03 m/s^2; speed in km/h (GPS, 0.1 km/h
steps); the road under the front wheels in mm (left and right); a temperature column the import
ignores; three short dropouts in the accelerometer column. The logger's clock starts at 1000 s.
"""
import math
import os
import random
import subprocess
import sys
import tempfile

from drive_tools import cubic_reader, knot_speed

HIDDEN = "damper_asymmetry:ratio=2.2"  # the answer: what `twin diagnose` should name
SEED = 20261126
# The generating run's integrator accuracy: far tighter than any fit's (3e-4 .. 1e-4), so the log
# holds the model and its hidden effect, not the generator's own integration error. At the study's
# 3e-4 that error alone moved the fitted ratio by about one interval half-width.
ACCURACY = "1e-8"
TWIN = sys.argv[1] if len(sys.argv) > 1 else "./build/cli/twin"
OUT = sys.argv[2] if len(sys.argv) > 2 else "data/drives"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def speed_profile(t):
    """Stop and go [m/s]: smooth (cosine) ramps between plateaus."""
    return knot_speed([(0, 0), (2, 0), (10, 15), (20, 15), (26, 0), (29, 0), (37, 20), (47, 20), (55, 5), (62, 5)], t)


def main():
    rng = random.Random(SEED)
    work = tempfile.mkdtemp(prefix="dtwin_drive_")
    with open(os.path.join(work, "speed.csv"), "w") as f:
        f.write("time_s,speed_mps\n")
        for k in range(0, 621):
            f.write(f"{0.1 * k:.1f},{speed_profile(0.1 * k):.6f}\n")
    demo = open(os.path.join(ROOT, "data/studies/demo.toml")).read()
    demo = demo.replace('vehicle = "../vehicle/midsize_sedan.toml"',
                        f'vehicle = "{os.path.join(ROOT, "data/vehicle/midsize_sedan.toml")}"')
    demo = demo[: demo.index("[sizes]")]
    demo += """
[scenarios.truth_drive]
duration_s = 61.0
speed = { csv = "speed.csv" }
road = { type = "iso8608", class = "C", band_cycles_per_m = [0.011, 0.5], smooth_until_s = 2.0, tracks = "independent" }

[sensors.seat]
position_m = [0.9, -0.4, 0.3]
quantity = "acceleration_z"

[sizes]
lab_repetitions = 1
"""
    study = os.path.join(work, "study.toml")
    open(study, "w").write(demo)
    trace = os.path.join(work, "truth.csv")
    subprocess.run([TWIN, "simulate", "--study", study, "--assembly", "M1", "--scenario", "truth_drive",
                    "--effect", HIDDEN, "--seed", str(SEED), "--out", trace, "--quiet",
                    "--channels", "speed_mps,seat_mps2,road_fl_m,road_fr_m", "--accuracy", ACCURACY], check=True)
    rows = [line.strip().split(",") for line in open(trace)]
    head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
    col = {name: [r[i] for r in data] for i, name in enumerate(head)}
    rate = 1000.0

    readers = {name: cubic_reader(col[name]) for name in col}

    def at(name, t):  # four-point cubic through the 1 kHz rows (error ~1e-6 of the signal here)
        return readers[name](t)

    g = 9.80665
    dropouts = {1234, 1235, 3100, 4777, 4778, 4779}
    os.makedirs(OUT, exist_ok=True)
    path = os.path.join(OUT, "stop_and_go.csv")
    with open(path, "w") as f:
        f.write("Time,GPS_Speed,Road_L,Road_R,AccZ_Seat,Cabin_Temp\n")
        for k in range(6001):
            t = 0.01 * k + (rng.uniform(-0.0015, 0.0015) if 0 < k < 6000 else 0.0)
            acc = at("seat_mps2", t) + rng.gauss(0.0, 0.03)
            speed_kmh = round(at("speed_mps", t) * 3.6, 1)
            cells = [f"{1000.0 + t:.4f}", f"{speed_kmh:.1f}", f"{1000 * at('road_fl_m', t):.3f}",
                     f"{1000 * at('road_fr_m', t):.3f}", "" if k in dropouts else f"{1.0 + acc / g:.6f}",
                     f"{21.5 + 0.01 * (k // 600):.2f}"]
            f.write(",".join(cells) + "\n")
    print(f"wrote {path} (6001 rows; hidden effect {HIDDEN}; scratch files in {work})")


if __name__ == "__main__":
    main()
