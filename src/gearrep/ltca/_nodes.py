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
    _depth_term,
    _surface_coefficient,
    contact_half_width_mm,
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
        if not self.coupling:
            dH = weber_contact_approach_mm(F / L, self.k[rows], self.h1[rows], self.h2[rows], *self.materials)
            return self.lam[rows] / L + dH / F
        blk = self.prepare(rows, groups) if block is None else block
        ye = HERTZ_STRIP_OFFSET * self.strip_width(rows, F, blk)
        lat = np.sqrt(blk["lat2"] + ye[blk["j"]] ** 2)  # (n_images, E)
        m1, m2 = self.materials
        surface = (_surface_coefficient(m1) + _surface_coefficient(m2)) * (
            np.arcsinh(blk["x2"] / lat) - np.arcsinh(blk["x1"] / lat)
        )
        C = np.zeros((rows.size, rows.size))
        C[blk["i"], blk["j"]] = (surface.sum(axis=0) + blk["fixed"]) / L[blk["j"]]
        return 0.5 * (C + C.T)

    def strip_width(self, rows, F, blk):
        """Hertz half-widths b_i of the nodes ``rows`` from their intensity averaged along the line with
        a triangle of half-width b_i (the plane-strain strip holds where the intensity varies little
        over a width; the average keeps a node finer than the width from setting it alone, which
        makes the secant iteration unstable, and the weights are continuous in the loads, so that it
        does not cycle)."""
        w = F / self.L[rows]
        b = contact_half_width_mm(w, self.k[rows], self.Estar)
        i, j, d = blk["i"], blk["j"], blk["dist"]
        kern = np.maximum(1.0 - d / b[i], 0.0)  # a triangle of half-width b_i (continuous in the loads)
        kern[blk["self"]] = 1.0
        n = rows.size
        wbar = np.bincount(i, weights=kern * w[j], minlength=n) / np.bincount(i, weights=kern, minlength=n)
        return contact_half_width_mm(wbar, self.k[rows], self.Estar)

    def prepare(self, rows, groups):
        """The load-independent geometry of the influence coefficients of ``rows`` (module
        docstring): for every (node i, source j) of one tooth pair (``i``, ``j``: E pairs), and for
        the source itself and its mirror images in member 1's face-end planes (first axis), the
        source segment's ends x1, x2 along node i's line and the squared lateral offset; node i's
        depths; the plate part of the tooth compliance (summed over the images); the distances
        along the line (``dist``, for :meth:`strip_width`)."""
        Is, Js = [], []
        for g in np.unique(groups):
            sel = np.flatnonzero(groups == g)
            I, J = np.meshgrid(sel, sel, indexing="ij")
            Is.append(I.ravel())
            Js.append(J.ravel())
        I, J = np.concatenate(Is), np.concatenate(Js)
        p, line, across = self.p[rows], self.line[rows], self.across[rows]
        left, right = self.left[rows], self.right[rows]
        x1, x2, lat2, z1, z2 = [], [], [], [], []
        cz = np.abs(line[J, 2])
        for image in (None, *self.ends):
            q, lo, hi = p[J], left[J], right[J]
            if image is not None:  # the mirror image: z -> 2 z_end - z, the segment reversed
                q = q.copy()
                q[:, 2] = 2.0 * image - q[:, 2]
                lo, hi = hi, lo
            d = q - p[I]
            a = np.einsum("ij,ij->i", d, line[I])
            x1.append(a - lo)
            x2.append(a + hi)
            lat2.append(np.einsum("ij,ij->i", d, across[I]) ** 2)
            # the teeth as cantilever plates along the face (z): the source's tributary interval
            z1.append(d[:, 2] - lo * cz)
            z2.append(d[:, 2] + hi * cz)
        z1, z2 = np.array(z1), np.array(z2)
        plate = 0.0
        for lam, H, mat in ((self.lam1, self.H1, self.materials[0]), (self.lam2, self.H2, self.materials[1])):
            Hi = H[rows][I]
            P = plate_kernel(np.concatenate([z2, z1]) / Hi, mat.poisson)
            plate = plate + lam[rows][I] * (P[: z2.shape[0]] - P[z2.shape[0] :]).sum(axis=0)
        x1, x2, lat2 = np.array(x1), np.array(x2), np.array(lat2)
        # the depth terms with the strip's lateral smearing left out: it moves them by O((b/h)^2),
        # the order to which the coupling sums to Weber's approach anyway, and so they do not change
        # with the loads
        lat0 = np.sqrt(lat2)
        depth = sum(
            _depth_term(x1, x2, lat0, h[rows][I], m).sum(axis=0)
            for h, m in ((self.h1, self.materials[0]), (self.h2, self.materials[1]))
        )
        return dict(
            i=I,
            j=J,
            x1=x1,
            x2=x2,
            lat2=lat2,
            fixed=plate - depth,
            dist=np.abs(x1[0] + left[J]),
            self=I == J,
        )
