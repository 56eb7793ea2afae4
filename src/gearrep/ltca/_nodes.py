"""Compliance of the candidate contact nodes: tooth compliance per node and the contact
deformation, coupled between the nodes of a tooth pair along the face.

A node i carries the load F_i [N] over its contact-line length L_i (intensity w_i = F_i / L_i).
Its deflection along the contact force's line is

    delta_i = lambda_i w_i + sum_j G_ij w_j

* lambda_i [mm^2/N]: the tooth compliance of both members at the node (Weber-Banaschek beam and
  Sainsot foundation, :class:`gearrep.ltca.ToothCompliance`; per strip, a thin slice);
* G_ij [mm^2/N]: the contact deformation at node i due to node j's load, the Boussinesq
  half-space displacement of the surface relative to the point at depth h_i on the load line
  (Weber's reference: the tooth centre line), for both bodies
  (:func:`gearrep.ltca.half_space_segment_mm2_per_N`): node j's load is a line load on its
  segment of the contact line, laterally smeared as a Hertz strip of half-width b_j (the offset
  HERTZ_STRIP_OFFSET b_j), with its mirror images in the planes of member 1's face ends.

Over a uniformly loaded line the sum over j is Weber's line-contact approach (plane strain), so an
unmodified aligned pair is computed as by independent strips; a localized load is coupled to its
neighbours as on a half-space, which is Hertz's point contact when the teeth are rigid. The
images make a free face end behave like a plane of symmetry (the first-order correction of the
half-space for the quarter-space of a tooth end: Hetenyi, "A general solution for the elastic
quarter space", J. Appl. Mech. 37 (1970) 70-76; used for edge contact by Guilbault, "A fast
correction for elastic quarter-space applied to 3D modeling of edge contact problems",
J. Tribol. 133 (2011) 031402); without them the half-space beyond the face end would stiffen the
end nodes. The influence coefficients are those of Conry & Seireg's (1973) load-distribution
programme, the half-space for the contact part; the tooth bending is not coupled along the face
(each node's beam is a slice).

The compliance matrix C_ij = (lambda_i delta_ij + G_ij) / L_j is made symmetric, (C + C^T) / 2 (the
discrete influence coefficients are reciprocal only up to the difference of the nodes' lengths
and depths, see Betti's theorem), and depends on the loads through the Hertz widths b_j: the load
distribution iterates on it (:mod:`gearrep.ltca._analysis`).
"""

from __future__ import annotations

import numpy as np

from ..ellipse import effective_modulus
from ._compliance import (
    HERTZ_STRIP_OFFSET,
    ToothCompliance,
    contact_half_width_mm,
    half_space_segment_mm2_per_N,
    plate_kernel,
    weber_contact_approach_mm,
)
from ._families import Member
from ._separation import Separations

__all__ = ["Nodes"]


