"""Design data of seed 003 (the thesis's printed gear data and study inputs) and the gear pairs.

:func:`params_from_published` is the one route by which the printed numbers enter: it reads the
``params_003_*.csv`` rows of a loaded :class:`gearrep.published.Published` (no file access).
Choices the thesis does not print are stated where they are made (``READINGS``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...published import param_table
from ...settings import SettingError
from ...surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks
from ...tca import GearPair, Misalignment
from ...units import DEG
from .model import profile_crowning

#: our readings where the thesis prints nothing: phi1 of every convergence study (the thesis gives
#: pi/2 in its frame for sec 6.1 only), the hands of the helical pairs, which gears carry a crown,
#: the pressure angle of the spiral bevel pair
READINGS = {
    "phi1_thesis": np.pi / 2,
    "hand1_helical_25_77": -1,
    "hand1_helical_40_37": 1,
    "spur_25_25_crown_on_both": True,  # a_p: "the text does not say whether one or both gears carry it"
    "spur_52_72_crown2": 0.0,  # a_1 on gear 1 only, gear 2 unmodified
    "spiral_bevel_17_17_pressure_angle_deg": 20.0,  # as for every other pair of the thesis
}


@dataclass(frozen=True)
class Design:
    """The thesis's design data: ``pairs`` {name: gear data (angles in degrees)} and the printed
    inputs of the studies (thesis frame, angles as printed)."""

    pairs: dict
    sec61_phi2_guesses_thesis: tuple
    sec61_phi2_window_thesis: tuple
    sec61_misalignment_deg: float
    helical_phi2_window_thesis: tuple
    helical_misalignment_arcmin: float
    spur_te_crowns: tuple
    spur_te_misalignment_mrad: float


def _table(published, example: str) -> dict:
    params = published.params[published.params["seed"] == "003"]
    return param_table(params, f"params_003_{example}.csv", example)


def params_from_published(published) -> Design:
    """The :class:`Design` from the seed-003 params tables of ``published`` (Published)."""
    t = {
        name: _table(published, name)
        for name in ("spur_52_72", "spur_25_25", "helical_25_77", "spur_25_25_m1", "helical_40_37")
    }
    phi1_t = READINGS["phi1_thesis"]

    def gear(d):
        return dict(
            n1=int(d["N1"]),
            n2=int(d["N2"]),
            module=float(d["module"]),
            pressure_angle_deg=float(d["pressure_angle"]),
            face_width=float(d["face_width"]),
        )

    s52, s25, h25, m1, h40 = (
        t[k] for k in ("spur_52_72", "spur_25_25", "helical_25_77", "spur_25_25_m1", "helical_40_37")
    )
    a_p = float(s25["a_p"])
    pairs = {
        "spur_52_72": dict(
            gear(s52), crown1=float(s52["a_1"]), crown2=READINGS["spur_52_72_crown2"], phi1_thesis=phi1_t
        ),
        "spur_25_25": dict(
            gear(s25), crown1=a_p, crown2=a_p if READINGS["spur_25_25_crown_on_both"] else 0.0, phi1_thesis=phi1_t
        ),
        "helical_25_77": dict(
            gear(h25),
            helix_angle_deg=float(h25["helix_angle"]),
            profile_crown1=float(h25["profile_crowning_1"]),
            profile_crown2=float(h25["profile_crowning_2"]),
            hand1=READINGS["hand1_helical_25_77"],
            phi1_thesis=phi1_t,
        ),
        "spur_25_25_m1": gear(m1),
        "helical_40_37": dict(
            gear(h40),
            helix_angle_deg=float(h40["helix_angle"]),
            hand1=READINGS["hand1_helical_40_37"],
            # Table 2 material and load of the stress ratios (sec 4.2, eq 23-24); both members alike
            load_N=float(h40["total_load_N"]),
            young_modulus_MPa=1e3 * float(h40["young_modulus_GPa"]),
            poisson_ratio=float(h40["poisson_ratio"]),
        ),
    }
    pairs.update(bevel_params(published))  # straight_bevel_39_32 and spiral_bevel_17_17 (sec 5.1-5.2)
    mrad_in, mrad_out = float(m1["misalignment_in_plane_mrad"]), float(m1["misalignment_out_of_plane_mrad"])
    if mrad_in != mrad_out:
        raise ValueError(f"spur_25_25_m1: the TE study uses one angle for both planes, got {mrad_in} and {mrad_out}")
    return Design(
        pairs=pairs,
        sec61_phi2_guesses_thesis=tuple(float(s25[f"phi2_guess_{i}"]) for i in range(4)),
        sec61_phi2_window_thesis=(float(s25["phi2_window_lo"]), float(s25["phi2_window_hi"])),
        sec61_misalignment_deg=float(s25["misalignment_in_plane"]),
        helical_phi2_window_thesis=(float(h25["phi2_window_lo"]), float(h25["phi2_window_hi"])),
        helical_misalignment_arcmin=float(h25["misalignment_in_plane"]),
        spur_te_crowns=tuple(float(m1[k]) for k in ("a_1_insufficient", "a_1_edge", "a_1_sufficient")),
        spur_te_misalignment_mrad=mrad_in,
    )


def bevel_params(published) -> dict:
    """Design entries of both bevel pairs from the params tables of ``published`` (angles in degrees)."""
    params = published.params[published.params["seed"] == "003"]
    st = param_table(params, "params_003_straight_bevel_39_32.csv", "straight_bevel_39_32")
    sp = param_table(params, "params_003_spiral_bevel_17_17.csv", "spiral_bevel_17_17")
    out = {
        "straight_bevel_39_32": dict(
            n1=int(st["N1"]),
            n2=int(st["N2"]),
            module=float(st["module"]),
            pressure_angle_deg=float(st["pressure_angle"]),
            face_width=float(st["face_width"]),
            shaft_angle_deg=float(st["shaft_angle"]),
            spiral_angle_deg=0.0,
            young_modulus=float(st["young_modulus_GPa"]) * 1e3,  # N/mm^2
            poisson_ratio=float(st["poisson_ratio"]),
            load=float(st["applied_load_kN"]) * 1e3,  # N
            printed_base_cone_deg=(float(st["base_cone_angle_1"]), float(st["base_cone_angle_2"])),
            printed_outer_cone_deg=(float(st["outer_cone_angle_1"]), float(st["outer_cone_angle_2"])),
            table6=dict(
                d_gamma=float(st["misalignment_shaft_angle"]) * DEG,
                d_E=float(st["misalignment_dE"]),
                d_A=float(st["misalignment_dA"]),
                d_G=float(st["misalignment_dG"]),
            ),
            n_starts=int(st["n_starts"]),
        ),
        "spiral_bevel_17_17": dict(
            n1=int(sp["N1"]),
            n2=int(sp["N2"]),
            module=float(sp["module"]),
            pressure_angle_deg=READINGS["spiral_bevel_17_17_pressure_angle_deg"],
            face_width=float(sp["face_width"]),
            shaft_angle_deg=float(sp["shaft_angle"]),
            spiral_angle_deg=float(sp["spiral_angle"]),
            young_modulus=float(sp["young_modulus_N_per_mm2"]),
            poisson_ratio=float(sp["poisson_ratio"]),
            load=float(sp["load_F_nondim"]),  # non-dimensional F = load / (E m b) (eq 56)
            n_starts=int(sp["n_starts"]),
        ),
    }
    return out


# ----------------------------------------------------------------------------------------------
# gear pairs
# ----------------------------------------------------------------------------------------------
def spur_pair(
    n1, n2, module, pressure_angle, face_width, *, crowning1=None, crowning2=None, misalignment=None
) -> GearPair:
    """Standard spur pair (side -1 flanks, standard centre distance), crowning objects or None."""
    g1 = InvoluteGearData(n1, module, pressure_angle, face_width)
    g2 = InvoluteGearData(n2, module, pressure_angle, face_width)
    f1, f2 = mating_flanks(g1, g2, side=-1, crowning1=crowning1, crowning2=crowning2)
    return GearPair(f1, f2, n1, n2, g1.r_p + g2.r_p, misalignment=misalignment)


def helical_pair(
    n1,
    n2,
    module,
    pressure_angle,
    helix_angle,
    face_width,
    *,
    hand1=1,
    crowning1=None,
    profile_crown1=0.0,
    profile_crown2=0.0,
    misalignment=None,
    helix_form="true",
) -> GearPair:
    """Standard helical pair (normal module and pressure angle, opposite hands; ``helix_form``
    "true" helicoids or "asin", eq 58 as printed)."""
    g1 = InvoluteGearData(n1, module, pressure_angle, face_width, helix_angle)
    g2 = InvoluteGearData(n2, module, pressure_angle, face_width, helix_angle)
    f1, f2 = mating_flanks(
        g1,
        g2,
        side=-1,
        hand1=hand1,
        crowning1=crowning1,
        relief1=profile_crowning(g1, profile_crown1),
        relief2=profile_crowning(g2, profile_crown2),
        helix_form=helix_form,
    )
    return GearPair(f1, f2, n1, n2, g1.r_p + g2.r_p, misalignment=misalignment)


def design_pair(design: Design, name: str, misalignment=None) -> GearPair:
    """The pair of a design entry (crowning as printed)."""
    d = design.pairs[name]
    alpha = d["pressure_angle_deg"] * DEG
    if name == "helical_25_77":
        return helical_pair(
            d["n1"],
            d["n2"],
            d["module"],
            alpha,
            d["helix_angle_deg"] * DEG,
            d["face_width"],
            hand1=d["hand1"],
            profile_crown1=d["profile_crown1"],
            profile_crown2=d["profile_crown2"],
            misalignment=misalignment,
        )
    if name == "helical_40_37":
        return pair_40_37(design, None, misalignment)
    c1 = ParabolicCrowning(d["crown1"]) if d.get("crown1", 0) > 0 else None
    c2 = ParabolicCrowning(d["crown2"]) if d.get("crown2", 0) > 0 else None
    return spur_pair(
        d["n1"], d["n2"], d["module"], alpha, d["face_width"], crowning1=c1, crowning2=c2, misalignment=misalignment
    )


def pair_40_37(design: Design, crowning=None, mis=None) -> GearPair:
    """Helical 40/37 of Tables 2-4 with a lead crown on the pinion."""
    d = design.pairs["helical_40_37"]
    return helical_pair(
        d["n1"],
        d["n2"],
        d["module"],
        d["pressure_angle_deg"] * DEG,
        d["helix_angle_deg"] * DEG,
        d["face_width"],
        hand1=d["hand1"],
        crowning1=crowning,
        misalignment=mis,
    )


def pair_spur_m1(design: Design, crown, mis=None) -> GearPair:
    """Spur 25/25, m = 1 of sec 4.1 with a parabolic crown ``crown`` on gear 1 (or none)."""
    d = design.pairs["spur_25_25_m1"]
    return spur_pair(
        d["n1"],
        d["n2"],
        d["module"],
        d["pressure_angle_deg"] * DEG,
        d["face_width"],
        crowning1=ParabolicCrowning(crown) if crown else None,
        misalignment=mis,
    )


def misalignment(plane: str, angle: float, pair: GearPair | None = None, pivot: str = "axis") -> Misalignment:
    """In-plane (axes intersect: member 2 turned about y_f) or out-of-plane (axes cross: turned
    about the centre line x_f) angular misalignment [rad].

    ``pivot="axis"``: about the mid-face point O2 of member 2's axis (the library's convention);
    ``pivot="pitch_point"``: about the pitch point C = (r_p1, 0, 0) at mid-face, i.e. the same
    rotation plus the translation (A2 - I)(O2 - C) of member 2 (needs ``pair`` for r_p2).
    Out-of-plane both pivots coincide (C lies on the centre line).
    """
    if plane == "none":
        return Misalignment()
    if plane not in ("in", "out"):
        raise ValueError(f"plane must be 'in', 'out' or 'none', got {plane!r}")
    if pivot not in ("axis", "pitch_point"):
        raise ValueError(f"pivot must be 'axis' or 'pitch_point', got {pivot!r}")
    d = dict(d_gamma_in=angle) if plane == "in" else dict(d_gamma_out=angle)
    if pivot == "pitch_point" and plane == "in":
        if pair is None:
            raise ValueError("pivot='pitch_point' needs the pair")
        r_p2 = pair.flank2.gear.r_p
        d.update(d_E=r_p2 * (np.cos(angle) - 1.0), d_Z=-r_p2 * np.sin(angle))
    return Misalignment(**d)


#: Tables 3 (in-plane) and 4 (out-of-plane): crowning amounts as printed, three rows per angle
#: (circular c_c [mm], parabolic c_1 [1/mm], logarithmic a_1 [mm]); inputs of the TE study (they
#: are values_003_T3/T4.csv rows of quantity crown_amount; a test keeps both equal).
TABLE34 = {
    ("in", -0.05): {
        "circular": [2.398, 2.400, 2.565],
        "parabolic": [0.0227, 0.0233, 0.0240],
        "logarithmic": [2.515, 2.600, 2.669],
    },
    ("in", -0.1): {
        "circular": [1.104, 1.150, 1.173],
        "parabolic": [0.0110, 0.0113, 0.0115],
        "logarithmic": [1.201, 1.236, 1.275],
    },
    ("in", -0.2): {
        "circular": [0.507, 0.520, 0.535],
        "parabolic": [0.0051, 0.0052, 0.0053],
        "logarithmic": [0.537, 0.553, 0.572],
    },
    ("out", 0.05): {
        "circular": [0.804, 0.830, 0.853],
        "parabolic": [0.00799, 0.00820, 0.00847],
        "logarithmic": [0.873, 0.900, 0.927],
    },
    ("out", 0.1): {
        "circular": [0.360, 0.370, 0.381],
        "parabolic": [0.00359, 0.00370, 0.00380],
        "logarithmic": [0.368, 0.380, 0.393],
    },
    ("out", 0.2): {
        "circular": [0.143, 0.146, 0.150],
        "parabolic": [0.00143, 0.00146, 0.00150],
        "logarithmic": [0.046, 0.055, 0.081],
    },
}


def validate(settings: dict, design: Design) -> None:
    """Cross-field checks: Tables 3-4 row 1 must be computed (the crowning areas and claims use it)."""
    if 1 not in settings["crowning_rows"]:
        raise SettingError(
            f"temirkhan2023.crowning_rows: got {settings['crowning_rows']!r}; allowed: a subset of [1, 2, 3] containing 1"
        )
