"""What the scripts that make logger files from the twin share (make_demo_drive.py,
make_unknown_car_drives.py)."""
import math


def cubic_reader(column, rate=1000.0):
    """A function t -> the four-point (Lagrange) cubic through a channel sampled at `rate` Hz from
    t = 0: error about 1e-6 of a drive's signals at 1 kHz."""
    def at(t):
        x = t * rate
        k = min(max(int(math.floor(x)) - 1, 0), len(column) - 4)
        s = x - k
        v = 0.0
        for i in range(4):
            w = 1.0
            for j in range(4):
                if j != i:
                    w *= (s - j) / (i - j)
            v += w * column[k + i]
        return v
    return at


def knot_speed(knots, t):
    """A speed profile through (t, v) knots with smooth (cosine) ramps between them [m/s]."""
    for (t0, v0), (t1, v1) in zip(knots, knots[1:]):
        if t0 <= t <= t1:
            u = (t - t0) / (t1 - t0)
            return v0 + (v1 - v0) * 0.5 * (1 - math.cos(math.pi * u))
    return knots[-1][1]
