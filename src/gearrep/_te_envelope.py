"""The TE transmitted over a meshing cycle from one tooth pair's sampled TE: the neighbouring pairs'
curves, their upper envelope and the steps at hand-overs. Public names of :mod:`gearrep.meshing`
(its module docstring gives the model); this module is their home."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .units import ARCSEC

__all__ = ["pair_te_curves", "upper_envelope", "handover_jump", "handover_gap", "SampledCycle", "sampled_cycle"]


def pair_te_curves(
    phi1, te, pitch: float, at, pairs=range(-2, 3), *, interpolation: str = "linear", tol: float = 1e-12, engaged=None
) -> np.ndarray:
    """TE of neighbouring tooth pairs from one pair's TE sampled on a grid.

    Tooth pair k engages one angular pitch (``pitch`` = 2 pi / N1) after pair k - 1, so with
    identical teeth TE_k(phi1) = TE_0(phi1 - k pitch). ``phi1``, ``te``: pair 0's TE [rad] on a
    grid (NaN where that pair has no contact on the flanks); ``at``: the angles where the curves
    are wanted. Returns (len(pairs), len(at)): TE_k interpolated (``"linear"`` or ``"cubic"``
    spline) inside pair 0's engagement interval [min, max] of the finite samples (+- ``tol``),
    -inf outside it (a pair that is not engaged cannot lead). ``engaged``: optional callable
    q -> bool mask at pair-0 angles q (e.g. the contact point inside the face width) that further
    restricts where a pair is in contact. Needs >= 2 finite samples.

    Parameters
    ----------
    phi1, te : (n,) array_like
        Pair 0's grid (increasing) and TE [rad].
    pitch : float
        Angular pitch 2 pi / N1 [rad].
    at : float or (m,) array_like
        Where the curves are wanted [rad].
    pairs : iterable of int, optional
        Tooth-pair offsets k.
    interpolation : {"linear", "cubic"}, optional
        Interpolation of pair 0's TE.
    tol : float, optional
        Slack of the engagement interval [rad].
    engaged : callable, optional
        q -> bool mask restricting where a pair is in contact.

    Returns
    -------
    numpy.ndarray
        (len(pairs), m) TE [rad], -inf where a pair is not engaged.

    Raises
    ------
    ValueError
        For fewer than two finite samples, a grid that does not increase, or a bad argument.

    Examples
    --------
    >>> import numpy as np
    >>> pitch = 2 * np.pi / 23  # rad
    >>> q = np.linspace(-0.2, 0.2, 41)  # pair 0's grid [rad]; its TE a parabola, engaged for |q| < 0.15
    >>> te = np.where(np.abs(q) < 0.15, -q * q, np.nan)
    >>> from gearrep.meshing import pair_te_curves
    >>> np.round(pair_te_curves(q, te, pitch, [0.0, pitch / 2]), 6).tolist()
    [[-inf, -inf], [-inf, -inf], [-0.0, -0.01868], [-inf, -0.01868], [-inf, -inf]]
    """
    phi1, te, at = (np.asarray(x, float) for x in (phi1, te, at))
    if phi1.ndim != 1 or te.shape != phi1.shape:
        raise ValueError(
            f"phi1 and te must be 1-D arrays of the same length (pair 0's TE on a grid), got shapes "
            f"{phi1.shape} and {te.shape}"
        )
    if at.ndim > 1:
        raise ValueError(f"at must be a scalar or a 1-D array of angles [rad], got shape {at.shape}")
    ok = np.isfinite(te) & np.isfinite(phi1)
    if ok.sum() < 2:
        raise ValueError(f"pair_te_curves needs >= 2 finite TE samples, got {int(ok.sum())}")
    if not (np.isfinite(pitch) and pitch > 0):
        raise ValueError(f"pitch must be > 0 rad, got {pitch!r}")
    if interpolation not in ("linear", "cubic"):
        raise ValueError(f"interpolation must be 'linear' or 'cubic', got {interpolation!r}")
    if not (np.isfinite(tol) and tol >= 0):
        raise ValueError(f"tol must be a finite number >= 0 [rad], got {tol!r}")
    pairs = list(pairs)
    if not pairs or any(isinstance(k, bool) or not isinstance(k, (int, np.integer)) for k in pairs):
        raise ValueError(f"pairs must be one or more integers (tooth-pair offsets), got {pairs!r}")
    x, y = phi1[ok], te[ok]
    if np.any(np.diff(x) <= 0):
        raise ValueError("phi1 must increase strictly along the grid (at its finite TE samples)")
    lo, hi = x.min(), x.max()
    if interpolation == "cubic":
        from scipy.interpolate import CubicSpline

        spline = CubicSpline(x, y)

        def f(q):
            return spline(np.clip(q, lo, hi))
    else:

        def f(q):
            return np.interp(q, x, y)

    out = []
    for k in pairs:
        q = at - k * pitch
        inside = (q >= lo - tol) & (q <= hi + tol)
        if engaged is not None:
            inside &= np.asarray(engaged(np.clip(q, lo, hi)), bool)
        out.append(np.where(inside, f(q), -np.inf))
    return np.stack(out)


def upper_envelope(curves) -> tuple[np.ndarray, np.ndarray]:
    """TE actually transmitted and the leading pair: (max over the rows of ``curves`` (pairs, n)
    as given by :func:`pair_te_curves`, index of the leading row). Member 2 is driven, so it is
    pushed to the most advanced position any engaged pair demands (for the opposite drive
    direction pass ``-curves`` and negate the envelope). NaN where no pair is engaged.

    Parameters
    ----------
    curves : (pairs, n) array_like
        TE of each pair [rad], -inf where not engaged.

    Returns
    -------
    tuple of numpy.ndarray
        (envelope [rad], index of the leading row).

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.meshing import upper_envelope
    >>> env, lead = upper_envelope(np.array([[-1.0, -2.0, -np.inf], [-3.0, -1.5, -np.inf]]))
    >>> env.tolist(), lead[:2].tolist()
    ([-1.0, -1.5, nan], [0, 1])
    """
    curves = np.asarray(curves, float)
    lead = np.argmax(curves, axis=0)
    env = curves[lead, np.arange(curves.shape[1])]
    return np.where(np.isfinite(env), env, np.nan), lead


def handover_jump(curves, lead, envelope) -> float:
    """Largest TE jump [rad] where the leading pair changes between neighbouring grid angles.

    A hand-over between angles i and i + 1 is a crossing when both pairs are engaged on one side
    with (nearly) equal TE; otherwise the TE jumps (a pair leaves or enters its flank while the
    other still leads): the jump is the smallest |TE_a - TE_b| where both are engaged, or the step
    of the envelope if they never are. 0 without a hand-over.

    Parameters
    ----------
    curves : (pairs, n) array_like
        TE of each pair [rad] (:func:`pair_te_curves`).
    lead, envelope : (n,) array_like
        :func:`upper_envelope` of ``curves``.

    Returns
    -------
    float
        The largest jump [rad].

    Examples
    --------
    >>> import numpy as np
    >>> pitch = 2 * np.pi / 23  # rad
    >>> q = np.linspace(-0.2, 0.2, 41)  # pair 0's grid [rad]; its TE a parabola, engaged for |q| < 0.15
    >>> te = np.where(np.abs(q) < 0.15, -q * q, np.nan)
    >>> from gearrep.meshing import handover_jump, pair_te_curves, upper_envelope
    >>> curves = pair_te_curves(q, te, pitch, np.linspace(-pitch / 2, pitch / 2, 5))
    >>> env, lead = upper_envelope(curves)
    >>> handover_jump(curves, lead, env)  # the neighbours meet on one TE: a crossing
    0.0
    """
    curves = np.asarray(curves, float)
    jump = 0.0
    for i in np.flatnonzero(lead[1:] != lead[:-1]):
        a, b = lead[i], lead[i + 1]
        both = [
            abs(curves[a, j] - curves[b, j])
            for j in (i, i + 1)
            if np.isfinite(curves[a, j]) and np.isfinite(curves[b, j])
        ]
        jump = max(jump, min(both) if both else abs(envelope[i + 1] - envelope[i]))
    return jump


def handover_gap(curves, lead, envelope) -> float:
    """Largest TE jump [rad] of the transmitted TE at a hand-over that is not a crossing.

    Sign-aware companion of :func:`handover_jump`: where the leading pair changes from a to b
    between neighbouring grid angles i and i + 1 and both pairs are engaged at both angles, their
    (continuous) TE curves have crossed between the samples (TE_a - TE_b changes sign), so the
    transmitted TE is continuous there: gap 0, however steep the curves (e.g. near tip relief).
    Otherwise a pair entered or left its flank while the other still led: the gap is the step of
    the envelope ``|env[i + 1] - env[i]|``. 0 without a hand-over.

    Parameters
    ----------
    curves : (pairs, n) array_like
        TE of each pair [rad] (:func:`pair_te_curves`).
    lead, envelope : (n,) array_like
        :func:`upper_envelope` of ``curves``.

    Returns
    -------
    float
        The largest gap [rad].

    Examples
    --------
    >>> import numpy as np
    >>> pitch = 2 * np.pi / 23  # rad
    >>> q = np.linspace(-0.2, 0.2, 41)  # pair 0's grid [rad]; its TE a parabola, engaged for |q| < 0.15
    >>> te = np.where(np.abs(q) < 0.15, -q * q, np.nan)
    >>> from gearrep.meshing import handover_gap, pair_te_curves, upper_envelope
    >>> curves = pair_te_curves(q, te, pitch, np.linspace(-pitch / 2, pitch / 2, 5))
    >>> env, lead = upper_envelope(curves)
    >>> round(float(handover_gap(curves, lead, env)), 6)  # pair 0 is not engaged on both sides of the hand-over
    0.014001
    """
    curves = np.asarray(curves, float)
    envelope = np.asarray(envelope, float)
    gap = 0.0
    for i in np.flatnonzero(lead[1:] != lead[:-1]):
        a, b = lead[i], lead[i + 1]
        if np.all(np.isfinite(curves[[a, b]][:, [i, i + 1]])):
            continue
        gap = max(gap, abs(envelope[i + 1] - envelope[i]))
    return gap


@dataclass(frozen=True)
class SampledCycle:
    """The TE transmitted over one mesh cycle, built from one tooth pair's sampled TE
    (:func:`sampled_cycle`).

    Attributes
    ----------
    phi1 : numpy.ndarray
        The cycle's angles [rad], from -pitch/2 to +pitch/2.
    te : numpy.ndarray
        The transmitted TE [rad] (upper envelope of the pairs), NaN where no pair is engaged.
    jump : float
        The largest TE step at a hand-over [rad] (:func:`handover_jump` or :func:`handover_gap`),
        NaN when pair 0 has fewer than two finite TE samples.

    Examples
    --------
    >>> import numpy as np
    >>> from gearrep.meshing import SampledCycle
    >>> cycle = SampledCycle(np.array([-0.1, 0.0, 0.1]), np.array([-2e-5, 0.0, -2e-5]), 1e-6)  # rad
    >>> round(cycle.jump_arcsec, 4), round(cycle.te_peak_to_peak, 9), cycle.continuous(0.1)
    (0.2063, 2e-05, False)
    """

    phi1: np.ndarray
    te: np.ndarray
    jump: float

    @property
    def jump_arcsec(self) -> float:
        """:attr:`jump` in arcsec (NaN stays NaN)."""
        return self.jump / ARCSEC if np.isfinite(self.jump) else np.nan

    def continuous(self, jump_tol_arcsec: float) -> bool:
        """A pair is engaged at every cycle angle and no hand-over steps by more than
        ``jump_tol_arcsec`` [arcsec].

        Parameters
        ----------
        jump_tol_arcsec : float
            The largest step allowed [arcsec].

        Returns
        -------
        bool
            Whether the transmitted TE is continuous within that step.
        """
        return bool(np.isfinite(self.te).all() and self.jump_arcsec <= jump_tol_arcsec)

    @property
    def te_extreme(self) -> float:
        """The transmitted TE of largest magnitude [rad] (NaN if none is finite)."""
        fin = np.isfinite(self.te)
        return float(self.te[fin][np.argmax(np.abs(self.te[fin]))]) if fin.any() else np.nan

    @property
    def te_peak_to_peak(self) -> float:
        """max - min of the finite transmitted TE [rad] (NaN if none is finite)."""
        fin = np.isfinite(self.te)
        return float(np.ptp(self.te[fin])) if fin.any() else np.nan


def sampled_cycle(phi1, te, pitch: float, n_points: int, pairs=range(-2, 3), *, handover: str = "jump") -> SampledCycle:
    """TE transmitted over one mesh cycle of ``n_points`` angles from -pitch/2 to +pitch/2, from
    pair 0's TE sampled on a grid (``phi1``, ``te`` [rad], NaN where pair 0 has no contact on the
    flanks): the upper envelope (:func:`upper_envelope`) of the neighbouring pairs' curves
    (:func:`pair_te_curves`, pairs k in ``pairs``) and its largest hand-over step, measured by
    :func:`handover_jump` (``handover="jump"``) or by the sign-aware :func:`handover_gap`
    (``"gap"``: a crossing between grid angles is continuous). With fewer than two finite samples
    the envelope is NaN everywhere and the step NaN.

    Parameters
    ----------
    phi1, te : (n,) array_like
        Pair 0's grid and TE [rad].
    pitch : float
        Angular pitch 2 pi / N1 [rad], > 0.
    n_points : int
        Angles of the cycle, >= 2.
    pairs : iterable of int, optional
        Tooth-pair offsets k.
    handover : {"jump", "gap"}, optional
        How the hand-over step is measured.

    Returns
    -------
    SampledCycle
        The cycle's angles, TE and largest step.

    Raises
    ------
    ValueError
        If ``handover``, ``n_points`` or ``pitch`` is bad.

    Examples
    --------
    >>> import numpy as np
    >>> pitch = 2 * np.pi / 23  # rad
    >>> q = np.linspace(-0.2, 0.2, 41)  # pair 0's grid [rad]; its TE a parabola, engaged for |q| < 0.15
    >>> te = np.where(np.abs(q) < 0.15, -q * q, np.nan)
    >>> from gearrep.meshing import sampled_cycle
    >>> cycle = sampled_cycle(q, te, pitch, 5)
    >>> np.round(cycle.te, 6).tolist(), cycle.jump, cycle.continuous(1.0)
    ([-0.01868, -0.004678, -0.0, -0.004678, -0.01868], 0.0, True)
    >>> round(cycle.te_peak_to_peak, 6), round(cycle.te_extreme, 6)  # rad
    (0.01868, -0.01868)
    """
    if handover not in ("jump", "gap"):
        raise ValueError(f"handover must be 'jump' or 'gap', got {handover!r}")
    if isinstance(n_points, bool) or not isinstance(n_points, (int, np.integer)) or n_points < 2:
        raise ValueError(f"n_points must be an integer >= 2, got {n_points!r}")
    if not (np.isfinite(pitch) and pitch > 0):
        raise ValueError(f"pitch must be > 0 rad, got {pitch!r}")
    at = np.linspace(-0.5 * pitch, 0.5 * pitch, int(n_points))
    if np.count_nonzero(np.isfinite(np.asarray(te, float))) < 2:
        return SampledCycle(at, np.full(at.shape, np.nan), np.nan)
    curves = pair_te_curves(phi1, te, pitch, at, pairs)
    env, lead = upper_envelope(curves)
    step = handover_gap if handover == "gap" else handover_jump
    return SampledCycle(at, env, float(step(curves, lead, env)))
