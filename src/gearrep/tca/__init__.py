"""Tooth contact analysis (TCA) of two tooth surfaces on rotation axes, with misalignment.

Sources: Temirkhan, PhD thesis 2023 (seed 003): conventional (Litvin) formulation eq (26)-(32),
reduced two-unknown formulation eq (33)-(44), transmission error eq (14); Litvin & Fuentes,
"Gear Geometry and Applied Theory", 2nd ed., ch. 9 (simulation of meshing, TCA) and the spur/helical chapters.
Seed 000 eq (5.1)-(5.12) sets up the same conventional system.

Frames and conventions
----------------------

Fixed frame S_f. Member 1 turns about the z_f axis through the origin:
    r_f = Rz(phi1) r_1(u1, v1).

Member 2 turns about its own axis through O2 = (a + dE, dH, dZ) (a = centre distance):
    r_f = O2 + A2 Rz(phase2 - phi2) r_2(u2, v2),   A2 = Ry(d_gamma_in) Rx(shaft_angle + d_gamma_out).

So phi2 > 0 turns member 2 about w2 = -A2 z (the sense in which an external member 1 turning by
phi1 > 0 drives it), and for an aligned conjugate pair phi2 = (N1/N2) phi1. ``phase2`` defaults to
pi - side pi/N2: for involute flanks (tooth of each gear centred on its x axis) this places the
tooth space of member 2 on the centre line, so that the zero-backlash standard pair is in
conjugate mesh at phi1 = phi2 = 0. That position is not the pitch-point contact: tooth 1 is then
centred on the centre line, so its flank meets the line of action off the pitch point (0.26 mm
outside the pitch circle for the thesis's spur 52/72 pair). The contact passes the pitch point when
the flank's pitch-circle point reaches the centre line, half the tooth's angular thickness away
(phi1 = -side pi/(2 N1) for a standard tooth); solve for it where the pitch point is wanted.
Misalignment (all applied to member 2; the angular ones pivot about O2, i.e. the mid-face point of
its axis): d_gamma_in = rotation about y_f, in the plane of the axes (axes intersect);
d_gamma_out = rotation about x_f, the centre line (axes cross); dE = centre-distance change;
dH = offset along y_f; dZ = axial displacement along z_f.

Normals: ``normal`` of a contact point is the unit normal of member 1 pointing out of its tooth
(``outward_sign`` of the flank, -side for :class:`~gearrep.surfaces.involute.InvoluteFlank`).
At a true contact the outward normals are opposite: n_f1 + n_f2 = 0. Eq (27) prints n_f1 - n_f2 = 0,
which holds only if one normal is reversed; with both flanks parameterised alike (their
r_u x r_v both point into, or both out of, the material) eq (27) as printed has no solution near
the contact. A root with n_f1 . n_f2 > 0 (the two bodies on the same side of the common tangent
plane) is a false root and gets status WRONG_ROOT.

Transmission error (eq 14): TE = (phi2 - phi20) - (N1/N2)(phi1 - phi10), phi2 measured in the
driven sense above; TE > 0 means member 2 leads its conjugate position. Eq (14) as printed holds
only with that sign convention for phi2: if both angles are measured about +z (as the thesis's
pitch-point example phi1 = 1.5707, phi2 = -1.6 suggests), an external pair needs
TE = (phi2 - phi20) + (N1/N2)(phi1 - phi10). Default reference phi10 = phi20 = 0 (the nominal
conjugate placement), so TE is absolute; re-zero it with :func:`transmission_error`.

(a) Conventional formulation (eq 26-32): unknowns x = (u1, v1, u2, v2, phi2) for given phi1,
    F = [ r_f1 - r_f2 (3 eq),  two components of n_f1 + n_f2 ].
    The unit-normal equation has only two independent components (eq 28). We drop the component
    j = argmax |n_f1,j| at the starting point (fixed during the iterations): the kept components
    then determine the dropped one up to sign, and that is well conditioned because the dropped
    component is the largest. Dropping a small component instead (e.g. n_z of a spur gear, which
    is ~0) makes the 5x5 Jacobian singular, because the kept ones fix it only through n_z^2.
    The sign left free is checked after convergence (WRONG_ROOT if n_f1 + n_f2 != 0). For a crowned
    spur pair, keeping (x, y) instead gives a Jacobian with s_min/s_max ~ 3e-8 and, from starts
    near the root, ~40 % false roots with n_z1 = +n_z2 (tests/unit/tca/test_tca.py). ``drop=`` overrides.

(b) Reduced formulation (eq 33-44), for member 2 in explicit cylindrical form
    r_2 = (u cos psi(u,v), u sin psi(u,v), v) (u = radius, v = axial coordinate, eq 35-36):
    unknowns (u1, v1) for given phi1; (u2, v2, phi2) follow explicitly from the point

    r_f1(u1, v1, phi1) (eq 37-40): with s = Rz(-phase2) A2^T (r_f1 - O2),
        v2 = s_z (eq 39),   u2 = sqrt(s_x^2 + s_y^2) (eq 40),
        phi2 = angle(r_2(u2, v2)) - atan2(s_y, s_x)                      (eq 41-44),

    and the two equations are two components of n_f1 x n_f2 = 0 (eq 33), dropping the component
    along argmax |n_f1,j| at the start (n_f1 x n_f2 is orthogonal to n_f1, so that component is
    dependent). The position equation holds by construction. Keeping the other pair (e.g. x, y of
    n1 x n2 for a spur gear, whose normal has n_z ~ 0) gives two nearly dependent equations
    (c . n1 = 0 ties c_x to c_y) with a Jacobian ~30 times smaller, and root accuracy to match.
    Eq (43) computes phi2 = +-acos(p2 . q2 / |q2|^2) with the sign from eq (44). Two remarks:
    |q2|^2 = |p2||q2| only because both projections have length u2; and acos loses half the digits
    near phi2 = 0 or pi (d acos/dx is infinite at x = +-1: an error eps in the cosine gives
    sqrt(2 eps) ~ 1e-8 rad). We use the equivalent atan2 form, which is exact to rounding and
    carries its own sign: phi2 is the right-handed rotation about w2 = -A2 z that takes the
    projection p2 of the member-2 surface point to the projection q2 of the contact point, i.e.
    phi2 = atan2((p2 x q2) . w2, p2 . q2). The sign of eq (44) is therefore + when (p2 x q2) . w2 > 0,
    i.e. when the rotation p2 -> q2 is counter-clockwise seen from the tip of w2; "clockwise" in the
    thesis's wording holds only when viewed from the other side. phi2 is taken on the branch
    nearest the nominal (N1/N2) phi1.

Line contact: for conjugate surfaces (aligned, unmodified involute pairs) the contact is a line
and the point solve is singular. Pass ``v1=`` to fix member 1's face-width coordinate; the
unknowns become (u1) [reduced] or (u1, u2, v2, phi2) [conventional, 5 equations, 4 unknowns,
least squares].

Bevel pairs (intersecting axes, thesis sec 3.3 and 5, misalignments eq 47-48): :class:`BevelPair`
and :class:`BevelMisalignment` (private module ``_bevel``, whose docstring derives the explicit
spherical form of member 2 used by the reduced formulation); every solve here accepts them.

Pairs of generated flanks (seed 000 eq 5.1-5.11): two two-parameter envelopes
(:class:`gearrep.surfaces.hob.GeneratedGear`) meet in a 9-unknown tangency system
(:func:`envelope_tangency_system`, :func:`solve_envelope_points`, :func:`trace_envelope_path`,
:func:`envelope_physical_contact`, :func:`robust_envelope_points`; private modules ``_envelope``
and ``_envelope_contact``); the curvilinear-tooth pair cut by one ZA hob is :class:`HobbedPair`
with its :class:`HobbedAssembly` errors, reached by continuation from the ideal pair
(:func:`hobbed_continue_to`), with its kinematic-error table (:func:`ke_table`), tip crossings and
contact ellipses (private module ``_hobbed``). Their names here carry ``envelope`` or ``hobbed``
where the module's own name is generic (``Pair``, ``trace_path``).

Start strategies (random and line-of-action starts, private module ``_starts``) and solver
variants (plain / damped / domain-kept / seeded / robust Newton for the conventional formulation,
plain / damped / robust for the reduced one, private module ``_variants``) are in this package
too. The library's start strategy for any start on the flank is :func:`robust_contact`
(projection into member 2's explicit domain, reduced solve, conventional seeded from it, a grid
fallback keeping the loaded tangency); :func:`reference_contacts` and :func:`start_robustness`
(private module ``_robustness``) measure a strategy against the contact traced by continuation
and verified.

All solves go through :func:`gearrep.solve.newton`. Per-row data (phi1, a fixed v1, the dropped
component) are carried as extra unknowns frozen by identity rows with zero residual, because
``newton`` hands ``fun`` only the rows still iterating.

Speed (measured by ``make bench``, :func:`gearrep.benchmark.tca_throughput`): the
systems are evaluated by components (structure of arrays: surfaces' ``evaluate_components``,
:func:`gearrep.frames.rotate_z` and :func:`gearrep.frames.matrix_applier` for the fixed
mountings, no (n, 3, 3) stacks), residual and Jacobian in one evaluation per Newton step
(``newton(fun_jac=)``), cos/sin of phi1 once per solve, the contact record from the last
evaluation; one-point calls run the same kernels on Python floats. A numba-compiled reduced
residual/Jacobian (evaluated outside the repository, same expressions) gave the same numbers
bit for bit and cost 0.57 reference-kernel elements per row against 2.6 for numpy, but importing
numba took 1.5 s and the first compilation 15 s per process (load ~9 on 2 cores), against a
cold-run goal of 45 s for the whole workflow: not adopted; numpy is the only path.
"""

