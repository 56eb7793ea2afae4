"""Design keys shared by the families of the ``gearrep`` command, and dotted-key helpers.

Each family declares its own keys in its module (:mod:`gearrep.cli.families`); what several of
them share is declared once here: the head of every design file (:func:`head`), the numerical
settings of the analyses (:data:`ANALYSIS`), the assembly errors of a pair on crossed or parallel
axes (:data:`MISALIGNMENT`, with :func:`misalignment` building the library's
:class:`gearrep.tca.Misalignment`), and the lengthwise crowning and profile relief of a member
(:data:`CROWNING`, :data:`RELIEF`, :func:`crowning`), and the keys of the loaded analysis
(:data:`LOAD`, a member's :data:`MATERIAL`, :data:`LOADED_ANALYSIS`, with :func:`materials`
building the library's :class:`gearrep.ltca.Material` pair). Lengths are in mm and angles in
degrees in the file; the library takes radians.
"""

from __future__ import annotations

import copy
import math

from .. import settings as st
from ..ltca import Material
from ..surfaces.involute import CircularCrowning, LogarithmicCrowning, ParabolicCrowning
from ..tca import Misalignment

__all__ = [
    "head",
    "grid",
    "ANALYSIS",
    "MISALIGNMENT",
    "CROWNING",
    "RELIEF",
    "relief",
    "LOAD",
    "MATERIAL",
    "LOADED_ANALYSIS",
    "ANALYSIS_REQUIRED",
    "misalignment",
    "materials",
    "crowning",
    "lookup",
    "lookup_value",
    "required",
    "set_dotted",
    "short",
]

MISALIGNMENT = st.group(
    "assembly errors of the gear (member 2), pivoting about the mid-face point of its axis",
    d_gamma_in_deg=st.number(0.0, "deg", "rotation in the plane of the axes (axes intersect)", ge=-5, le=5),
    d_gamma_out_deg=st.number(0.0, "deg", "rotation about the centre line (axes cross)", ge=-5, le=5),
    d_E_mm=st.number(0.0, "mm", "centre-distance change", ge=-100, le=100),
    d_H_mm=st.number(0.0, "mm", "offset perpendicular to the centre line and the axis", ge=-100, le=100),
    d_Z_mm=st.number(0.0, "mm", "axial displacement of the gear", ge=-100, le=100),
)


def grid(value, reason, most):
    """A (profile, face) grid size: two integers in [2, ``most``]."""
    return st.array(value, "1", reason, st.integer(None, "1", "", ge=2, le=most), min_items=2, max_items=2)


ANALYSIS = st.group(
    "numerical settings of the analyses (hashed as the settings in every provenance sidecar)",
    n_points=st.integer(41, "1", "contact positions on the path and on the meshing cycle", ge=5, le=2001),
    elastic_approach_mm=st.number(
        0.00632, "mm", "elastic approach of the contact ellipses (thesis/NASA use 6.32e-3 mm)", gt=0, le=1
    ),
    tol=st.number(
        1e-10,
        "mm",
        "Newton residual of every contact solve, the meshing cycle's included: far below surface finish and the"
        " elastic approach; on the README pair TE moves by 3e-9 relative between 1e-10 and 1e-12",
        ge=1e-14,
        le=1e-4,
    ),
    maxiter=st.integer(50, "1", "Newton iterations per contact solve", ge=1, le=1000),
    curvature_grid=grid([9, 7], "grid (profile x face) of the curvature table", 201),
    flank_grid=grid([25, 25], "grid (profile x face) of the flank point clouds and STL", 501),
)

#: :data:`ANALYSIS` with the settings of the loaded analysis (the families that support it)
LOADED_ANALYSIS = st.group(
    ANALYSIS.reason,
    **ANALYSIS.fields,
    ltca_nodes=st.integer(
        21,
        "1",
        "nodes along the face per tooth pair in the loaded analysis (gearrep ltca; 0.65 % from 161 nodes on the "
        "README pair, docs/ltca.md)",
        ge=5,
        le=161,
    ),
)

#: the load of the loaded analysis (``gearrep ltca``); its torque has no default: the analysis that
#: needs it requires it (:data:`ANALYSIS_REQUIRED`), the other analyses ignore the block
LOAD = st.group(
    "the load of the loaded tooth contact analysis (gearrep ltca)",
    torque_Nm=st.number(
        None,
        "N m",
        "torque on the driving member (required by gearrep ltca); up to 1e7 N m, the largest mill and marine drives",
        gt=0,
        le=1e7,
    ),
    driving=st.choice("pinion", ("pinion", "gear"), "the member the torque drives (the other one is driven)"),
)

#: a member's material in the loaded analysis (isotropic, linear elastic)
MATERIAL = st.group(
    "elastic material of the member in the loaded analysis (default steel, ISO 6336-2's reference for Z_E)",
    E_MPa=st.number(
        206000.0, "MPa", "Young's modulus: from soft polymers (0.1 GPa) to diamond (1200 GPa)", ge=100, le=1.2e6
    ),
    poisson=st.number(
        0.3, "1", "Poisson ratio of an isotropic engineering material (0.5: incompressible)", ge=0, le=0.5
    ),
)

