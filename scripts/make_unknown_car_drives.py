#!/usr/bin/env python3
"""Makes two drives of a car nobody measured (the demonstration of docs/measurements.md,
"A car nobody measured"): data/drives/unknown_car_a.csv and unknown_car_b.csv, logger files as a
test car would record them, made by the twin itself with a vehicle that is NOT the demo vehicle.

  python3 scripts/make_unknown_car_drives.py [TWIN] [OUT_DIR]

The car: the demo sedan's file with other masses, inertias, CG (height and longitudinal
position) and tire and strut values (HIDDEN below: what the walkthrough's calibration must find),
its body accelerometer mounted elsewhere (SEAT) and a string potentiometer on the front-left
strut logged through the logger's 30 Hz anti-alias filter (first order). Two drives on different
ISO 8608 roads and speed profiles, each with a standstill and turns: the twin has no lateral
dynamics, so during a turn the body accelerometer also carries a roll-induced vertical
acceleration the model cannot have (ROLL_IN_TURN, in proportion to the lateral acceleration):
the turns are for the mapping to mask (|yaw rate| above 3 deg/s), not to fit.

Logger columns: Time [s, 100 Hz, jittered by +-1.5 ms, clock from 500 s], Speed [km/h, 0.1 km/h
steps], YawRate [deg/s, noise 0.2], Road_L and Road_R [mm, under the front wheels], AccZ [g with
its 1 g offset, noise 0.03 m/s^2], Pot_FL [mm, compression positive, noise 0.05 mm],
Oil_Temp [C, ignored]. Seeds are fixed: the files are reproducible.
"""
import math
import os
import random
import subprocess
import sys
import tempfile

from drive_tools import cubic_reader, knot_speed

# The car (the walkthrough must not read these; docs/measurements.md states them after the walk).
HIDDEN = {
    "chassis.mass_kg": 1620.0,             # demo 1400
    "chassis.pitch_inertia_kgm2": 2550.0,  # demo 2100
    "chassis.roll_inertia_kgm2": 560.0,    # demo 500
    "chassis.cg_height_m": 0.58,           # demo 0.55
    "chassis.cg_x_m": 0.06,                # demo 0 (the CG 6 cm forward of the file's)
    "tire.stiffness": 205000.0,            # demo truth 180000
    "tire.damping": 2600.0,                # demo truth 3000
    "suspension.stiffness": 34000.0,       # demo truth 30000
    "suspension.damping": 2300.0,          # demo truth 2500
}
SEAT = [1.15, -0.35, 0.25]  # the accelerometer's true position (the demo study says 0.9, -0.4, 0.3)
ROLL_IN_TURN = 0.08         # vertical acceleration at the sensor per m/s^2 of lateral acceleration
ACCURACY = "1e-8"           # the generating runs' integrator accuracy (far below any fit's)
TWIN = sys.argv[1] if len(sys.argv) > 1 else "./build/cli/twin"
OUT = sys.argv[2] if len(sys.argv) > 2 else "data/drives"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

DRIVES = {
    # name: (duration, speed knots (t, v m/s), road class, seed, turns [(t0, t1, yaw rate deg/s)])
    "a": (95.0, [(0, 0), (3, 0), (13, 17), (35, 17), (41, 0), (46, 0), (56, 22), (80, 22), (90, 8), (96, 8)], "C", 20261128,
          [(24.0, 30.0, 14.0), (66.0, 71.0, -11.0)]),
    "b": (80.0, [(0, 0), (2, 0), (10, 12), (28, 12), (33, 0), (37, 0), (47, 25), (72, 25), (81, 20)], "B", 20261129,
          [(18.0, 23.0, -16.0), (58.0, 63.0, 9.0)]),
}


def yaw_rate(turns, t):
    """deg/s: a smooth turn in and out over each turn's interval."""
    for t0, t1, r in turns:
        if t0 <= t <= t1:
            return r * math.sin(math.pi * (t - t0) / (t1 - t0)) ** 2
    return 0.0


