"""Loaded tooth contact analysis (LTCA): load distribution, loaded transmission error, contact
pressure, edge contact and mesh stiffness of a gear pair under torque (docs/ltca.md).

Model
-----
1. **First touches from the surfaces** (:mod:`._separation`): nodes along member 1's face (the end
   nodes on the face ends) of every tooth pair that can be in mesh; each node's transverse section is
   brought into contact with member 2's flank: a tangency inside both flanks, or, beyond a flank's
   boundary, a contact at a tip edge or at member 2's face end (edge contact is found, not assumed
   away). Member 2 rests at the first touch (the unloaded TCA transmission error); the other nodes
   are open by their separations.
2. **Compliance** (:mod:`._compliance`, :mod:`._nodes`): the Weber-Banaschek tooth compliance of both
   members (bending, shear, compression) with the Sainsot-Velex-Duverger gear-body term, read from
   each member's own tooth section (:mod:`._families`), coupled along the face as a cantilever plate
   (Jaramillo 1950); the contact deformation as Boussinesq's half-space relative to the tooth centre
   line (Weber's reference), which couples the nodes and sums to Weber's line-contact approach over a
   uniform line; mirror images at the face ends.
3. **Load distribution** (:mod:`._distribution`, :mod:`._analysis`): the contact problem (loads >= 0,
   contact where the deformed gap closes, torque balance about the driving axis) as a convex
   quadratic programme (Conry & Seireg 1973), solved by a primal active-set method; the Hertz
   non-linearity by an accelerated fixed-point iteration; a localized contact is solved again on
   nodes over its loaded span.
4. **Results** (:mod:`._analysis`): per position the loaded TE, loads per tooth pair, the flank and
   tip-edge pressures, the loads at tip edges and face ends, the pressure map, the mesh stiffness; per
   cycle the summary of :class:`CycleSummary`.

Families (:data:`SUPPORTED`): involute spur and helical (crowned, relieved, misaligned) and CATT
flanks; bevel, Novikov-Wildhaber and hob-generated flanks are refused with the reason. The involute
tooth section has the root fillet of ISO 53's rack tip radius (0.38 m_n); not modelled: a CATT
tooth's fillet, shaft and bearing deflections, friction, dynamics. Units: N, mm, MPa, N m for
the torque; angles in rad. :mod:`.iso` holds the ISO 6336 closed forms the validation study
(``gearrep.replications.ltca``) compares with.

One call per family: ``loaded_contact(pair, torque_Nm, materials=(Material(E1, nu1),
Material(E2, nu2)), driving="pinion")`` for the ``GearPair`` of any supported family.
"""

from . import iso
from ._analysis import CycleSummary, LoadedContact, PressureMap, cycle_positions, loaded_contact
from ._compliance import (
    STEEL,
    Material,
    ToothCompliance,
    cantilever_plate_ratio,
    contact_half_width_mm,
    half_space_segment_mm2_per_N,
    line_contact_pressure_MPa,
    plate_kernel,
    weber_contact_approach_mm,
)
from ._distribution import ContactLoads, solve_contact_loads
from ._families import SUPPORTED, refusal
from ._separation import KINDS, Separations, face_nodes, initial_separations, section_contacts

__all__ = [
    "iso",
    "Material",
    "STEEL",
    "ToothCompliance",
    "contact_half_width_mm",
    "line_contact_pressure_MPa",
    "weber_contact_approach_mm",
    "half_space_segment_mm2_per_N",
    "cantilever_plate_ratio",
    "plate_kernel",
    "SUPPORTED",
    "refusal",
    "ContactLoads",
    "solve_contact_loads",
    "Separations",
    "face_nodes",
    "KINDS",
    "section_contacts",
    "initial_separations",
    "LoadedContact",
    "CycleSummary",
    "PressureMap",
    "cycle_positions",
    "loaded_contact",
]
