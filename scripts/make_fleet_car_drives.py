#!/usr/bin/env python3
"""Makes the drives of a production car that carries only accelerometers (docs/diagnosis.md, "A
fleet car's worn damper, from its accelerometers"): data/drives/fleet_car_*.csv, logger files as
such a car's own system would write them, made by the twin itself (`twin simulate`).

  python3 scripts/make_fleet_car_drives.py [TWIN] [OUT_DIR] [DRIVE ...]

The car is the demo sedan on its PAC2002 tires and MacPherson struts. It carries an accelerometer
on each wheel carrier (the wheel centre's vertical acceleration) and three on the body (two over
the front wheels' strut towers, one at the rear in the middle); nobody knows the roads. Each
drive runs over its own ISO 8608 road (class C between 0.05 and 1 cycle/m, independent tracks,
seed fixed) at its own speed profile. Every channel passes the logger's anti-alias filter
(second-order Butterworth at ANTI_ALIAS_HZ, declared on the sensors of the generating study so the
twin applies it), is sampled at RATE_HZ on a clock jittered by +-JITTER_S, carries white noise
(WHEEL_NOISE, BODY_NOISE) and is written in g with the sensor's 1 g at rest.

The wheels' noise enters the twin as an error of its input, which no likelihood of the body's
channels accounts for: at 0.1 m/s^2 it raised the body channels' residual at the truth from 0.021
to about 0.028 m/s^2 (the noise is 0.02), a lack of fit a diagnosis then tries to explain.
FLEET_WHEEL_NOISE (m/s^2) in the environment sets another for such a study.

The drives (HIDDEN below: what the diagnosis must find):
  null          four corners alike
  damper_rr     the rear-right damper worn to 55 % of its damping
  spring_fl     the front-left spring 70 % of its rate (a sagged, soft spring)
  friction_rl   a sticky strut at the rear left (Coulomb friction 150 N)
  damper_rear   both rear dampers worn to 60 % (one axle)
  wear_1..6     one car over a year: its front-left damper wears from 100 % to 50 % of its damping

Logger columns: Time [a date and clock time, UTC, RATE_HZ, jittered], Speed [km/h, 0.1 km/h
steps], AccZ_FL, AccZ_FR, AccZ_RL, AccZ_RR [g, the wheel carriers], AccZ_B1, AccZ_B2, AccZ_B3
[g, the body]. Seeds are fixed: the files are reproducible.
"""
import math
import os
import random
import subprocess
import sys
import tempfile

from drive_tools import cubic_reader, knot_speed

RATE_HZ = 200.0
JITTER_S = 0.001
ANTI_ALIAS_HZ = 50.0
WHEEL_NOISE = float(os.environ.get("FLEET_WHEEL_NOISE", "0.02"))  # m/s^2: a good MEMS wheel sensor
BODY_NOISE = 0.02   # m/s^2
ACCURACY = "1e-8"
G = 9.80665
# The body accelerometers (chassis axes from the CG: x forward, y left, z up) [m].
BODY = {"b1": [1.2, 0.6, 0.3], "b2": [1.2, -0.6, 0.3], "b3": [-1.3, 0.0, 0.3]}
WHEELS = ["fl", "fr", "rl", "rr"]

# name: (date, duration s, speed knots (t, v m/s), road seed, hidden --set values, hidden effects)
DRIVES = {
    "null": ("2026-02-03T08:15:00", 24.0, [(0, 12), (8, 12), (14, 18), (25, 18)], 20270101, {}, []),
    "damper_rr": ("2026-02-04T08:20:00", 24.0, [(0, 14), (10, 14), (15, 20), (25, 20)], 20270102,
                  {"suspension.damping@rr": 0.55}, []),
    "spring_fl": ("2026-02-05T17:40:00", 24.0, [(0, 16), (9, 16), (14, 11), (25, 11)], 20270103,
                  {"suspension.stiffness@fl": 0.7}, []),
    "friction_rl": ("2026-02-06T07:55:00", 24.0, [(0, 10), (12, 10), (18, 15), (25, 15)], 20270104,
                    {}, ["strut_friction@rl:force_N=150"]),
    "damper_rear": ("2026-02-09T12:05:00", 24.0, [(0, 15), (10, 15), (16, 19), (25, 19)], 20270105,
                    {"suspension.damping@rear": 0.6}, []),
}
# The wear series: one car, six drives over a year, its front-left damper losing damping.
WEAR = [1.0, 0.9, 0.8, 0.7, 0.6, 0.5]
WEAR_DATES = ["2026-01-12T07:30:00", "2026-03-09T07:35:00", "2026-05-11T07:28:00",
              "2026-07-13T07:40:00", "2026-09-14T07:33:00", "2026-11-16T07:31:00"]
for i, (f, date) in enumerate(zip(WEAR, WEAR_DATES)):
    DRIVES[f"wear_{i + 1}"] = (date, 24.0, [(0, 13), (9, 13), (15, 18), (25, 18)], 20270201 + i,
                               {"suspension.damping@fl": f}, [])

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARGS = sys.argv[1:]
TWIN = ARGS[0] if len(ARGS) > 0 else "./build/cli/twin"
OUT = ARGS[1] if len(ARGS) > 1 else "data/drives"
ONLY = ARGS[2:]


