"""Time alignment, the SAE J211 CFC filter, and the per-curve figures of the table."""

import math

import numpy as np

from .errors import CompareError

# SAE J211-1 (Rev. 2007), Appendix C: the CFC filter is a 2-pole Butterworth low pass run
# forward and then backward (4 poles, no phase shift) with its design frequency at
# 2.0775 x CFC: the double pass has the gain 1 / (1 + (f / 2.0775 CFC)^4) (before the
# bilinear warping), -0.45 dB at F_H = CFC and -2.9 dB at F_N = 1.65 CFC, inside J211's
# channel corridor (+0.5/-1 dB at F_H, +0.5/-4 dB at F_N).
CFC_DESIGN_FACTOR = 2.0775
CFC_CLASSES = (60, 180, 600, 1000)


def uniform(t, y, step):
    """`y(t)` linearly interpolated onto a uniform grid of about `step` from t[0] to t[-1]."""
    n = max(2, int(round((t[-1] - t[0]) / step)) + 1)
    grid = np.linspace(t[0], t[-1], n)
    return grid, np.interp(grid, t, y)


def native_step(t):
    """The median output interval of a curve (LS-DYNA and Crumple write at cycle times near
    the requested interval, so the intervals differ a little from sample to sample)."""
    d = np.diff(t)
    d = d[d > 0]
    return float(np.median(d)) if len(d) else 0.0


def cfc_coefficients(cfc, dt):
    """(a0, a1, a2, b1, b2) of SAE J211-1 Appendix C for class `cfc` [Hz] and sample interval
    `dt` [s]: y[i] = a0 x[i] + a1 x[i-1] + a2 x[i-2] + b1 y[i-1] + b2 y[i-2] (the bilinear
    transform of the Butterworth pole pair, prewarped: wa = tan(wd dt / 2))."""
    wd = 2.0 * math.pi * cfc * CFC_DESIGN_FACTOR
    if wd * dt / 2.0 >= math.pi / 2.0:
        raise CompareError(f"CFC {cfc:g} needs samples closer than {math.pi / wd:.3g} s; the "
                           f"curve is sampled every {dt:.3g} s (ask for a shorter *DATABASE_ "
                           "interval or a lower CFC)")
    wa = math.tan(wd * dt / 2.0)
    d = 1.0 + math.sqrt(2.0) * wa + wa * wa
    a0 = wa * wa / d
    return a0, 2.0 * a0, a0, -2.0 * (wa * wa - 1.0) / d, (-1.0 + math.sqrt(2.0) * wa - wa * wa) / d


def _pass(x, c):
    a0, a1, a2, b1, b2 = c
    y = np.empty_like(x)
    # Started at rest on the first value: a constant passes unchanged from the first sample.
    x1 = x2 = y1 = y2 = x[0]
    for i, xi in enumerate(x):
        yi = a0 * xi + a1 * x1 + a2 * x2 + b1 * y1 + b2 * y2
        y[i] = yi
        x2, x1, y2, y1 = x1, xi, y1, yi
    return y


def cfc_filter(y, dt, cfc):
    """`y` (uniform, interval `dt` in seconds) through the J211 CFC filter, forward and
    backward. J211 asks for data before and after the event so that the filter's start-up
    does not show; a simulation has none, so each end is extended by its point reflection
    (2 y[0] - y[k]): a straight line passes unchanged and a start from rest stays at rest."""
    y = np.asarray(y, dtype=float)
    if len(y) < 3:
        return y.copy()
    c = cfc_coefficients(cfc, dt)
    settle = 1.0 / (CFC_DESIGN_FACTOR * cfc)  # about one period of the design frequency
    pad = min(len(y) - 1, 10 * int(math.ceil(settle / dt)))
    head = 2.0 * y[0] - y[pad:0:-1]
    tail = 2.0 * y[-1] - y[-2:-pad - 2:-1]
    x = np.concatenate([head, y, tail])
    x = _pass(_pass(x, c)[::-1], c)[::-1]
    return x[pad:pad + len(y)]


def figures(t, y, t0, t1):
    """Peak (largest magnitude, signed) and its time, the value at t1, and the integral over
    [t0, t1] of one code's own samples (the window ends interpolated)."""
    inside = (t > t0) & (t < t1)
    tw = np.concatenate([[t0], t[inside], [t1]])
    yw = np.concatenate([[np.interp(t0, t, y)], y[inside], [np.interp(t1, t, y)]])
    k = int(np.argmax(np.abs(yw)))
    integral = float(np.sum(0.5 * (yw[1:] + yw[:-1]) * np.diff(tw)))
    return {"peak": float(yw[k]), "peak_time": float(tw[k]), "end": float(yw[-1]),
            "integral": integral, "samples": int(len(t))}


def common_grid(a, b, max_points):
    """Times shared by two curves: their overlap, at the finer of their output intervals,
    at most `max_points` points; None when they do not overlap."""
    t0, t1 = max(a[0], b[0]), min(a[-1], b[-1])
    if not t1 > t0:
        return None
    steps = [s for s in (native_step(a), native_step(b)) if s > 0]
    step = min(steps) if steps else (t1 - t0)
    n = int(min(max_points, max(2, round((t1 - t0) / step) + 1)))
    return np.linspace(t0, t1, n)
