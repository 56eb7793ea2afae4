"""The pairs of the loaded-contact validation: ISO 6336's standard spur gears and the README's
crowned 52/72 pair (thesis sec 6.2, from its published design data).

ISO 6336-1's theoretical stiffness c'_th holds for solid disc gears of the standard basic rack
(alpha = 20 deg, h_a = 1, h_f = 1.25, x = 0): :data:`ISO_DESIGNS` are such gears over a range of
tooth numbers and modules (b = 10 m). The crowned pair is the one :mod:`gearrep.ltca` is
benchmarked on (README): the thesis's spur 52/72 with its printed crown a_1 on gear 1 and the
README example's 0.05 deg out-of-plane error.
"""

from __future__ import annotations

from dataclasses import dataclass

from ...published import param_table
from ...settings import SettingError
from ...surfaces.catt import assemble
from ...surfaces.involute import InvoluteGearData, ParabolicCrowning, mating_flanks, standard_centre_distance
from ...tca import GearPair, Misalignment
from ...units import DEG

__all__ = [
    "ISO_DESIGNS",
    "Design",
    "params_from_published",
    "validate",
    "iso_pair",
    "readme_pair",
    "helical_pair",
    "symmetric_pair",
    "pitch_torque_Nm",
    "catt_pair",
]

#: (z1, z2, module [mm]) of the ISO comparisons: several tooth numbers and modules, b = 10 m
ISO_DESIGNS = ((20, 40, 2.0), (30, 30, 3.0), (52, 72, 1.0), (25, 60, 4.0))
#: the README example's misalignment of the crowned pair (examples/crowned_spur.yaml)
README_MISALIGNMENT_DEG = 0.05


@dataclass(frozen=True)
class Design:
    """The crowned pair's printed data (thesis sec 6.2): tooth numbers, module [mm], pressure
    angle [deg], face width [mm] and crown coefficient a_1 [1/mm] of gear 1; ``catt``: the CATT
    pair of seed 004 sec 4 (keys of :func:`gearrep.surfaces.catt.assemble`, its FE material and
    torque), for the load balance of a localized-contact family."""

    n1: int
    n2: int
    module: float
    pressure_angle_deg: float
    face_width: float
    crown1: float
    catt: dict


def params_from_published(published) -> Design:
    """The crowned 52/72 pair and the CATT sec 4 pair of ``published`` (params_003_spur_52_72.csv,
    params_004_examples.csv; no file access)."""
    d = param_table(published.params, "params_003_spur_52_72.csv", "spur_52_72")
    c = param_table(published.params, "params_004_examples.csv", "sec4_3d_model")
    f = param_table(published.params, "params_004_examples.csv", "sec4_fea")
    catt = dict(
        z1=int(c["z1"]),
        z2=int(c["z2"]),
        module=float(c["module"]),
        R_T=float(c["tooth_line_radius"]),
        face_width=float(c["face_width"]),
        pressure_angle_deg=float(c["pressure_angle"]),
        addendum=float(c["addendum_coefficient"]),
        clearance=float(c["clearance_coefficient"]),
        E_MPa=1000.0 * float(f["young_modulus_GPa"]),
        poisson=float(f["poisson_ratio"]),
        torque_Nm=float(f["torque_Nm"]),
    )
    return Design(
        int(d["N1"]),
        int(d["N2"]),
        float(d["module"]),
        float(d["pressure_angle"]),
        float(d["face_width"]),
        float(d["a_1"]),
        catt,
    )


def validate(settings: dict, design: Design) -> None:
    """Cross-field limits: the convergence study's node counts grow by halving the spacing."""
    n = list(settings["convergence_nodes"])
    if any(b != 2 * (a - 1) + 1 for a, b in zip(n, n[1:])):
        raise SettingError(
            f"ltca.convergence_nodes: got {n!r}; allowed: each count 2 (n - 1) + 1 of the one before "
            "(the node spacing halved)"
        )


def iso_pair(z1: int, z2: int, module: float, b=None, misalignment=None, crown1=None) -> GearPair:
    """Standard-rack spur pair (alpha = 20 deg, x = 0) on its reference centre distance; face
    width ``b`` (default 10 m)."""
    b = 10.0 * module if b is None else b
    g1 = InvoluteGearData(z1, module, 20.0 * DEG, b)
    g2 = InvoluteGearData(z2, module, 20.0 * DEG, b)
    f1, f2 = mating_flanks(g1, g2, crowning1=crown1)
    return GearPair(f1, f2, z1, z2, standard_centre_distance(g1, g2), misalignment=misalignment)


def readme_pair(design: Design, misaligned: bool = True, crowned: bool = True) -> GearPair:
    """The README pair: thesis 52/72 with gear 1's printed crown, 0.05 deg out of plane."""
    g1 = InvoluteGearData(design.n1, design.module, design.pressure_angle_deg * DEG, design.face_width)
    g2 = InvoluteGearData(design.n2, design.module, design.pressure_angle_deg * DEG, design.face_width)
    f1, f2 = mating_flanks(g1, g2, crowning1=ParabolicCrowning(design.crown1) if crowned else None)
    mis = Misalignment(d_gamma_out=README_MISALIGNMENT_DEG * DEG) if misaligned else None
    return GearPair(f1, f2, design.n1, design.n2, standard_centre_distance(g1, g2), misalignment=mis)


def helical_pair() -> GearPair:
    """A helical pair for the load balance: the thesis's 40/37 geometry (m_n = 1, 20 deg, beta =
    14 deg, b = 20 mm), unmodified."""
    g1 = InvoluteGearData(40, 1.0, 20.0 * DEG, 20.0, helix_angle=14.0 * DEG)
    g2 = InvoluteGearData(37, 1.0, 20.0 * DEG, 20.0, helix_angle=14.0 * DEG)
    f1, f2 = mating_flanks(g1, g2)
    return GearPair(f1, f2, 40, 37, standard_centre_distance(g1, g2))


def symmetric_pair() -> GearPair:
    """Two equal gears (30/30, m = 2 mm, b = 20 mm): the position phi_p + d mirrors phi_p - d."""
    return iso_pair(30, 30, 2.0, b=20.0)


def catt_pair(design: Design, flank_pair: str = "B") -> GearPair:
    """The CATT pair of seed 004 sec 4 with flank pair ``flank_pair`` ("A": pinion convex, "B":
    pinion concave; :data:`gearrep.surfaces.catt.PAIRS`)."""
    c = design.catt
    keys = ("z1", "z2", "module", "R_T", "face_width")
    params = dict(pressure_angle_deg=c["pressure_angle_deg"], addendum=c["addendum"], clearance=c["clearance"])
    return assemble({k: c[k] for k in keys}, flank_pair, params).gear_pair


def pitch_torque_Nm(pair: GearPair, load_N_per_mm: float) -> float:
    """Pinion torque [N m] of a nominal tangential load per face width F_t / b [N/mm]."""
    g1 = pair.flank1.gear
    return float(load_N_per_mm * g1.face_width * g1.r_p / 1000.0)
