"""The ISO/TS 18571:2014 objective rating of a comparison curve C (Crumple) against a
reference T (LS-DYNA), both sampled at the same N uniform times:

    R = wZ Z + wP EP + wM EM + wS ES,  weights 0.4, 0.2, 0.2, 0.2  (clause 6.1)

- corridor Z (6.2): inner and outer half widths a0 Tnorm and b0 Tnorm (a0 = 0.05, b0 = 0.5,
  Tnorm = max |T|); a point scores 1 inside the inner corridor, 0 outside the outer one, and
  ((b0 Tnorm - |C - T|) / ((b0 - a0) Tnorm))^kZ between (kZ = 2); Z is the mean.
- phase EP (6.3): C is shifted against T by up to epsP N samples (epsP = 0.2) in either
  direction; the shift n that maximises the Pearson correlation of the overlapping parts is
  kept (the smallest |n| among equal maxima), EP = ((epsP N - |n|) / (epsP N))^kP, kP = 1, and
  0 at |n| >= epsP N.
- magnitude EM (6.4): the shifted, overlapping parts are aligned by dynamic time warping
  (squared difference, steps (1,0), (0,1), (1,1), Sakoe-Chiba band of 10 % of their length);
  eps = ||Cw - Tw||_1 / ||Tw||_1, EM = ((epsM - eps) / epsM)^kM, epsM = 0.5, kM = 1, 0 beyond.
- slope ES (6.5): derivatives of the shifted parts (central differences), smoothed by a
  9-point moving average (1, 3, 5, 7 points at the ends); eps = ||C' - T'||_1 / ||T'||_1,
  ES = ((epsS - eps) / epsS)^kS, epsS = 2, kS = 1.

Grades (clause 6.6): excellent R > 0.94, good R > 0.8, fair R > 0.58, poor otherwise.
Conventions where the standard divides by zero (docs/validation.md): a rating of two equal
curves is 1; a norm of T equal to 0 with C not 0 gives 0; a correlation of a constant
part is taken as 0 (no shift is preferred over another)."""

import math

import numpy as np

DEFAULTS = {"a0": 0.05, "b0": 0.5, "kZ": 2.0, "epsP": 0.2, "kP": 1.0, "epsM": 0.5,
            "kM": 1.0, "epsS": 2.0, "kS": 1.0, "dtw_window": 0.1,
            "wZ": 0.4, "wP": 0.2, "wM": 0.2, "wS": 0.2}
GRADES = ((0.94, "excellent"), (0.8, "good"), (0.58, "fair"), (-1.0, "poor"))


def _falloff(error, limit, exponent):
    if error <= 0.0:
        return 1.0
    if error >= limit:
        return 0.0
    return ((limit - error) / limit) ** exponent


def corridor(t_ref, c, p=DEFAULTS):
    norm = float(np.max(np.abs(t_ref)))
    diff = np.abs(c - t_ref)
    if norm == 0.0:
        return 1.0 if not np.any(diff) else 0.0
    inner, outer = p["a0"] * norm, p["b0"] * norm
    rating = np.clip((outer - diff) / (outer - inner), 0.0, 1.0) ** p["kZ"]
    rating[diff <= inner] = 1.0
    return float(np.mean(rating))


def _pearson(x, y):
    sx, sy = np.std(x), np.std(y)
    if sx == 0.0 or sy == 0.0:
        return 0.0
    return float(np.mean((x - x.mean()) * (y - y.mean())) / (sx * sy))


def _overlap(t_ref, c, n):
    """The parts of T and C that overlap when C is moved n samples later (n < 0: earlier)."""
    if n >= 0:
        return t_ref[n:], c[: len(c) - n]
    return t_ref[: len(t_ref) + n], c[-n:]


def best_shift(t_ref, c, p=DEFAULTS):
    """The shift n (samples; C moved n later) of largest correlation, |n| < epsP N."""
    limit = int(math.floor(p["epsP"] * len(t_ref)))
    best, best_rho = 0, -np.inf
    for n in sorted(range(-limit, limit + 1), key=abs):
        a, b = _overlap(t_ref, c, n)
        if len(a) < 2:
            continue
        rho = _pearson(a, b)
        if rho > best_rho + 1e-12:
            best, best_rho = n, rho
    return best


