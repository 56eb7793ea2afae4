"""`gearrep.ltca.refusal`: the reason the loaded analysis refuses a flank, the one the refusal of
`loaded_contact` carries; empty for the supported families."""

import numpy as np
import pytest

from gearrep.ltca import loaded_contact, refusal
from gearrep.surfaces.bevel import BevelGearData, mating_bevel_flanks
from gearrep.surfaces.involute import InvoluteGearData, mating_flanks
from gearrep.tca import BevelPair


def test_refusal_is_empty_for_a_supported_flank_and_names_class_and_reason_otherwise():
    g = InvoluteGearData(20, 2.0, np.radians(20), 20.0)
    f1, _ = mating_flanks(g, g)
    assert refusal(f1) == ""
    b1, b2 = mating_bevel_flanks(*(BevelGearData(17, 17, 5.0, np.radians(20), 20.0) for _ in range(2)))
    why = refusal(b1)
    assert why.startswith("SphericalInvoluteFlank (bevel flanks: the tooth section lies on the back cone")
    with pytest.raises(ValueError) as e:
        loaded_contact(BevelPair(b1, b2, 17, 17), 10.0)
    assert str(e.value).endswith(f"got {why}")
    assert refusal(object()) == "object (no tooth section is defined for it)"