class Nodes:
    """Per-candidate data of all positions, flattened: compliances, depths, lengths, geometry.

    ``tooth_bending``: False leaves the tooth compliance out (the contact deformation alone, the
    rigid-tooth limit); ``coupling``: False uses Weber's approach per node (independent strips)."""

    def __init__(
        self, sep: Separations, m1: Member, m2: Member, materials, bore_radius_mm, *, tooth_bending=True, coupling=True
    ):
        c = sep.contacts
        ok = sep.in_contact.ravel()
        n = ok.size
        self.materials = materials
        self.coupling = bool(coupling)
        self.Estar = float(
            effective_modulus(materials[0].E_MPa, materials[0].poisson, materials[1].E_MPa, materials[1].poisson)
        )
        self.lam1, self.lam2, self.H1, self.H2, self.h1, self.h2 = (np.full(n, np.nan) for _ in range(6))
        if np.any(ok):
            t1 = ToothCompliance(m1, materials[0], bore_radius_mm[0])
            t2 = ToothCompliance(m2, materials[1], bore_radius_mm[1])
            u1, v1, u2, v2 = c.u1[ok], c.v1[ok], c.u2[ok], c.v2[ok]
            on = 1.0 if tooth_bending else 0.0
            self.lam1[ok], self.lam2[ok] = on * t1.compliance(u1, v1), on * t2.compliance(u2, v2)
            self.H1[ok], self.H2[ok] = t1.cantilever_length(u1, v1), t2.cantilever_length(u2, v2)
            self.h1[ok] = t1.load_geometry(u1, v1)[2]
            self.h2[ok] = t2.load_geometry(u2, v2)[2]
        self.lam = self.lam1 + self.lam2
        self.L = sep.line_length_mm.ravel()
        self.k = sep.k_rel_per_mm.ravel()
        self.p = c.position
        across = sep.across.reshape(-1, 3)
        line = np.cross(c.normal, across)
        with np.errstate(invalid="ignore"):
            line = line / np.linalg.norm(line, axis=1, keepdims=True)
            line *= np.where(line[:, 2] < 0, -1.0, 1.0)[:, None]  # along increasing z
            # each node's segment of the contact line: its tributary interval of the face
            dz = np.diff(sep.z_mm, axis=-1)
            zeros = np.zeros(sep.z_mm.shape[:-1] + (1,))
            cos = np.abs(line[:, 2])
            self.left = (0.5 * np.concatenate([zeros, dz], axis=-1)).ravel() / cos
            self.right = (0.5 * np.concatenate([dz, zeros], axis=-1)).ravel() / cos
        self.line = line
        self.across = across
        self.ends = (m1.z_lo, m1.z_hi)

    def compliance(self, rows, F, groups, block=None):
        """Secant compliance of the nodes ``rows`` at loads F > 0 [N]: the (n, n) matrix [mm/N]
        (block-diagonal over ``groups``, the tooth pair of each row), or its diagonal when not
        coupled. ``block``: the geometry of :meth:`prepare` for these rows (made here if None)."""
        L = self.L[rows]
        tooth = self.lam[rows] / L
        if not self.coupling:
            dH = weber_contact_approach_mm(F / L, self.k[rows], self.h1[rows], self.h2[rows], *self.materials)
            return tooth + dH / F
        blk = self.prepare(rows, groups) if block is None else block
        ye = HERTZ_STRIP_OFFSET * self.strip_width(rows, F, blk)
        lat = np.sqrt(blk["lat2"] + ye[blk["j"]] ** 2)
        G = half_space_segment_mm2_per_N(blk["x1"], blk["x2"], lat, blk["h1"], self.materials[0])
        G += half_space_segment_mm2_per_N(blk["x1"], blk["x2"], lat, blk["h2"], self.materials[1])
        C = np.zeros((rows.size, rows.size))
        np.add.at(C, (blk["i"], blk["j"]), (G + blk["plate"]) / L[blk["j"]])
        return 0.5 * (C + C.T)

    def strip_width(self, rows, F, blk):
        """Hertz half-widths b_i of the nodes ``rows`` from their intensity averaged along the line with
        a triangle of half-width b_i (the plane-strain strip holds where the intensity varies little
        over a width; the average keeps a node finer than the width from setting it alone, which
        makes the secant iteration unstable, and the weights are continuous in the loads, so that it
        does not cycle)."""
        w = F / self.L[rows]
        b = contact_half_width_mm(w, self.k[rows], self.Estar)
        i, j, d = blk["ni"], blk["nj"], blk["nd"]
        kern = np.maximum(1.0 - d / b[i], 0.0)  # a triangle of half-width b_i (continuous in the loads)
        kern[i == j] = 1.0
        n = rows.size
        wbar = np.bincount(i, weights=kern * w[j], minlength=n) / np.bincount(i, weights=kern, minlength=n)
        return contact_half_width_mm(wbar, self.k[rows], self.Estar)

    def prepare(self, rows, groups):
        """The load-independent geometry of the influence coefficients of ``rows`` (module
        docstring): for every (node i, source j) of one tooth pair, and the sources' mirror images in
        member 1's face-end planes, the source segment's ends x1, x2 along node i's line, the squared
        lateral offset and node i's depths."""
        out = {k: [] for k in ("i", "j", "x1", "x2", "lat2", "h1", "h2", "plate", "ni", "nj", "nd")}
        lam1, lam2, H1, H2 = self.lam1[rows], self.lam2[rows], self.H1[rows], self.H2[rows]
        nu1, nu2 = self.materials[0].poisson, self.materials[1].poisson
        p, line, across = self.p[rows], self.line[rows], self.across[rows]
        left, right = self.left[rows], self.right[rows]
        for g in np.unique(groups):
            sel = np.flatnonzero(groups == g)
            I, J = np.meshgrid(sel, sel, indexing="ij")
            I, J = I.ravel(), J.ravel()
            for image in (None, *self.ends):
                q, lo, hi = p[J], left[J], right[J]
                if image is not None:  # the mirror image: z -> 2 z_end - z, the segment reversed
                    q = q.copy()
                    q[:, 2] = 2.0 * image - q[:, 2]
                    lo, hi = hi, lo
                d = q - p[I]
                a = np.sum(d * line[I], axis=1)
                out["i"].append(I)
                out["j"].append(J)
                out["x1"].append(a - lo)
                out["x2"].append(a + hi)
                out["lat2"].append(np.sum(d * across[I], axis=1) ** 2)
                # the teeth as cantilever plates along the face (z): the source's tributary interval
                cz = np.abs(line[J, 2])
                z1, z2 = d[:, 2] - lo * cz, d[:, 2] + hi * cz
                out["plate"].append(
                    lam1[I] * (plate_kernel(z2 / H1[I], nu1) - plate_kernel(z1 / H1[I], nu1))
                    + lam2[I] * (plate_kernel(z2 / H2[I], nu2) - plate_kernel(z1 / H2[I], nu2))
                )
                if image is None:  # the distances along the line within the tooth pair
                    out["ni"].append(I)
                    out["nj"].append(J)
                    out["nd"].append(np.abs(a))
                out["h1"].append(self.h1[rows][I])
                out["h2"].append(self.h2[rows][I])
        return {k: np.concatenate(v) for k, v in out.items()}
