"""gearrep.units: conversions exact and inverse."""

import math

import numpy as np
import pytest

from gearrep import units


@pytest.mark.parametrize(
    "to, back, x, y",
    [
        (units.deg2rad, units.rad2deg, 180.0, math.pi),
        (units.arcmin2rad, units.rad2arcmin, 60.0, math.pi / 180.0),
        (units.arcsec2rad, units.rad2arcsec, 3600.0, math.pi / 180.0),
        (units.in2mm, units.mm2in, 1.0, 25.4),
    ],
)
def test_unit_conversions_exact_and_inverse(to, back, x, y):
    assert to(x) == pytest.approx(y, rel=1e-15)
    arr = np.array([-2.5, 0.0, 1e-9, 7.0])
    np.testing.assert_allclose(back(to(arr)), arr, rtol=1e-15, atol=0)