def generating_study(work):
    """The demo study reduced to M1 (PAC2002, MacPherson), its calibrated values at their truths,
    one scenario per drive, and the seven accelerometers with the logger's filter."""
    demo = open(os.path.join(ROOT, "data/studies/demo.toml")).read()
    demo = demo.replace('vehicle = "../vehicle/midsize_sedan.toml"',
                        f'vehicle = "{os.path.join(ROOT, "data/vehicle/midsize_sedan.toml")}"')
    demo = demo.replace('tire = ["pac2002", "fiala"]', 'tire = ["pac2002"]').replace(
        'suspension = ["macpherson", "solid_axle"]', 'suspension = ["macpherson"]')
    demo = demo[: demo.index("[sizes]")]
    demo = demo.replace("[simulation]\n", "[simulation]\nmax_internal_steps = 20000000\n")
    for name, (_, duration, knots, seed, _, _) in DRIVES.items():
        with open(os.path.join(work, f"speed_{name}.csv"), "w") as f:
            f.write("time_s,speed_mps\n")
            for k in range(int(duration * 10) + 11):
                f.write(f"{0.1 * k:.1f},{knot_speed(knots, 0.1 * k):.6f}\n")
        demo += f"""
[scenarios.truth_{name}]
duration_s = {duration}
speed = {{ csv = "speed_{name}.csv" }}
road = {{ type = "iso8608", class = "C", band_cycles_per_m = [0.05, 1.0], smooth_until_s = 1.0, tracks = "independent" }}
"""
    for w in WHEELS:
        demo += f"""
[sensors.w{w}]
body = "wheel_{w}"
quantity = "acceleration_z"
filter = {{ order = 2, cutoff_hz = {ANTI_ALIAS_HZ} }}
"""
    for b, p in BODY.items():
        demo += f"""
[sensors.{b}]
position_m = [{p[0]}, {p[1]}, {p[2]}]
quantity = "acceleration_z"
filter = {{ order = 2, cutoff_hz = {ANTI_ALIAS_HZ} }}
"""
    demo += "\n[sizes]\nlab_repetitions = 1\n"
    path = os.path.join(work, "study.toml")
    open(path, "w").write(demo)
    return path


def clock(date, t):
    """'YYYY-MM-DDTHH:MM:SS.ffffZ' at t seconds after `date` (t < one day)."""
    day, hms = date.split("T")
    h, m, s = (int(x) for x in hms.split(":"))
    total = h * 3600 + m * 60 + s + t
    return f"{day}T{int(total // 3600):02d}:{int(total % 3600 // 60):02d}:{total % 60:07.4f}Z"


def main():
    work = tempfile.mkdtemp(prefix="dtwin_fleet_car_")
    study = generating_study(work)
    os.makedirs(OUT, exist_ok=True)
    channels = ["speed_mps"] + [f"w{w}_mps2" for w in WHEELS] + [f"{b}_mps2" for b in BODY]
    for name, (date, duration, knots, seed, sets, effects) in DRIVES.items():
        if ONLY and name not in ONLY:
            continue
        rng = random.Random(seed)
        trace = os.path.join(work, f"truth_{name}.csv")
        cmd = [TWIN, "simulate", "--study", study, "--assembly", "M1", "--scenario", f"truth_{name}",
               "--seed", str(seed), "--out", trace, "--quiet", "--channels", ",".join(channels),
               "--accuracy", ACCURACY]
        cmd += [f"--set={k}={v}" for k, v in sets.items()] + [f"--effect={e}" for e in effects]
        subprocess.run(cmd, check=True)
        rows = [line.strip().split(",") for line in open(trace)]
        head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
        col = {n: [r[i] for r in data] for i, n in enumerate(head)}
        at = {n: cubic_reader(col[n]) for n in col}
        path = os.path.join(OUT, f"fleet_car_{name}.csv")
        n = int(round((duration - 1.0) * RATE_HZ))
        with open(path, "w") as f:
            f.write("Time,Speed,AccZ_FL,AccZ_FR,AccZ_RL,AccZ_RR,AccZ_B1,AccZ_B2,AccZ_B3\n")
            for k in range(n + 1):
                t = k / RATE_HZ + (rng.uniform(-JITTER_S, JITTER_S) if 0 < k < n else 0.0)
                cells = [clock(date, t), f"{round(at['speed_mps'](t) * 3.6, 1):.1f}"]
                for w in WHEELS:
                    cells.append(f"{1.0 + (at[f'w{w}_mps2'](t) + rng.gauss(0.0, WHEEL_NOISE)) / G:.6f}")
                for b in BODY:
                    cells.append(f"{1.0 + (at[f'{b}_mps2'](t) + rng.gauss(0.0, BODY_NOISE)) / G:.6f}")
                f.write(",".join(cells) + "\n")
        print(f"wrote {path} ({n + 1} rows; scratch files in {work})")


if __name__ == "__main__":
    main()
