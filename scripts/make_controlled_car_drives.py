#!/usr/bin/env python3
"""Makes the drives of a car with a suspension controller (docs/measurements.md, "A car with a
controller"): data/drives/controlled_car_a.csv and controlled_car_b.csv (and controlled_car_c.csv,
a long drive at 110 Hz for scripts/bench_jobs.sh), logger files as such a
car's own system would write them, made by the twin itself with a car that differs from the
sedan in its structure, not only in its values.

  python3 scripts/make_controlled_car_drives.py [TWIN] [OUT_DIR]
  python3 scripts/make_controlled_car_drives.py --long [TWIN] [OUT_DIR]   # only controlled_car_long.csv

--long writes a 12-minute drive of the same car at 110 Hz instead (79 201 rows, 3 MB: made when
needed, never committed), the drive of scripts/bench_jobs.sh's long_drive row, its truth integrated
at accuracy 1e-6 (LONG_ACCURACY).

The car (HIDDEN below: what the walkthrough's diagnosis must find):
  - its road signal is the car's own estimate of the road from its wheel sensors: the motion of
    the wheel centre itself, not the road under a tire (the twin's tire option `hub`);
  - a skyhook controller on every corner (the `skyhook` effect);
  - a sprung mass far above the sedan's range (2300 kg against 1100 to 1900: an SUV on the
    sedan's priors). The owner knows it (a weighbridge) and the study enters it: with the road
    signal at the hub and one body accelerometer, the data hold only the ratios of the strut's
    forces to the mass, never the mass itself (docs/measurements.md).
The drives are on different ISO 8608 roads (the same on both tracks: one road signal) and speed
profiles, each with a standstill and a turn to mask.

Logger columns: Time [s, 100 Hz (c: 110 Hz), jittered by +-1.5 ms, clock from 1200 s], Speed [km/h, 0.1
km/h steps], YawRate [deg/s, noise 0.2], RoadVel [m/s: the vertical velocity of the road signal
under the front wheels], AccZ [g with its 1 g offset, noise 0.03 m/s^2]. Seeds are fixed: the
files are reproducible.
"""
import math
import os
import random
import re
import subprocess
import sys
import tempfile

from drive_tools import cubic_reader, knot_speed

# The car (the walkthrough must not read these; docs/measurements.md states them after the walk).
HIDDEN_VALUES = {
    "chassis.mass_kg": 2300.0,             # the sedan study's range: 1100 to 1900 (known: the study enters it)
    "chassis.pitch_inertia_kgm2": 2900.0,  # inside its range (1500 to 3200)
    "chassis.roll_inertia_kgm2": 650.0,    # not calibrated: one road signal for both tracks leaves roll unexcited
    "chassis.yaw_inertia_kgm2": 3300.0,    # (yaw is no degree of freedom; it keeps the inertias a rigid body's)
    "suspension.stiffness": 42000.0,       # inside (10e3 to 80e3)
    "suspension.damping": 1800.0,          # inside (500 to 8000)
}
HIDDEN_SKYHOOK = 2500.0                    # N s/m per corner
TIRE = "hub"                               # the road signal is the hub's own motion
# --passive: a car whose structure is the twin's (a tire under the road, no controller) and whose
# calibrated values lie inside the sedan's ranges: the walkthrough's null case (passive_car_a.csv, _b.csv).
PASSIVE = "--passive" in sys.argv
if PASSIVE:
    HIDDEN_VALUES = {
        "chassis.mass_kg": 2300.0,             # the same heavy body (known, as above)
        "chassis.pitch_inertia_kgm2": 2500.0,
        "chassis.roll_inertia_kgm2": 650.0,
        "chassis.yaw_inertia_kgm2": 3000.0,
        "suspension.stiffness": 35000.0,
        "suspension.damping": 2200.0,
        "tire.stiffness": 210000.0,
        "tire.damping": 2800.0,
    }
    HIDDEN_SKYHOOK = 0.0
    TIRE = "pac2002"
