"""Contact ellipses cut by the tooth edges (pure: arrays in, arrays out).

A Hertz contact ellipse is the footprint on unbounded surfaces; on a tooth it ends where the flank
ends. Each edge of each member is taken as a half-space at the contact point P (the ellipse is
small against the tooth's radii), given by its family (``Family.edge_spaces``); for members on
parallel or crossed axes (:func:`axial_edges`) a face edge is the plane at axial coordinate +-B/2
of that member (axial coordinate along its axis, from its mid-face point), a tip circle (where the
gear data know r_a) the plane tangent to the tip cylinder at the foot of P, normal to the radial
direction e_r. With unit direction u out of the flank and distance d from P to that plane, the
ellipse (semi-axes a, b along unit m, m2) reaches the edge when sqrt(a^2 (u.m)^2 + b^2 (u.m2)^2)
> d. The ellipse cut by all the half-spaces is a convex polygon (:data:`POLYGON_POINTS` points on
the ellipse, clipped); its area is the contact area on the flank, and the major axis, cut by the
same half-spaces, runs from ``lo`` to ``hi`` (signed distances from P along m).

The pinion turns about z_f through the origin; the gear about A2 z through O2 (its mid-face point,
:class:`gearrep.tca.GearPair`).
"""

from __future__ import annotations

import numpy as np

__all__ = ["EDGES", "POLYGON_POINTS", "EdgeCut", "axial_edges", "cut_at_edges"]

#: edge names, in the order the half-spaces of :func:`axial_edges` come
EDGES = ("pinion_face", "pinion_tip", "gear_face", "gear_tip")
#: points on the ellipse of the clipped polygon (the area is the polygon's clipped share of pi a b)
POLYGON_POINTS = 72


class EdgeCut:
    """Per contact point: ``edge`` (names of :data:`EDGES` reached, joined by "+", "" none),
    ``lo``, ``hi`` [mm] (the major axis on the flank), ``area`` [mm^2] (the ellipse on the flank)
    and ``outline`` (list of (k, 3) points [mm] of the cut ellipse, fixed frame; empty arrays where
    there is no ellipse)."""

    def __init__(self, edge, lo, hi, area, outline):
        self.edge, self.lo, self.hi, self.area, self.outline = edge, lo, hi, area, outline


def axial_edges(pair, face_width, P) -> list:
    """The edges of both members of a :class:`gearrep.tca.GearPair` at the contact points ``P``
    (n, 3) [mm]: a list of (name, u (n, 3), d (n,)), the flank being where u . (X - P) <= d (module
    docstring): the face edges at +-``face_width`` / 2 along each axis, the tip cylinders where
    the flanks' gear data know r_a."""
    tips = [getattr(getattr(f, "gear", None), "r_a", None) for f in (pair.flank1, pair.flank2)]
    half = 0.5 * float(face_width)
    z = np.array([0.0, 0.0, 1.0])
    out = []
    for member, origin, axis, r_a in (
        ("pinion", np.zeros(3), z, tips[0]),
        ("gear", np.asarray(pair.O2, float), pair.A2 @ z, tips[1]),
    ):
        rel = P - origin
        ax = rel @ axis
        out.append((f"{member}_face", np.tile(axis, (len(P), 1)), half - ax))
        out.append((f"{member}_face", np.tile(-axis, (len(P), 1)), half + ax))
        if r_a is not None:
            radial = rel - np.outer(ax, axis)
            r = np.linalg.norm(radial, axis=1)
            with np.errstate(invalid="ignore", divide="ignore"):
                out.append((f"{member}_tip", radial / r[:, None], float(r_a) - r))
    return out


def _clip(poly, normal, d):
    """Sutherland-Hodgman: the part of the convex 2-D polygon ``poly`` where normal . x <= d."""
    if len(poly) == 0:
        return poly
    s = poly @ normal - d
    out = []
    for i in range(len(poly)):
        j = (i + 1) % len(poly)
        if s[i] <= 0:
            out.append(poly[i])
        if (s[i] <= 0) != (s[j] <= 0):
            out.append(poly[i] + (poly[j] - poly[i]) * (s[i] / (s[i] - s[j])))
    return np.array(out).reshape(-1, 2)


def _area(poly) -> float:
    if len(poly) < 3:
        return 0.0
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def cut_at_edges(edges, position, normal, major_axis, a, b) -> EdgeCut:
    """The contact ellipses cut at the tooth edges (module docstring): ``edges(P)`` -> the list of
    half-spaces (name, u, d) at the points P (e.g. :func:`axial_edges`), ``position`` (n, 3) [mm]
    and ``normal`` (n, 3) of the contact points in the fixed frame, ``major_axis`` (n, 3) unit
    vectors, ``a``, ``b`` (n,) semi-axes [mm] (NaN: no ellipse there, then NaN results and edge "")."""
    P = np.asarray(position, float)
    m = np.asarray(major_axis, float)
    m2 = np.cross(np.asarray(normal, float), m)
    a, b = np.asarray(a, float), np.asarray(b, float)
    spaces = edges(P)
    th = np.linspace(0.0, 2.0 * np.pi, POLYGON_POINTS, endpoint=False)
    n = len(a)
    edge = np.full(n, "", dtype=object)
    lo, hi, area = np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan)
    outline = [np.empty((0, 3))] * n
    for i in np.flatnonzero(np.isfinite(a) & np.isfinite(b) & np.all(np.isfinite(P), axis=1)):
        poly = np.column_stack([a[i] * np.cos(th), b[i] * np.sin(th)])
        t_lo, t_hi, names = -a[i], a[i], []
        for name, u, d in spaces:
            um, um2 = float(u[i] @ m[i]), float(u[i] @ m2[i])
            if not np.isfinite(d[i]):
                continue
            di = max(float(d[i]), 0.0)  # a converged contact is on the flank (an edge contact to rounding)
            if np.hypot(a[i] * um, b[i] * um2) > di and name not in names:
                names.append(name)
            poly = _clip(poly, np.array([um, um2]), di)
            if um > 0:
                t_hi = min(t_hi, di / um)
            elif um < 0:
                t_lo = max(t_lo, di / um)
        edge[i] = "+".join(names)
        # the clipped share of the inscribed polygon times the ellipse's area (no polygon bias)
        lo[i], hi[i] = t_lo, t_hi
        area[i] = np.pi * a[i] * b[i] * _area(poly) / (0.5 * POLYGON_POINTS * a[i] * b[i] * np.sin(th[1]))
        outline[i] = P[i] + np.outer(poly[:, 0], m[i]) + np.outer(poly[:, 1], m2[i])
    return EdgeCut(edge, lo, hi, area, outline)
