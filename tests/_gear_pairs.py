"""The example pairs of the thesis (seed 003) that several test files share: the sec. 6.2 spur pair
and the Table 2 helical pair (lengths and angles as the portability check moves them), the Table 5
straight bevel gears and the sec. 5.2 spiral bevel gears."""

import numpy as np
from _numerics import nudged

from gearrep.surfaces.bevel import BevelGearData
from gearrep.surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
from gearrep.tca import GearPair

D = np.radians
ALPHA = D(20)
C1 = 0.002857  # thesis sec. 6.2 crowning of gear 1


def spur_pair(n1=52, n2=72, m=1.0, b=11.42, crown1=None, thin1=0.0, thin2=0.0, mis=None):
    """Thesis sec. 6.2 spur pair (52/72, m = 1, 20 deg, b = 11.42); lengths and angles as the
    portability check moves them (tests/_numerics.py, ``nudged``)."""
    m, b, alpha = nudged(m), nudged(b), nudged(ALPHA)
    g1 = InvoluteGearData(n1, m, alpha, b)
    g2 = InvoluteGearData(n2, m, alpha, b)
    c1 = crown1
    if thin1:
        c1 = ParabolicCrowning(0.0 if crown1 is None else crown1.c1, 0.0, thin1)
    c2 = ParabolicCrowning(0.0, 0.0, thin2) if thin2 else None
    f1, f2 = mating_flanks(g1, g2, crowning1=c1, crowning2=c2)
    return GearPair(f1, f2, n1, n2, standard_centre_distance(g1, g2), misalignment=mis), g1, g2


def helical_pair(form="true", crown1=None, mis=None, n1=40, n2=37):
    """Thesis Table 2 helical pair (40/37, m_n = 1, 20 deg, beta = 14 deg, b = 20); lengths and
    angles as the portability check moves them."""
    m, alpha, b, beta = nudged(1.0), nudged(ALPHA), nudged(20.0), nudged(D(14))
    g1 = InvoluteGearData(n1, m, alpha, b, helix_angle=beta)
    g2 = InvoluteGearData(n2, m, alpha, b, helix_angle=beta)
    f1, f2 = mating_flanks(g1, g2, crowning1=crown1, helix_form=form)
    return GearPair(f1, f2, n1, n2, standard_centre_distance(g1, g2), misalignment=mis), g1, g2


def straight_bevel(n1=39, n2=32):
    """Thesis Table 5 straight bevel gears (39/32, m = 2.5, 20 deg, b = 14): (gear 1, gear 2)."""
    return BevelGearData(n1, n2, 2.5, D(20), 14.0), BevelGearData(n2, n1, 2.5, D(20), 14.0)


def spiral_bevel():
    """Thesis sec. 5.2 spiral bevel gears (17/17, m = 1, 20 deg, b = 4.8, 35 deg spiral): (gear 1, gear 2)."""
    g = BevelGearData(17, 17, 1.0, D(20), 4.8, spiral_angle=D(35))
    return g, g