SEAT = [0.4, -0.35, 0.25]                  # the accelerometer, where the mapping says it is
# --corner: a car whose road signal is one corner's (the front-left wheel's motion; the other
# wheels meet no signal: the twin's road.fl_only = 1), whose accelerometer sits over the
# front-left wheel where nobody wrote it down (the study puts it near the CG), with a skyhook;
# --feedforward: the same car with a feed-forward controller (road_feedforward) instead of the
# skyhook (corner_car_*.csv, feedforward_car_*.csv; docs/measurements.md, "A sensor nobody placed").
CORNER = "--corner" in sys.argv
FEEDFORWARD = "--feedforward" in sys.argv
HIDDEN_FEEDFORWARD = -1800.0               # N s/m: a force against the road's push (tau at its default 0.02 s)
HIDDEN_FORMS = {}
if CORNER or FEEDFORWARD:
    HIDDEN_VALUES = {
        "chassis.mass_kg": 2300.0,             # weighed (the study enters it)
        "chassis.pitch_inertia_kgm2": 2700.0,
        "chassis.roll_inertia_kgm2": 650.0,
        "chassis.yaw_inertia_kgm2": 3200.0,
        "suspension.stiffness": 38000.0,
        "suspension.damping": 1700.0,
    }
    HIDDEN_SKYHOOK = 0.0 if FEEDFORWARD else 2200.0
    HIDDEN_FORMS = {"road.fl_only": 1.0}   # the signal is the front-left wheel's alone
    TIRE = "hub"
    # Over the front-left wheel: the sedan's CG-to-front-axle distance and half its track.
    SEAT = [1.515, 0.775, 0.25]
ROLL_IN_TURN = 0.08                        # vertical acceleration at the sensor per m/s^2 of lateral acceleration
ACCURACY = "1e-8"
LONG = "--long" in sys.argv
ARGS = [a for a in sys.argv[1:] if a not in ("--passive", "--corner", "--feedforward", "--long")]
TWIN = ARGS[0] if len(ARGS) > 0 else "./build/cli/twin"
OUT = ARGS[1] if len(ARGS) > 1 else "data/drives"
PREFIX = "passive_car" if PASSIVE else "feedforward_car" if FEEDFORWARD else "corner_car" if CORNER else "controlled_car"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