#: dotted keys without a default that only one analysis needs (the others run without them):
#: required by that analysis (:func:`gearrep.cli.design.require_analysis`), not by every design
ANALYSIS_REQUIRED = {"ltca": ("load.torque_Nm",)}

CROWNING = st.group(
    "longitudinal crowning of the member (material removed toward the face edges)",
    kind=st.choice("none", ("none", "parabolic", "circular", "logarithmic"), "crowning form (thesis eq 10-12)"),
    crown_mm=st.number(0.0, "mm", "material removed at the face edges", ge=0, le=10),
    log_shape=st.number(0.9, "1", "logarithmic crowning shape a2 (a1 follows from crown_mm)", ge=0.01, lt=1),
)


def relief(reason: str, amount_reason: str, length_reason: str):
    """The keys of a profile relief, ``amount_mm`` and ``length_mm``; each family words where
    they are measured. The length is at least 1 um: shorter lengths drive the relief's curvature
    2 c_m / L^2 towards overflow."""
    return st.group(
        reason,
        amount_mm=st.number(0.0, "mm", amount_reason, ge=0, le=5),
        length_mm=st.number(
            0.5,
            "mm",
            f"{length_reason} (at least 1 um; shorter lengths drive the relief's "
            "curvature 2 c_m / L^2 towards overflow)",
            ge=0.001,
            le=100,
        ),
    )


RELIEF = relief(
    "profile relief (parabolic, thesis eq 13)",
    "material removed at the tip (tip relief) or form circle (root relief)",
    "radial length of the relief",
)


def head(family: str, module_reason: str, face_most: float = 5000) -> dict:
    """The keys every family starts with: family, name, module_mm, face_width_mm."""
    return dict(
        family=st.choice(family, (family,), "surface family of both members"),
        name=st.text("unnamed design", "a name for the reports"),
        module_mm=st.number(None, "mm", module_reason, gt=0, le=100),
        face_width_mm=st.number(None, "mm", "face width of both members", gt=0, le=face_most),
    )


def misalignment(values) -> Misalignment:
    """The library's misalignment of the resolved ``values['misalignment']`` (:data:`MISALIGNMENT`)."""
    m = values["misalignment"]
    return Misalignment(
        d_gamma_in=math.radians(m["d_gamma_in_deg"]),
        d_gamma_out=math.radians(m["d_gamma_out_deg"]),
        d_E=m["d_E_mm"],
        d_H=m["d_H_mm"],
        d_Z=m["d_Z_mm"],
    )


def crowning(c, face_width: float, v0: float = 0.0):
    """The library's crowning of a resolved :data:`CROWNING` block ``c`` on a face ``face_width``
    [mm] wide whose middle is at face coordinate ``v0`` [mm]; None for no crown."""
    if c["kind"] == "none" or c["crown_mm"] == 0.0:
        return None
    h = 0.5 * face_width
    if c["kind"] == "parabolic":
        return ParabolicCrowning(c["crown_mm"] / h**2, v0=v0)
    if c["kind"] == "circular":
        return CircularCrowning(c["crown_mm"], face_width, v0=v0)
    return LogarithmicCrowning(c["crown_mm"] / math.log(1.0 / (1.0 - c["log_shape"])), c["log_shape"], h, v0=v0)


def materials(values) -> tuple:
    """(member 1, member 2) :class:`gearrep.ltca.Material` of the resolved ``pinion.material`` and
    ``gear.material`` (:data:`MATERIAL`)."""
    return tuple(Material(values[m]["material"]["E_MPa"], values[m]["material"]["poisson"]) for m in ("pinion", "gear"))


def lookup(decl, dotted: str):
    """The declared setting of the dotted key ``dotted`` (KeyError, AttributeError or TypeError
    where no key of that name is declared)."""
    parts = dotted.split(".")
    s = decl[parts[0]]
    for p in parts[1:]:
        s = s.fields[p]
    return s


def analysis_only() -> frozenset:
    """The dotted keys that only one analysis requires (:data:`ANALYSIS_REQUIRED`)."""
    return frozenset(k for keys in ANALYSIS_REQUIRED.values() for k in keys)


def lookup_value(values: dict, dotted: str):
    """The value of the dotted key ``dotted`` in the resolved design ``values``."""
    v = values
    for part in dotted.split("."):
        v = v[part]
    return v


def required(decl, prefix: str = "") -> list[str]:
    """The dotted keys of ``decl`` (its keys under ``prefix``) without a default (value None): a
    design must give them; those only one analysis needs (:data:`ANALYSIS_REQUIRED`) are left out."""
    out = []
    for k, s in decl.items():
        if s.kind == "group":
            out += required(s.fields, f"{prefix}{k}.")
        elif s.value is None and f"{prefix}{k}" not in analysis_only():
            out.append(f"{prefix}{k}")
    return out


def set_dotted(d: dict, dotted: str, value) -> dict:
    """A deep copy of ``d`` with the dotted key set (the sweep's grid axes)."""
    out = copy.deepcopy(d)
    node = out
    parts = dotted.split(".")
    for p in parts[:-1]:
        if not isinstance(node.get(p), dict):
            node[p] = {}
        node = node[p]
    node[parts[-1]] = value
    return out


def short(v) -> str:
    """``repr(v)`` cut to 80 characters (a refused value in a one-line message)."""
    r = repr(v)
    return r if len(r) <= 80 else r[:77] + "..."