def generating_study(work):
    demo = open(os.path.join(ROOT, "data/studies/demo.toml")).read()
    demo = demo.replace('vehicle = "../vehicle/midsize_sedan.toml"',
                        f'vehicle = "{os.path.join(ROOT, "data/vehicle/midsize_sedan.toml")}"')
    demo = demo[: demo.index("[sizes]")]
    for name, (duration, knots, road_class, seed, turns) in DRIVES.items():
        with open(os.path.join(work, f"speed_{name}.csv"), "w") as f:
            f.write("time_s,speed_mps\n")
            for k in range(int(duration * 10) + 11):
                f.write(f"{0.1 * k:.1f},{knot_speed(knots, 0.1 * k):.6f}\n")
        demo += f"""
[scenarios.truth_{name}]
duration_s = {duration}
speed = {{ csv = "speed_{name}.csv" }}
road = {{ type = "iso8608", class = "{road_class}", band_cycles_per_m = [0.011, 0.5], smooth_until_s = 2.0, tracks = "independent" }}
"""
    demo += f"""
[sensors.seat]
position_m = [{SEAT[0]}, {SEAT[1]}, {SEAT[2]}]
quantity = "acceleration_z"

[sensors.pot_fl]
body = "wheel_fl"
quantity = "travel"
filter = {{ order = 1, cutoff_hz = 30.0 }}

[fixed]
""" + "".join(f'"{k}" = {v}\n' for k, v in HIDDEN.items() if not k.startswith(("tire.", "suspension."))) + """
[sizes]
lab_repetitions = 1
"""
    path = os.path.join(work, "study.toml")
    open(path, "w").write(demo)
    return path


def main():
    work = tempfile.mkdtemp(prefix="dtwin_unknown_car_")
    study = generating_study(work)
    sets = [f"--set={k}={v}" for k, v in HIDDEN.items() if k.startswith(("tire.", "suspension."))]
    os.makedirs(OUT, exist_ok=True)
    g = 9.80665
    for name, (duration, knots, road_class, seed, turns) in DRIVES.items():
        rng = random.Random(seed)
        trace = os.path.join(work, f"truth_{name}.csv")
        subprocess.run([TWIN, "simulate", "--study", study, "--assembly", "M1", "--scenario", f"truth_{name}", "--seed", str(seed),
                        "--out", trace, "--quiet", "--channels", "speed_mps,seat_mps2,road_fl_m,road_fr_m,pot_fl_m",
                        "--accuracy", ACCURACY] + sets, check=True)
        rows = [line.strip().split(",") for line in open(trace)]
        head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
        col = {n: [r[i] for r in data] for i, n in enumerate(head)}

        readers = {n: cubic_reader(col[n]) for n in col}

        def at(n, t):  # four-point cubic through the 1 kHz rows
            return readers[n](t)

        path = os.path.join(OUT, f"unknown_car_{name}.csv")
        n = int(round((duration - 1.0) * 100))
        with open(path, "w") as f:
            f.write("Time,Speed,YawRate,Road_L,Road_R,AccZ,Pot_FL,Oil_Temp\n")
            for k in range(n + 1):
                t = 0.01 * k + (rng.uniform(-0.0015, 0.0015) if 0 < k < n else 0.0)
                v = at("speed_mps", t)
                r = yaw_rate(turns, t)
                lateral = v * math.radians(r)  # m/s^2
                acc = at("seat_mps2", t) + ROLL_IN_TURN * lateral + rng.gauss(0.0, 0.03)
                cells = [f"{500.0 + t:.4f}", f"{round(v * 3.6, 1):.1f}", f"{r + rng.gauss(0.0, 0.2):.2f}",
                         f"{1000 * at('road_fl_m', t):.3f}", f"{1000 * at('road_fr_m', t):.3f}", f"{1.0 + acc / g:.6f}",
                         f"{1000 * at('pot_fl_m', t) + rng.gauss(0.0, 0.05):.3f}", f"{88.0 + 0.02 * (k // 500):.2f}"]
                f.write(",".join(cells) + "\n")
        print(f"wrote {path} ({n + 1} rows; scratch files in {work})")


if __name__ == "__main__":
    main()