DRIVES = {
    # name: (duration, speed knots (t, v m/s), road class, seed, turns [(t0, t1, yaw rate deg/s)])
    "a": (38.0, [(0, 0), (2, 0), (8, 16), (18, 16), (22, 9), (29, 21), (39, 21)], "C", 20261201,
          [(19.0, 23.0, 12.0)]),
    "b": (52.0, [(0, 0), (2, 0), (9, 13), (22, 13), (30, 24), (53, 24)], "C", 20261202,
          [(14.0, 19.0, -13.0)]),
    # A long drive at the real car's 110 Hz: the two-minute window of scripts/bench_jobs.sh's long_window row.
    "c": (128.0, [(0, 0), (2, 0), (10, 18), (40, 18), (48, 11), (70, 11), (80, 23), (129, 23)], "C", 20261203,
          [(58.0, 63.0, 10.0)]),
}
RATE_HZ = {"a": 100.0, "b": 100.0, "c": 110.0, "long": 110.0}  # the logger's clock
# The long drive's truth at 1e-6: its integration error stays far
# below the noise, at about a fifth of the steps 1e-8 takes.
LONG_ACCURACY = "1e-6"
if LONG:
    # Twelve minutes at 110 Hz: three standstills, six turns, speeds from 11 to 25 m/s.
    DRIVES = {
        "long": (721.0, [(0, 0), (2, 0), (10, 18), (60, 18), (68, 11), (100, 11), (110, 23), (180, 23), (190, 0), (200, 0),
                         (210, 15), (280, 15), (290, 25), (380, 25), (390, 12), (450, 12), (460, 0), (470, 0), (480, 20),
                         (560, 20), (570, 14), (640, 14), (650, 22), (722, 22)], "C", 20261204,
                 [(58.0, 63.0, 10.0), (150.0, 155.0, -12.0), (300.0, 306.0, 11.0), (420.0, 425.0, -10.0),
                  (530.0, 535.0, 12.0), (600.0, 606.0, -9.0)]),
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
    demo = demo.replace('tire = ["pac2002", "fiala"]', f'tire = ["{TIRE}"]').replace(
        'suspension = ["macpherson", "solid_axle"]', 'suspension = ["macpherson"]')
    demo = demo[: demo.index("[sizes]")]
    # At the generating accuracy the hub's stiff link takes about 20 000 steps per second of drive.
    demo = demo.replace("[simulation]\n", "[simulation]\nmax_internal_steps = 20000000\n" + ("max_wall_s = 100000\n" if LONG else ""))
    # The demo's calibrated values are set from the command line (--set); its tire values do not
    # apply to the hub input: drop every [[calibrated]] table.
    demo = re.sub(r"\[\[calibrated\]\]\n(?:[^\[\n][^\n]*\n|\n)*", "", demo)
    for name, (duration, knots, road_class, seed, turns) in DRIVES.items():
        with open(os.path.join(work, f"speed_{name}.csv"), "w") as f:
            f.write("time_s,speed_mps\n")
            for k in range(int(duration * 10) + 11):
                f.write(f"{0.1 * k:.1f},{knot_speed(knots, 0.1 * k):.6f}\n")
        demo += f"""
[scenarios.truth_{name}]
duration_s = {duration}
speed = {{ csv = "speed_{name}.csv" }}
road = {{ type = "iso8608", class = "{road_class}", band_cycles_per_m = [0.05, 1.0], smooth_until_s = 2.0, tracks = "identical" }}
"""
    demo += f"""
[sensors.seat]
position_m = [{SEAT[0]}, {SEAT[1]}, {SEAT[2]}]
quantity = "acceleration_z"
""" + ("" if HIDDEN_SKYHOOK == 0.0 else f"""
[effects.skyhook]
damping = {HIDDEN_SKYHOOK}
""") + ("" if not FEEDFORWARD else f"""
[effects.road_feedforward]
gain = {HIDDEN_FEEDFORWARD}
""") + """
[fixed]
""" + "".join(f'"{k}" = {v}\n' for k, v in HIDDEN_VALUES.items() if not k.startswith(("suspension.", "tire."))) + """
[sizes]
lab_repetitions = 1
"""
    path = os.path.join(work, "study.toml")
    open(path, "w").write(demo)
    return path


def main():
    work = tempfile.mkdtemp(prefix=f"dtwin_{PREFIX}_")
    study = generating_study(work)
    sets = [f"--set={k}={v}" for k, v in HIDDEN_VALUES.items() if k.startswith(("suspension.", "tire."))]
    sets += [f"--set={k}={v}" for k, v in HIDDEN_FORMS.items()]
    os.makedirs(OUT, exist_ok=True)
    g = 9.80665
    for name, (duration, knots, road_class, seed, turns) in DRIVES.items():
        if (PASSIVE or CORNER or FEEDFORWARD) and name == "c":
            continue  # the null case and the variants need the two walkthrough drives only
        rng = random.Random(seed)
        trace = os.path.join(work, f"truth_{name}.csv")
        subprocess.run([TWIN, "simulate", "--study", study, "--assembly", "M1", "--scenario", f"truth_{name}", "--seed", str(seed),
                        "--out", trace, "--quiet", "--channels", "speed_mps,seat_mps2,road_fl_m",
                        "--accuracy", LONG_ACCURACY if LONG else ACCURACY] + sets, check=True)
        rows = [line.strip().split(",") for line in open(trace)]
        head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
        col = {n: [r[i] for r in data] for i, n in enumerate(head)}
        # The road signal's vertical velocity: the central difference of the 1 kHz road height.
        h = col["road_fl_m"]
        col["road_vel"] = [(h[min(i + 1, len(h) - 1)] - h[max(i - 1, 0)]) / (0.001 * (min(i + 1, len(h) - 1) - max(i - 1, 0)))
                           for i in range(len(h))]
        readers = {n: cubic_reader(col[n]) for n in col}

        def at(n, t):  # four-point cubic through the 1 kHz rows
            return readers[n](t)

        path = os.path.join(OUT, f"{PREFIX}_{name}.csv")
        rate = RATE_HZ[name]
        n = int(round((duration - 1.0) * rate))
        with open(path, "w") as f:
            f.write("Time,Speed,YawRate,RoadVel,AccZ\n")
            for k in range(n + 1):
                t = k / rate + (rng.uniform(-0.0015, 0.0015) if 0 < k < n else 0.0)
                v = at("speed_mps", t)
                r = yaw_rate(turns, t)
                lateral = v * math.radians(r)  # m/s^2
                acc = at("seat_mps2", t) + ROLL_IN_TURN * lateral + rng.gauss(0.0, 0.03)
                cells = [f"{1200.0 + t:.4f}", f"{round(v * 3.6, 1):.1f}", f"{r + rng.gauss(0.0, 0.2):.2f}",
                         f"{at('road_vel', t):.5f}", f"{1.0 + acc / g:.6f}"]
                f.write(",".join(cells) + "\n")
        print(f"wrote {path} ({n + 1} rows; scratch files in {work})")


if __name__ == "__main__":
    main()