from . import _envelope, _envelope_contact, _hobbed
from ._bevel import BevelMisalignment, BevelPair
from ._curvature import contact_curvatures, contact_ellipse, contact_hertz
from ._envelope import hob_pitch_l
from ._formulations import (
    MAX_CONTACT_TOL,
    check_formulation,
    conventional_system,
    default_start,
    reduced_unknowns,
    solve_contact,
)
from ._hobbed import KE_COLUMNS, ke_table
from ._kernels import normal_derivatives, reduced_system
from ._pair import ContactPoints, GearPair, Misalignment, transmission_error
from ._path import trace_path
from ._robustness import ROBUSTNESS_COLUMNS, classify_contacts, reference_contacts, start_robustness
from ._rows import newton_rows
from ._starts import (
    FALLBACK_GRID,
    draw_starts,
    flank_sense,
    line_of_action_start,
    line_of_action_starts,
    meshing_sense,
    offset_start,
    project_starts,
    robust_contact,
)
from ._variants import (
    CONVENTIONAL_VARIANTS,
    REDUCED_VARIANTS,
    flank_boxes,
    guard_reduced_starts,
    robust_start,
    seed_from_reduced,
    solve_conventional,
    solve_reduced,
    solve_variant,
    transverse_stage,
)

#: the envelope-pair TCA (private modules ``_envelope``, ``_envelope_contact``) under names that say so
EnvelopeFlank = _envelope.Flank
envelope_flank = _envelope.make_flank
envelope_member_geometry = _envelope.member_geometry
envelope_dropped_component = _envelope.dropped_component
envelope_tangency_system = _envelope.tangency_system
EnvelopeContactPath = _envelope.ContactPath
solve_envelope_points = _envelope.solve_points
predict_envelope_contact = _envelope.predict
require_converged = _envelope.require
trace_envelope_path = _envelope.trace_path
envelope_physical_contact = _envelope_contact.physical_contact
envelope_pinion_outward = _envelope_contact.pinion_outward
envelope_tangency_near = _envelope_contact.tangency_near
envelope_turn_gap = _envelope_contact.turn_gap
robust_envelope_points = _envelope_contact.robust_points
classify_envelope_points = _envelope_contact.classify_points
#: the hob-cut curvilinear pair (private module ``_hobbed``)
HobbedAssembly = _hobbed.Assembly
HobbedPair = _hobbed.Pair
hobbed_pair = _hobbed.make_pair
hobbed_ideal_start = _hobbed.ideal_start
hobbed_continue_to = _hobbed.continue_to
clear_hobbed_start_cache = _hobbed.clear_start_cache
hobbed_physical_contact = _hobbed.physical_contact
hobbed_phi1_grid = _hobbed.phi1_grid
hobbed_tip_crossing = _hobbed.tip_crossing
hobbed_elastic_ellipses = _hobbed.elastic_ellipses

