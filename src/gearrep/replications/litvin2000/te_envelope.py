"""Meshing-cycle TE of the worm-ground pinion (seed 002, sec. 5.5) from one tooth pair's sampled
TE: the neighbouring pairs and their upper envelope come from :mod:`gearrep.meshing`
(``pair_te_curves``, ``upper_envelope``); this module only adds the evaluation angles that
matter here (the face-edge hand-overs and the crossings of neighbouring curves)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ... import meshing

__all__ = ["te_envelope"]


def te_envelope(phi, te, z, per, face_width, drive, n_fine=400):
    """Meshing-cycle TE from tooth pair 0's TE(phi1) and contact z(phi1) on a grid (general form:
    curved TE functions hand over where neighbouring curves cross, or at the face edge).

    Pair k: TE_0(phi1 - k per) while |z_0(phi1 - k per)| <= B/2; the pair in contact is the max
    (drive > 0) or min of the candidates (k = -3..3). TE_0 and z_0 are cubic splines through the
    finite grid values; the envelope is evaluated on ``n_fine`` + 1 points over one cycle
    [0, per] plus the exact face crossings (brentq, +-1e-10 rad either side) and the curve
    crossings TE_0(t) = TE_0(t - per) (brentq). Returns (TE_max = peak-to-peak of the envelope,
    DataFrame phi1_rad, te_arcsec, tooth (-99 where no pair is in contact), number of such gaps)."""
    from scipy.interpolate import CubicSpline  # here: scipy costs 0.5 s per process
    from scipy.optimize import brentq

    ok = np.isfinite(te) & np.isfinite(z)
    fte, fz = CubicSpline(phi[ok], te[ok]), CubicSpline(phi[ok], z[ok])
    lo_d, hi_d = phi[ok].min(), phi[ok].max()
    ks = range(-3, 4)

    x = np.linspace(0.0, per, n_fine + 1)
    extra = []
    # face crossings of each pair (z monotone along the helix)
    zz = fz(np.linspace(lo_d, hi_d, 4001))
    xs = np.linspace(lo_d, hi_d, 4001)
    for edge in (-0.5 * face_width, 0.5 * face_width):
        s = np.sign(zz - edge)
        for i in np.nonzero(s[:-1] * s[1:] < 0)[0]:
            r = brentq(lambda t: fz(t) - edge, xs[i], xs[i + 1], xtol=1e-14)
            for k in ks:
                y = r + k * per
                if 0.0 <= y <= per:
                    extra += [y - 1e-10, y + 1e-10]
    # crossings of neighbouring curves
    for k in ks:
        d = lambda t: fte(t) - fte(t - per)  # noqa: E731
        g = np.linspace(lo_d + per, hi_d, 4001)
        dv = d(g)
        for i in np.nonzero(np.sign(dv[:-1]) * np.sign(dv[1:]) < 0)[0]:
            r = brentq(d, g[i], g[i + 1], xtol=1e-14)
            y = r - k * per
            if 0.0 <= y <= per:
                extra.append(y)
    x = np.unique(np.concatenate([x, np.array(extra, float)]))
    # the pair in contact: the upper envelope of the pairs' TE (of -TE for the opposite drive)
    sign = 1.0 if drive > 0 else -1.0
    curves = meshing.pair_te_curves(
        phi[ok],
        sign * te[ok],
        per,
        x,
        pairs=ks,
        interpolation="cubic",
        tol=0.0,
        engaged=lambda q: np.abs(fz(q)) <= 0.5 * face_width + 1e-12,
    )
    env, lead = meshing.upper_envelope(curves)
    anyc = np.isfinite(env)
    val = sign * env
    tooth = np.where(anyc, np.array(list(ks))[lead], -99)
    df = pd.DataFrame(dict(phi1_rad=x, te_arcsec=val, tooth=tooth))
    gaps = int((~anyc).sum())
    return (float(np.nanmax(val) - np.nanmin(val)) if anyc.any() else np.nan), df, gaps
