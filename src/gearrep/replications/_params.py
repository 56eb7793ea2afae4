"""Checking of a replication's parameter dict (shared by the modules of this package): merge over
the defaults with unknown keys refused, numbers in a range, positive values, counts. Every error
is a ValueError that names the replication, the key and the allowed range."""

from __future__ import annotations

import copy

import numpy as np


def merge(label: str, defaults: dict, params: dict | None, *overlays: dict, passthrough=()) -> dict:
    """Deep copy of ``defaults`` updated by each overlay, then by ``params``; a key of ``params``
    that is neither a default nor in ``passthrough`` is refused."""
    if params is not None and not isinstance(params, dict):
        raise ValueError(f"{label} params must be a dict, got {type(params).__name__}")
    p = copy.deepcopy(defaults)
    for o in overlays:
        p.update(copy.deepcopy(o))
    unknown = sorted(k for k in (params or {}) if k not in defaults and k not in passthrough)
    if unknown:
        raise ValueError(f"{label} params: unknown key {unknown[0]!r} (unknown keys {unknown}; "
                         f"allowed {sorted(defaults)})")
    for k, v in (params or {}).items():
        p[k] = copy.deepcopy(v)
    return p


def number(p: dict, key: str, lo: float, hi: float, *, integer: bool = False):
    """``p[key]`` as a float (or int) in [lo, hi]."""
    v = p[key]
    try:
        f = float(v)
    except (TypeError, ValueError):
        raise ValueError(f"{key} must be a number in [{lo}, {hi}], got {v!r}") from None
    if not (np.isfinite(f) and lo <= f <= hi) or (integer and f != int(f)):
        raise ValueError(f"{key} must be {'an integer' if integer else 'a number'} in [{lo}, {hi}], got {v!r}")
    return int(f) if integer else f


def positive(label: str, p: dict, keys) -> None:
    """Each ``p[key]`` a finite number > 0."""
    for k in keys:
        if not (np.isfinite(float(p[k])) and float(p[k]) > 0):
            raise ValueError(f"{label} params: {k} must be > 0, got {p[k]!r}")


def counts(label: str, p: dict, keys) -> None:
    """Each ``p[key]`` an integer >= 1."""
    for k in keys:
        if int(p[k]) != p[k] or p[k] < 1:
            raise ValueError(f"{label} params: {k} must be a positive integer, got {p[k]!r}")