__all__ = [
    "Misalignment",
    "GearPair",
    "BevelMisalignment",
    "BevelPair",
    "ContactPoints",
    "transmission_error",
    "normal_derivatives",
    "conventional_system",
    "newton_rows",
    "check_formulation",
    "MAX_CONTACT_TOL",
    "default_start",
    "solve_contact",
    "reduced_unknowns",
    "reduced_system",
    "trace_path",
    "contact_curvatures",
    "contact_ellipse",
    "contact_hertz",
    "CONVENTIONAL_VARIANTS",
    "REDUCED_VARIANTS",
    "flank_boxes",
    "solve_conventional",
    "solve_reduced",
    "solve_variant",
    "seed_from_reduced",
    "guard_reduced_starts",
    "transverse_stage",
    "robust_start",
    "line_of_action_start",
    "line_of_action_starts",
    "draw_starts",
    "offset_start",
    "FALLBACK_GRID",
    "project_starts",
    "robust_contact",
    "meshing_sense",
    "flank_sense",
    "ROBUSTNESS_COLUMNS",
    "reference_contacts",
    "classify_contacts",
    "start_robustness",
    "EnvelopeFlank",
    "envelope_flank",
    "envelope_member_geometry",
    "envelope_dropped_component",
    "envelope_tangency_system",
    "EnvelopeContactPath",
    "solve_envelope_points",
    "predict_envelope_contact",
    "hob_pitch_l",
    "require_converged",
    "trace_envelope_path",
    "envelope_physical_contact",
    "envelope_pinion_outward",
    "envelope_tangency_near",
    "envelope_turn_gap",
    "robust_envelope_points",
    "classify_envelope_points",
    "KE_COLUMNS",
    "HobbedAssembly",
    "HobbedPair",
    "hobbed_pair",
    "hobbed_ideal_start",
    "hobbed_continue_to",
    "clear_hobbed_start_cache",
    "hobbed_physical_contact",
    "ke_table",
    "hobbed_phi1_grid",
    "hobbed_tip_crossing",
    "hobbed_elastic_ellipses",
]