def phase(n, length, p=DEFAULTS):
    return _falloff(abs(n), p["epsP"] * length, p["kP"])


def warp(x, y, window):
    """Dynamic time warping of x against y (equal lengths) in a band |i - j| < r,
    r = ceil(window n): the warped pair (x[path i], y[path j]). Each row of the accumulated
    cost D[i, j] = c[i, j] + min(D[i-1, j], D[i-1, j-1], D[i, j-1]) is a min-plus prefix
    scan, done with numpy: D[i, j] = S[j] + min over k <= j of (A[k] - S[k-1]), S the
    running sum of row i's costs and A[k] = min(D[i-1, k], D[i-1, k-1])."""
    n = len(x)
    r = max(1, int(math.ceil(window * n)))
    big = np.inf
    acc = np.full((n, n), big) if n <= 3000 else None
    if acc is None:
        raise ValueError("warp: more than 3000 points")
    prev = np.full(n, big)
    for i in range(n):
        lo, hi = max(0, i - r + 1), min(n, i + r)
        cost = (x[i] - y[lo:hi]) ** 2
        if i == 0:
            a = np.full(hi - lo, big)
            a[0] = 0.0
        else:
            up = prev[lo:hi]
            diag = np.concatenate([[prev[lo - 1] if lo > 0 else big], prev[lo:hi - 1]])
            a = np.minimum(up, diag)
        s = np.cumsum(cost)
        s_before = np.concatenate([[0.0], s[:-1]])
        row = s + np.minimum.accumulate(a - s_before)
        prev = np.full(n, big)
        prev[lo:hi] = row
        acc[i] = prev
    return _backtrack(acc, x, y)


def _backtrack(acc, x, y):
    i = j = len(x) - 1
    path = [(i, j)]
    while i > 0 or j > 0:
        steps = []
        if i > 0 and j > 0:
            steps.append((acc[i - 1, j - 1], i - 1, j - 1))  # the diagonal wins a tie
        if i > 0:
            steps.append((acc[i - 1, j], i - 1, j))
        if j > 0:
            steps.append((acc[i, j - 1], i, j - 1))
        _, i, j = min(steps, key=lambda s: s[0])
        path.append((i, j))
    path.reverse()
    idx = np.array(path)
    return x[idx[:, 0]], y[idx[:, 1]]


def _relative_l1(c, t_ref):
    den = float(np.sum(np.abs(t_ref)))
    num = float(np.sum(np.abs(c - t_ref)))
    if num == 0.0:
        return 0.0
    return num / den if den > 0.0 else np.inf


def magnitude(t_shift, c_shift, p=DEFAULTS):
    tw, cw = warp(t_shift, c_shift, p["dtw_window"])
    return _falloff(_relative_l1(cw, tw), p["epsM"], p["kM"])


def smoothed_derivative(y, dt):
    d = np.gradient(y, dt)
    out = np.convolve(d, np.ones(9) / 9.0, mode="same")
    for k, width in enumerate((1, 3, 5, 7)):
        if len(d) >= width:
            out[k] = d[:width].mean()
            out[len(d) - 1 - k] = d[len(d) - width:].mean()
    return out


def slope(t_shift, c_shift, dt, p=DEFAULTS):
    err = _relative_l1(smoothed_derivative(c_shift, dt), smoothed_derivative(t_shift, dt))
    return _falloff(err, p["epsS"], p["kS"])


def grade(r):
    return next(name for bound, name in GRADES if r > bound)


def rate(t_ref, c, dt, p=DEFAULTS):
    """All four ratings, the total and its grade, and `lag`: how much later C runs than T
    (the shift kept by the phase rating, in time units; negative when C runs early)."""
    t_ref, c = np.asarray(t_ref, dtype=float), np.asarray(c, dtype=float)
    n = best_shift(t_ref, c, p)
    ts, cs = _overlap(t_ref, c, n)
    z, ep = corridor(t_ref, c, p), phase(n, len(t_ref), p)
    em, es = magnitude(ts, cs, p), slope(ts, cs, dt, p)
    total = p["wZ"] * z + p["wP"] * ep + p["wM"] * em + p["wS"] * es
    return {"R": total, "corridor": z, "phase": ep, "magnitude": em, "slope": es,
            "lag": -n * dt, "grade": grade(total)}
