"""Loaded tooth contact analysis (LTCA): load distribution, loaded transmission error, contact
pressure and mesh stiffness of a gear pair under torque.

Model
-----
1. **Initial separations from the surfaces** (:mod:`._separation`): member 1's face is cut into
   strips; at each mesh position the section of every strip of every tooth pair that can be in
   mesh is brought into contact with member 2's flank (curve-to-surface tangency, a Newton solve
   on the flank surfaces of :mod:`gearrep.tca`'s pair). Member 2 rests at the first touch (the
   unloaded TCA transmission error); the other strips are open by their initial separations.
2. **Compliance** (:mod:`._compliance`): per strip, the thin-slice model of ISO 6336-1 Annex E:
   independent strips along the face (no coupling between strips), each with the Weber-Banaschek
   tooth compliance of both members (bending, shear, compression) plus the Sainsot-Velex-Duverger
   fillet-foundation term, and Weber's line-contact approach (Hertzian flattening, non-linear in
   the load).
3. **Load distribution** (:mod:`._distribution`): the contact problem (non-negative loads, contact
   where the deformed gap closes, torque balance about the driving axis) as a convex quadratic
   programme (Conry & Seireg 1973), solved by a primal active-set method; the Hertzian
   non-linearity by fixed-point iteration on the secant compliance.
4. **Results** (:mod:`._analysis`): per position the loaded TE, loads per tooth pair, Hertz
   line-contact pressure per strip (Johnson eq 4.45) and its map, mesh stiffness; per cycle the
   summary of :class:`CycleSummary`.

Scope: involute spur and helical pairs, unmodified (line contact), crowned or misaligned
(localised contact along the strips). Not modelled: coupling between strips along the face, edge
contact at the flank boundaries, the root fillet shape, shaft and bearing deflections, friction.
Units: N, mm, MPa, N m for the torque; angles in rad. :mod:`.iso` holds the ISO 6336 closed forms
used to validate the results.
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
from ._families import SUPPORTED
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
