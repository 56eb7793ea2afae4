"""Seed 004's printed relative-curvature equations (gearrep.replications.ma2021.model) against the
library routes the replication computes with (gearrep.ellipse, gearrep.curvature)."""

from __future__ import annotations

import numpy as np
import pytest

from gearrep import curvature, ellipse
from gearrep.replications.ma2021 import model
from gearrep.surfaces.catt import CATTFlank, CATTGearData


def test_eq23_26_as_printed_equals_the_library_route():
    """Random curvatures and angles: A, B and |alpha| of eq (23)-(26) equal
    ellipse.litvin_coefficients (which computes them as eigenvalues of the relative tensor)."""
    rng = np.random.default_rng(4)
    k = rng.normal(scale=0.05, size=(4, 200))
    k1I, k2I = np.maximum(k[0], k[1]), np.minimum(k[0], k[1])
    k1II, k2II = np.maximum(k[2], k[3]), np.minimum(k[2], k[3])
    sigma = rng.uniform(0, np.pi, 200)
    A, B, alpha = model.litvin_AB_eq23_26(k1I, k2I, k1II, k2II, sigma)
    A_lib, B_lib, alpha_lib = ellipse.litvin_coefficients(k1I, k2I, k1II, k2II, sigma)
    np.testing.assert_allclose(A, A_lib, rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(B, B_lib, rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(alpha, np.abs(alpha_lib), atol=1e-7)


def test_eq23_loses_digits_to_the_cancellation_the_library_avoids():
    """A CATT-like pair (sigma = 90 deg): the relative axial curvature 2A is the difference of the
    two flanks' axial curvatures c / (R_T -+ q), far smaller than kS ~ the profile curvatures. The
    printed A = (kS - root)/4 carries the rounding of kS and root (absolute ~1e-17), so its relative
    error grows like 1/A ~ R_T^2; the library route stays at rounding (exact A from fractions)."""
    from fractions import Fraction

    c, q = np.cos(np.radians(20)), np.pi * 8 / 4
    errs = []
    for RT in (500.0, 5000.0, 50000.0):
        kI_ax, kII_ax = c / (RT - q), c / (RT + q)  # surface I: k1 = profile 0.01; surface II: k2 = profile -0.03
        exact = 0.5 * float(Fraction(kI_ax) - Fraction(kII_ax))
        args = (0.01, kI_ax, kII_ax, -0.03, np.pi / 2)
        A_lib = ellipse.litvin_coefficients(*args)[0]
        A_eq = model.litvin_AB_eq23_26(*args)[0]
        assert abs(A_lib / exact - 1) < 1e-15
        errs.append(abs(A_eq / exact - 1))
    assert errs[-1] > 1e-10 and errs[-1] > 100 * errs[0]  # digits lost grow with R_T


def test_eq20_like_indexed_is_right_only_when_first_directions_coincide():
    k1I, k2I, k1II, k2II = 0.03, 0.01, 0.02, -0.01
    d1, d2 = model.eq20_like_indexed(k1I, k2I, k1II, k2II)
    k1, k2, _ = curvature.relative_principal_curvatures(k1I, k2I, k1II, k2II, 0.0)
    np.testing.assert_allclose(sorted([d1, d2]), sorted([k1, k2]), rtol=1e-14)
    k1, k2, _ = curvature.relative_principal_curvatures(k1I, k2I, k1II, k2II, np.pi / 2)
    assert not np.allclose(sorted([d1, d2]), sorted([k1, k2]))


def test_second_form_in_basis_is_the_shape_matrix_on_a_catt_flank():
    """curvature.second_form_in_basis (used by the replication's tensor route) in the basis of
    curvature.shape_matrix equals that matrix; its eigenvalues are the principal curvatures."""
    f = CATTFlank(CATTGearData(19, 8.0, 500.0, 80.0), -1)
    th, ph = np.meshgrid(np.linspace(-0.05, 0.05, 5), np.linspace(f.lower[1], f.upper[1], 5))
    P = f.evaluate(th.ravel(), ph.ravel())
    t1, t2, n, S11, S12, S22 = curvature.shape_matrix(P)
    K = curvature.second_form_in_basis(P, n, t1, t2)
    scale = np.max(np.abs([S11, S12, S22]))
    np.testing.assert_allclose(K[..., 0, 0], S11, atol=1e-12 * scale)
    np.testing.assert_allclose(K[..., 0, 1], S12, atol=1e-12 * scale)
    np.testing.assert_allclose(K[..., 1, 1], S22, atol=1e-12 * scale)
    pc = curvature.principal_curvatures(P)
    k1, k2, _ = curvature.sym2_eig(K[..., 0, 0], K[..., 1, 0], K[..., 1, 1])
    np.testing.assert_allclose(k1, pc.k1, rtol=1e-10)
    np.testing.assert_allclose(k2, pc.k2, rtol=1e-10)
    # the opposite normal flips the form
    np.testing.assert_allclose(curvature.second_form_in_basis(P, -n, t1, t2), -K, atol=1e-15)


def test_the_cycle_index_looks_each_design_and_curve_up_once():
    """The claims ask for the same curves hundreds of times: each is selected and sorted once and
    handed out again (the same frame), per reading of on_path; designs likewise."""
    import pandas as pd

    from gearrep.replications.ma2021 import sweeps

    rows = []
    for design, module in (("a", 4.0), ("b", 8.0)):
        for phi, on_path in ((2.0, True), (1.0, False), (0.0, True)):
            rows.append(
                {"design": design, "group": "fig12", "module_mm": module, "pair": "B", "reading": "R1",
                 "phi_paper_deg": phi, "in_window": True, "on_path": on_path, "S_mm2": phi + module}
            )  # fmt: skip
    idx = sweeps.CycleIndex(pd.DataFrame(rows))
    c = sweeps.curve(idx, "a", "B", "R1")
    assert list(c["phi_paper_deg"]) == [0.0, 2.0]
    assert sweeps.curve(idx, "a", "B", "R1") is c
    assert list(sweeps.curve(idx, "a", "B", "R1", on_path_only=False)["phi_paper_deg"]) == [0.0, 1.0, 2.0]
    assert sweeps._design(idx, "F12", 8.0, {}) == "b" == sweeps._design(idx, "F12", 8.0, {})
    with pytest.raises(ValueError, match="expected one design"):
        sweeps._design(idx, "F12", 12.0, {})
