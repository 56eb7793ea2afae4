"""Design files of the ``gearrep`` command: one declaration per surface family, checked before any work.

A design is a mapping (read from YAML by the command; this module reads no files). Its keys are
declared once here with :mod:`gearrep.settings` (value, range, unit, reason; value ``None`` marks
a required key); :func:`json_schema` generates the schema shipped in ``examples/design.schema.json``
from the same declarations. :func:`check` resolves a mapping against its family's declaration and
then checks the geometry (undercut limit, cutter radius against the face width, relief lengths,
contact inside the flanks under the given misalignment). Every refusal is a
:class:`gearrep.settings.SettingError` whose message starts with the key (``design.<key>``), the
value and the allowed range.

Lengths are in mm, angles in degrees in the file (radians inside the library). The ``analysis``
block holds the numerical settings of the analyses (hashed apart from the design in provenance).
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from .. import settings as _s
from ..settings import SettingError

__all__ = [
    "FAMILIES",
    "DECLARATIONS",
    "Design",
    "check",
    "resolve",
    "json_schema",
    "canonical_hash",
    "split_settings",
    "set_dotted",
]

FAMILIES = ("involute", "novikov", "catt", "hobbed_curvilinear")

_MISALIGNMENT = _s.group(
    "assembly errors of the gear (member 2), pivoting about the mid-face point of its axis",
    d_gamma_in_deg=_s.number(0.0, "deg", "rotation in the plane of the axes (axes intersect)", ge=-5, le=5),
    d_gamma_out_deg=_s.number(0.0, "deg", "rotation about the centre line (axes cross)", ge=-5, le=5),
    d_E_mm=_s.number(0.0, "mm", "centre-distance change", ge=-100, le=100),
    d_H_mm=_s.number(0.0, "mm", "offset perpendicular to the centre line and the axis", ge=-100, le=100),
    d_Z_mm=_s.number(0.0, "mm", "axial displacement of the gear", ge=-100, le=100),
)


def _grid(value, reason, most):
    return _s.array(value, "1", reason, _s.integer(None, "1", "", ge=2, le=most), min_items=2, max_items=2)


_ANALYSIS = _s.group(
    "numerical settings of the analyses (hashed as the settings in every provenance sidecar)",
    n_points=_s.integer(41, "1", "contact positions on the path and on the meshing cycle", ge=5, le=2001),
    elastic_approach_mm=_s.number(
        0.00632, "mm", "elastic approach of the contact ellipses (thesis/NASA use 6.32e-3 mm)", gt=0, le=1
    ),
    tol=_s.number(
        1e-10,
        "mm",
        "Newton residual of every contact solve, the meshing cycle's included: far below surface finish and the"
        " elastic approach; on the README pair TE moves by 3e-9 relative between 1e-10 and 1e-12",
        ge=1e-14,
        le=1e-4,
    ),
    maxiter=_s.integer(50, "1", "Newton iterations per contact solve", ge=1, le=1000),
    curvature_grid=_grid([9, 7], "grid (profile x face) of the curvature table", 201),
    flank_grid=_grid([25, 25], "grid (profile x face) of the flank point clouds and STL", 501),
)


def _head(family: str, module_reason: str) -> dict:
    """The keys every family starts with: family, name, module_mm, face_width_mm."""
    return dict(
        family=_s.choice(family, (family,), "surface family of both members"),
        name=_s.text("unnamed design", "a name for the reports"),
        module_mm=_s.number(None, "mm", module_reason, gt=0, le=100),
        face_width_mm=_s.number(None, "mm", "face width of both members", gt=0, le=5000),
    )


_TAIL = dict(misalignment=_MISALIGNMENT, analysis=_ANALYSIS)


_CROWNING = _s.group(
    "longitudinal crowning of the member (material removed toward the face edges)",
    kind=_s.choice("none", ("none", "parabolic", "circular", "logarithmic"), "crowning form (thesis eq 10-12)"),
    crown_mm=_s.number(0.0, "mm", "material removed at the face edges", ge=0, le=10),
    log_shape=_s.number(0.9, "1", "logarithmic crowning shape a2 (a1 follows from crown_mm)", ge=0.01, lt=1),
)

_RELIEF = _s.group(
    "profile relief (parabolic, thesis eq 13)",
    amount_mm=_s.number(0.0, "mm", "material removed at the tip (tip relief) or form circle (root relief)", ge=0, le=5),
    length_mm=_s.number(0.5, "mm", "radial length of the relief", gt=0, le=100),
)


def _involute_member(reason):
    return _s.group(
        reason,
        teeth=_s.integer(None, "1", "number of teeth", ge=3, le=10000),
        profile_shift=_s.number(0.0, "1", "profile-shift coefficient x", ge=-1.5, le=1.5),
        crowning=_CROWNING,
        tip_relief=_RELIEF,
        root_relief=_RELIEF,
    )


INVOLUTE = _s.declare(
    **_head("involute", "normal module"),
    pressure_angle_deg=_s.number(20.0, "deg", "normal pressure angle", ge=10, le=35),
    helix_angle_deg=_s.number(0.0, "deg", "helix angle at the pitch cylinder (0: spur)", ge=0, le=45),
    hand=_s.choice("right", ("right", "left"), "helix hand of the pinion (the gear has the other hand)"),
    addendum=_s.number(1.0, "1", "addendum coefficient h_a", ge=0.5, le=1.5),
    dedendum=_s.number(1.25, "1", "dedendum coefficient h_f", ge=0.8, le=2),
    pinion=_involute_member("the driving member (member 1)"),
    gear=_involute_member("the driven member (member 2)"),
    **_TAIL,
)

NOVIKOV = _s.declare(
    **_head("novikov", "normal module (1 / normal diametral pitch)"),
    pressure_angle_deg=_s.number(25.0, "deg", "normal pressure angle at the rack contact point Q", ge=10, le=35),
    helix_angle_deg=_s.number(None, "deg", "helix angle (Novikov-Wildhaber gears are helical)", ge=5, le=45),
    hand=_s.choice("left", ("left", "right"), "helix hand of the pinion"),
    pinion=_s.group(
        "the driving member (member 1), generated by the convex-profile rack",
        teeth=_s.integer(None, "1", "number of teeth", ge=5, le=10000),
        rack_radius_modules=_s.number(5.88, "1", "rack profile radius in modules (NASA report: 5.88)", gt=1, le=1000),
    ),
    gear=_s.group(
        "the driven member (member 2), generated by the concave-profile rack",
        teeth=_s.integer(None, "1", "number of teeth", ge=5, le=10000),
        rack_radius_modules=_s.number(6.35, "1", "rack profile radius in modules (NASA report: 6.35)", gt=1, le=1000),
    ),
    **_TAIL,
)

CATT = _s.declare(
    **_head("catt", "module of the middle section"),
    cutter_radius_mm=_s.number(None, "mm", "cutter (tooth-trace arc) radius R_T", gt=0, le=1e5),
    pressure_angle_deg=_s.number(20.0, "deg", "blade pressure angle", ge=10, le=35),
    addendum=_s.number(1.0, "1", "addendum coefficient h*", ge=0.5, le=1.5),
    clearance=_s.number(0.25, "1", "clearance coefficient c*", ge=0, le=0.5),
    flank_pair=_s.choice(
        "B", ("A", "B"), "A: pinion convex on gear concave; B: pinion concave on gear convex (seed 004 assembly)"
    ),
    pinion=_s.group("the driving member (member 1)", teeth=_s.integer(None, "1", "number of teeth", ge=5, le=10000)),
    gear=_s.group("the driven member (member 2)", teeth=_s.integer(None, "1", "number of teeth", ge=5, le=10000)),
    **_TAIL,
)

_HOB_MISALIGNMENT = _s.group(
    "assembly errors of seed 000 sec 5.2 (eq 5.1-5.3): the pinion axis turned about the mid-face point of its "
    "axis, the gear moved; the library (tseng_tca Assembly) takes at most 0.01 rad and 2 mm",
    dgamma_h_deg=_s.number(
        0.0,
        "deg",
        "horizontal misalignment: pinion axis turned about the centre-distance line (axes cross)",
        ge=-0.5,
        le=0.5,
    ),
    dgamma_v_deg=_s.number(
        0.0,
        "deg",
        "vertical misalignment: pinion axis turned in the plane of the axes (axes intersect)",
        ge=-0.5,
        le=0.5,
    ),
    dC_mm=_s.number(0.0, "mm", "centre-distance change", ge=-2, le=2),
    dZ_mm=_s.number(0.0, "mm", "axial displacement of the gear", ge=-2, le=2),
)

_HOB_ANALYSIS = _s.group(
    "numerical settings of the analyses (hashed as the settings in every provenance sidecar)",
    n_points=_ANALYSIS.fields["n_points"],
    elastic_approach_mm=_ANALYSIS.fields["elastic_approach_mm"],
    tol=_s.number(
        1e-11,
        "mm",
        "residual of the 9-equation TCA system of every contact solve (seed 000 replication: 1e-11)",
        ge=1e-13,
        le=1e-6,
    ),
    continuation_steps=_s.integer(
        4,
        "1",
        "warm-started solves from the ideal pair (R_cg >= R_cp + 3 mm, aligned) to the design "
        "(seed 000 replication: 4; one step fails for its almost-line-contact Example 5.2)",
        ge=1,
        le=100,
    ),
    ke_table=_s.group(
        "pinion angles of the kinematic-error table (KE zero at phi1 = 0; seed 000 Tables 5.2-5.9: -10 to 10 deg "
        "in 2-deg steps); the grid must hit 0",
        start_deg=_s.number(-10.0, "deg", "first pinion angle", ge=-60, le=0),
        end_deg=_s.number(10.0, "deg", "last pinion angle", ge=0, le=60),
        step_deg=_s.number(2.0, "deg", "step of the pinion angle", gt=0, le=60),
    ),
    curvature_grid=_ANALYSIS.fields["curvature_grid"],
    flank_grid=_ANALYSIS.fields["flank_grid"],
)


def _hobbed_member(reason):
    return _s.group(
        reason,
        teeth=_s.integer(None, "1", "number of teeth", ge=4, le=10000),
        cutter_radius_mm=_s.number(
            None, "mm", "nominal radius R_c of the circular-arc tooth trace (the hob's swivel radius)", ge=20, le=1e6
        ),
    )


HOBBED_CURVILINEAR = _s.declare(
    family=_s.choice("hobbed_curvilinear", ("hobbed_curvilinear",), "surface family of both members"),
    name=_s.text("unnamed design", "a name for the reports"),
    module_mm=_s.number(None, "mm", "normal module of the ZA hob (and of both members)", gt=0, le=100),
    face_width_mm=_s.number(None, "mm", "face width of both members", gt=0, le=1000),
    pressure_angle_deg=_s.number(20.0, "deg", "normal pressure angle of the hob", ge=10, le=35),
    hob_pitch_radius_mm=_s.number(
        None, "mm", "pitch radius r_h of the single-start ZA hob (seed 000 Table 5.1: 30 mm)", gt=0, le=1000
    ),
    hob_profile=_s.choice(
        "axial",
        ("axial", "printed"),
        "axial: straight thread profile in the axial section (a true ZA hob; reproduces seed 000 Tables 4.3/4.4); "
        "printed: seed 000 eq 4.40 as printed (profile in the normal section)",
    ),
    pinion=_hobbed_member("the driving member (member 1): convex flank, tooth trace arc centred on the far side"),
    gear=_hobbed_member("the driven member (member 2): concave flank"),
    misalignment=_HOB_MISALIGNMENT,
    analysis=_HOB_ANALYSIS,
)

DECLARATIONS = {"involute": INVOLUTE, "novikov": NOVIKOV, "catt": CATT, "hobbed_curvilinear": HOBBED_CURVILINEAR}


def _required(decl, prefix="") -> list[str]:
    out = []
    for k, s in decl.items():
        if s.kind == "group":
            out += _required(s.fields, f"{prefix}{k}.")
        elif s.value is None:
            out.append(f"{prefix}{k}")
    return out


def _mark_required(schema: dict, decl) -> dict:
    req = [k for k, s in decl.items() if s.kind != "group" and s.value is None]
    req += [k for k, s in decl.items() if s.kind == "group" and _required(s.fields)]
    if req:
        schema["required"] = req
    for k, s in decl.items():
        if s.kind == "group":
            _mark_required(schema["properties"][k], s.fields)
    return schema


def json_schema() -> dict:
    """JSON schema of a design file: one alternative per family (keys, ranges, units, required keys)."""
    alts = []
    for fam, decl in DECLARATIONS.items():
        sch = _mark_required(_s.json_schema(decl, f"a {fam} gear pair"), decl)
        sch["required"] = ["family"] + sch.get("required", [])
        alts.append(sch)
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "gearrep design file",
        "description": "generated from gearrep.cli.design.DECLARATIONS (python -m gearrep schema)",
        "oneOf": alts,
    }


def resolve(raw) -> dict:
    """The design mapping resolved against its family's declaration (types, ranges, unknown and
    missing keys); no geometry checks. Raises SettingError naming the key."""
    if not isinstance(raw, Mapping):
        raise SettingError(f"design: got {_short(raw)}; allowed: a mapping with keys family, ... (see the schema)")
    fam = raw.get("family")
    if fam is None:
        raise SettingError(f"design.family: missing; allowed: one of {list(FAMILIES)}")
    if not isinstance(fam, str) or fam not in DECLARATIONS:
        raise SettingError(f"design.family: got {_short(fam)}; allowed: one of {list(FAMILIES)}")
    decl = DECLARATIONS[fam]
    _refuse_unknown(decl, raw, "design")
    out = _s.resolve(decl, raw, where="design")
    for key in _required(decl):
        v = out
        for part in key.split("."):
            v = v[part]
        if v is None:
            s = _lookup(decl, key)
            raise SettingError(f"design.{key}: missing; allowed: {s.allowed()}")
    return out


def _refuse_unknown(decl, raw: Mapping, where: str):
    """An unknown key anywhere in ``raw`` refused with its value, the closest declared key and the
    keys allowed there."""
    for k, v in raw.items():
        if k not in decl:
            name = k if isinstance(k, str) and re.fullmatch(r"[A-Za-z_]\w*", k) else repr(k)
            raise SettingError(
                f"{where}.{name}: got {_short(v)} under an unknown key{_s.closest(k, decl)}; allowed keys here: "
                f"{sorted(decl)}"
            )
        if decl[k].kind == "group" and isinstance(v, Mapping):
            _refuse_unknown(decl[k].fields, v, f"{where}.{k}")


def _short(v) -> str:
    r = repr(v)
    return r if len(r) <= 80 else r[:77] + "..."


def _lookup(decl, dotted):
    parts = dotted.split(".")
    s = decl[parts[0]]
    for p in parts[1:]:
        s = s.fields[p]
    return s


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


def split_settings(values: dict) -> tuple[dict, dict]:
    """(design without ``analysis``, the ``analysis`` settings)."""
    d = {k: v for k, v in values.items() if k != "analysis"}
    return d, dict(values.get("analysis", {}))


def canonical_hash(obj) -> str:
    """sha256 of the canonical JSON of ``obj`` (sorted keys; floats by repr)."""
    return hashlib.sha256(json.dumps(obj, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


# ----------------------------------------------------------------------------------------------
# the pair built from a resolved design
# ----------------------------------------------------------------------------------------------
@dataclass
class Design:
    """A checked design: ``values`` (resolved mapping), the library ``pair`` (gearrep.tca.GearPair;
    hobbed_curvilinear: gearrep.hobbed.Pair), the family and its helpers
    (``mesh``: the CATT mesh, or the hobbed pair's PairDesign), and the contact found at phi1 = 0
    (``start``, hobbed_curvilinear)."""

    values: dict
    family: str
    pair: object
    line_contact: bool = False
    mesh: object = None
    #: hobbed_curvilinear: the physical contact at phi1 = 0 (tca_envelope.ContactPath), set by check
    start: object = None

    @property
    def analysis(self) -> dict:
        return self.values["analysis"]

    @property
    def name(self) -> str:
        return self.values["name"]


def _misalignment(v):
    from ..tca import Misalignment

    m = v["misalignment"]
    return Misalignment(
        d_gamma_in=math.radians(m["d_gamma_in_deg"]),
        d_gamma_out=math.radians(m["d_gamma_out_deg"]),
        d_E=m["d_E_mm"],
        d_H=m["d_H_mm"],
        d_Z=m["d_Z_mm"],
    )


def _crowning(c, face_width):
    from ..surfaces.involute import CircularCrowning, LogarithmicCrowning, ParabolicCrowning

    if c["kind"] == "none" or c["crown_mm"] == 0.0:
        return None
    h = 0.5 * face_width
    if c["kind"] == "parabolic":
        return ParabolicCrowning(c["crown_mm"] / h**2)
    if c["kind"] == "circular":
        return CircularCrowning(c["crown_mm"], face_width)
    return LogarithmicCrowning(c["crown_mm"] / math.log(1.0 / (1.0 - c["log_shape"])), c["log_shape"], h)


def _check_pointed(v, member):
    """Refuse a profile shift that leaves ``member``'s tooth pointed below its tip circle (the tooth's
    half angle at the tip, s/(2 r_p) + inv(alpha_t) - inv(alpha_a), falls to zero as x grows: the
    tip circle grows by x m while the flanks lean in), naming the largest shift allowed."""
    from scipy.optimize import brentq

    from ..surfaces.involute import involute_polar_angle

    m, z = v["module_mm"], v[member]["teeth"]
    a_n, beta = math.radians(v["pressure_angle_deg"]), math.radians(v["helix_angle_deg"])
    m_t = m / math.cos(beta)
    a_t = math.atan(math.tan(a_n) / math.cos(beta))
    r_p = 0.5 * z * m_t
    r_b = r_p * math.cos(a_t)

    def half_angle(x):
        s = m_t * (0.5 * math.pi + 2.0 * x * math.tan(a_n))
        r_a = r_p + (v["addendum"] + x) * m
        return s / (2 * r_p) + float(involute_polar_angle(r_p, r_b)) - float(involute_polar_angle(max(r_a, r_b), r_b))

    x = v[member]["profile_shift"]
    if half_angle(x) > 0:
        return
    limit = brentq(half_angle, -1.5, x) if half_angle(-1.5) > 0 else float("nan")
    raise SettingError(
        f"design.{member}.profile_shift: got {x!r}; allowed: below {limit:.4g} for {z} teeth (a larger shift leaves "
        "the tooth pointed below its tip circle)"
    )


def _check_removal(v, member, g, u_lo, u_hi):
    """Refuse a crown or relief that removes more than the tooth holds: the crown alone at the tip
    circle, and at the face edge the crown plus the tip relief at the tip circle and plus the root
    relief at the start of the involute; where the removal reaches :meth:`InvoluteGearData.max_flank_removal` the flank
    crosses the tooth's centre plane (no material left)."""
    mv = v[member]
    crown = mv["crowning"]["crown_mm"] if mv["crowning"]["kind"] != "none" else 0.0
    for key, amount, r, where in (
        ("crowning.crown_mm", crown, u_hi, "the tip circle"),
        ("tip_relief.amount_mm", mv["tip_relief"]["amount_mm"], u_hi, "the tip circle"),
        ("root_relief.amount_mm", mv["root_relief"]["amount_mm"], u_lo, "the start of the involute"),
    ):
        most = g.max_flank_removal(r) - (crown if key != "crowning.crown_mm" else 0.0)
        if amount > 0 and not amount < most:
            raise SettingError(
                f"design.{member}.{key}: got {amount!r}; allowed: below {most:.4g} mm (more removes the whole "
                f"tooth thickness at {where}, r = {r:.4g} mm, at the face edge: the flank would cross the tooth's "
                "centre plane)"
            )


def _involute(v) -> Design:
    from ..surfaces.involute import InvoluteFlank, InvoluteGearData, RootRelief, TipRelief, undercut_limit
    from ..tca import GearPair

    gears, flanks = [], []
    for i, member in enumerate(("pinion", "gear")):
        mv = v[member]
        _check_pointed(v, member)
        g = InvoluteGearData(
            mv["teeth"],
            v["module_mm"],
            math.radians(v["pressure_angle_deg"]),
            v["face_width_mm"],
            math.radians(v["helix_angle_deg"]),
            x=mv["profile_shift"],
            h_a=v["addendum"],
            h_f=v["dedendum"],
        )
        lim = undercut_limit(g)
        if mv["teeth"] < lim:
            raise SettingError(
                f"design.{member}.teeth: got {mv['teeth']}; allowed: an integer >= {math.ceil(lim - 1e-9)} "
                f"(undercut limit {lim:.4g} teeth for x = {mv['profile_shift']:g}; raise {member}.profile_shift "
                "to lower it)"
            )
        if v["face_width_mm"] > 20 * g.r_p:
            raise SettingError(
                f"design.face_width_mm: got {v['face_width_mm']!r}; allowed: at most 20 pitch radii of the "
                f"{member} ({20 * g.r_p:.6g} mm)"
            )
        c = mv["crowning"]
        if c["kind"] == "circular" and not c["crown_mm"] < 0.5 * v["face_width_mm"]:
            raise SettingError(
                f"design.{member}.crowning.crown_mm: got {c['crown_mm']!r}; allowed: below half the face width "
                f"({0.5 * v['face_width_mm']:g} mm) for a circular crown"
            )
        if c["kind"] != "none" and c["crown_mm"] == 0.0:
            raise SettingError(
                f"design.{member}.crowning.crown_mm: got 0.0; allowed: > 0 mm for crowning kind {c['kind']!r} "
                "(or kind: none)"
            )
        u_lo, u_hi = max(g.r_b, g.r_f), g.r_a
        _check_removal(v, member, g, u_lo, u_hi)
        relief = []
        for kind, cls in (("tip_relief", TipRelief), ("root_relief", RootRelief)):
            r = mv[kind]
            if r["amount_mm"] == 0.0:
                continue
            if not r["length_mm"] < u_hi - u_lo:
                raise SettingError(
                    f"design.{member}.{kind}.length_mm: got {r['length_mm']!r}; allowed: below the radial height of "
                    f"the involute flank ({u_hi - u_lo:.6g} mm)"
                )
            u0 = u_hi - r["length_mm"] if kind == "tip_relief" else u_lo + r["length_mm"]
            relief.append(cls(u0, r["length_mm"], r["amount_mm"]))
        gears.append(g)
        hand = 1 if v["hand"] == "right" else -1
        flanks.append(
            InvoluteFlank(
                g, 1, hand if i == 0 else -hand, crowning=_crowning(c, v["face_width_mm"]), relief=tuple(relief)
            )
        )
    a = gears[0].r_p + gears[1].r_p
    pair = GearPair(flanks[0], flanks[1], gears[0].n_teeth, gears[1].n_teeth, a, misalignment=_misalignment(v))
    return Design(v, "involute", pair)


def _novikov(v) -> Design:
    from ..surfaces.novikov import member_flank
    from ..tca import GearPair

    if not v["gear"]["rack_radius_modules"] > v["pinion"]["rack_radius_modules"]:
        raise SettingError(
            f"design.gear.rack_radius_modules: got {v['gear']['rack_radius_modules']!r}; allowed: a number above "
            f"pinion.rack_radius_modules = {v['pinion']['rack_radius_modules']!r} (the concave gear profile must be "
            "flatter than the convex pinion profile for point contact)"
        )
    m = v["module_mm"]
    an = math.radians(v["pressure_angle_deg"])
    beta = math.radians(v["helix_angle_deg"]) * (-1.0 if v["hand"] == "left" else 1.0)
    n1, n2 = v["pinion"]["teeth"], v["gear"]["teeth"]
    flanks = []
    for member, N in (("pinion", n1), ("gear", n2)):
        rho = v[member]["rack_radius_modules"] * m
        f = member_flank(N, 1.0 / m, 1.0 / (2.0 * rho), an, math.cos(an) * m, beta, member)  # lengths in mm
        half = 0.5 * v["face_width_mm"] / math.cos(beta)
        f.lower = np.array([-1.2 * m, -1.5 * half])
        f.upper = np.array([1.2 * m, 1.5 * half])
        flanks.append(f)
    a = flanks[0].r_p + flanks[1].r_p
    pair = GearPair(flanks[0], flanks[1], n1, n2, a, misalignment=_misalignment(v), phase2=0.0)
    return Design(v, "novikov", pair)


def _middle_section_undercut(member, z, module, alpha_deg, face_width, addendum, how):
    """Refuse ``member``'s tooth number below the undercut limit of its middle section, an involute
    cut by a straight rack of ``addendum`` modules (CATT and hobbed curvilinear gears)."""
    from ..surfaces.involute import InvoluteGearData, undercut_limit

    lim = undercut_limit(InvoluteGearData(max(z, 3), module, math.radians(alpha_deg), face_width, h_a=addendum))
    if z < lim:
        raise SettingError(
            f"design.{member}.teeth: got {z}; allowed: an integer >= {math.ceil(lim - 1e-9)} "
            f"(undercut limit {lim:.4g} teeth of the middle section{how})"
        )


def _catt(v) -> Design:
    from ..surfaces.catt import assemble

    m, B, R_T = v["module_mm"], v["face_width_mm"], v["cutter_radius_mm"]
    least = 0.5 * B + math.pi * m
    if not R_T > least:
        raise SettingError(
            f"design.cutter_radius_mm: got {R_T!r}; allowed: above half the face width plus pi modules "
            f"({least:.6g} mm), so that the arc spans the face"
        )
    for member in ("pinion", "gear"):
        z = v[member]["teeth"]
        # the middle section is an involute cut by a straight rack of addendum h* (seed 004 eq 5)
        _middle_section_undercut(member, z, m, v["pressure_angle_deg"], B, v["addendum"], "")
    design = {"z1": v["pinion"]["teeth"], "z2": v["gear"]["teeth"], "module": m, "R_T": R_T, "face_width": B}
    prm = {"pressure_angle_deg": v["pressure_angle_deg"], "addendum": v["addendum"], "clearance": v["clearance"]}
    mesh = assemble(design, v["flank_pair"], prm)
    mesh.gear_pair = mesh.gear_pair.with_misalignment(_misalignment(v))
    return Design(v, "catt", mesh.gear_pair, mesh=mesh)


def _hobbed_curvilinear(v) -> Design:
    from ..surfaces.hob import PairDesign, za_hob
    from ..tca import hobbed_pair as make_pair

    m, B, a_deg = v["module_mm"], v["face_width_mm"], v["pressure_angle_deg"]
    r_h = v["hob_pitch_radius_mm"]
    least = max(0.5 * m, 0.25 * math.pi * m / math.tan(math.radians(a_deg)))
    if not r_h > least:
        raise SettingError(
            f"design.hob_pitch_radius_mm: got {r_h!r}; allowed: above {least:.6g} mm for module {m:g} mm and "
            f"{a_deg:g} deg (the radius of the thread-groove apex, r_h - (pi m / 4) / tan(alpha_n), must be positive)"
        )
    for member in ("pinion", "gear"):
        z = v[member]["teeth"]
        # the middle section (psi = 0) is cut by the hob's straight axial profile, a rack of addendum 1 module
        _middle_section_undercut(member, z, m, a_deg, B, 1.0, ", cut by the hob's straight axial profile")
        R = v[member]["cutter_radius_mm"]
        if not R > 0.5 * B:
            raise SettingError(
                f"design.{member}.cutter_radius_mm: got {R!r}; allowed: above half the face width ({0.5 * B:g} mm), "
                "so that the arc tooth trace spans the face"
            )
    R_p, R_g = v["pinion"]["cutter_radius_mm"], v["gear"]["cutter_radius_mm"]
    if not R_g >= R_p:
        raise SettingError(
            f"design.gear.cutter_radius_mm: got {R_g!r}; allowed: >= pinion.cutter_radius_mm = {R_p!r} (the concave "
            "gear trace must be as flat as the convex pinion trace or flatter, else the flanks meet at the face edges)"
        )
    from .hobbed import check_ke_grid

    check_ke_grid(v)
    hob = za_hob(m, a_deg, r_h, v["hob_profile"])
    gears = PairDesign(v["pinion"]["teeth"], v["gear"]["teeth"], float(B), hob)
    pair = make_pair(gears, R_p, R_g, _hob_assembly(v))
    return Design(v, "hobbed_curvilinear", pair, mesh=gears)


def _hob_assembly(v):
    from ..tca import HobbedAssembly as Assembly

    m = v["misalignment"]
    return Assembly(math.radians(m["dgamma_h_deg"]), math.radians(m["dgamma_v_deg"]), m["dC_mm"], m["dZ_mm"])


_BUILDERS = {"involute": _involute, "novikov": _novikov, "catt": _catt, "hobbed_curvilinear": _hobbed_curvilinear}


def build(values: dict) -> Design:
    """The pair of a resolved design (geometry checks included, no contact solve)."""
    try:
        with np.errstate(all="ignore"):
            return _BUILDERS[values["family"]](values)
    except SettingError:
        raise
    except (ValueError, ZeroDivisionError, OverflowError) as e:  # a library refusal the checks above missed
        raise SettingError(f"design: {e}; allowed: a design the {values['family']} family can build") from None


def _largest_with_contact(values: dict, name: str, x: float, steps: int = 6) -> float:
    """Bisection on the magnitude of misalignment ``name`` (same sign as ``x``) between 0 (contact)
    and ``x`` (none): the smallest magnitude found without contact, to 2^-steps of |x| (plain
    Newton solves: an estimate of the limit, which the message calls approximate)."""
    from .analysis import contact_at

    lo, hi = 0.0, abs(x)
    base = build(values)
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        d = Design(values, base.family, None, mesh=base.mesh)
        d.pair = base.pair.with_misalignment(
            _misalignment(set_dotted(values, f"misalignment.{name}", math.copysign(mid, x)))
        )
        if d.mesh is not None:
            d.mesh.gear_pair = d.pair
        c, _ = contact_at(d, np.array([0.0]), quick=True, face=False)
        lo, hi = (mid, hi) if c.converged[0] else (lo, mid)
    return hi


def _involute_mesh(d: Design) -> None:
    """Refuse an involute design whose operating centre distance (the nominal one changed by the
    misalignment d_E and d_H) leaves the range of :func:`gearrep.meshing.centre_distance_limits`:
    below it a tip meets the other member below its involute (tip interference: no engagement
    limit on the flanks), above it the total contact ratio is below 1 (a gap in the meshing)."""
    from ..meshing import centre_distance_limits

    pair, v = d.pair, d.values
    g1, g2 = pair.flank1.gear, pair.flank2.gear
    eps_b = float(g1.face_width * abs(np.sin(g1.helix_angle)) / (np.pi * g1.module))
    lim = centre_distance_limits(
        g1.r_a, g1.r_b, float(pair.lower1[0]), g2.r_a, g2.r_b, float(pair.lower2[0]), g1.base_pitch, eps_b
    )
    a0 = g1.r_p + g2.r_p
    m = v["misalignment"]
    d_e, d_h = m["d_E_mm"], m["d_H_mm"]
    a = math.hypot(a0 + d_e, d_h)
    lo = math.sqrt(max(lim["a_min"] ** 2 - d_h**2, 0.0)) - a0
    hi = math.sqrt(lim["a_max"] ** 2 - d_h**2) - a0 if lim["a_max"] > abs(d_h) else float("nan")
    if lim["a_min"] < a < lim["a_max"]:
        return
    tip = "gear" if lim["a_min_tip2"] >= lim["a_min_tip1"] else "pinion"
    root = "pinion" if tip == "gear" else "gear"
    if a <= lim["a_min"]:
        why = (
            f"tip interference: at a centre distance below {lim['a_min']:.6g} mm the {tip}'s tip meets the {root} "
            f"below the start of its involute (r = {float((pair.lower1 if root == 'pinion' else pair.lower2)[0]):.5g} mm)"
        )
    else:
        ratio = (
            math.sqrt(g1.r_a**2 - g1.r_b**2)
            + math.sqrt(g2.r_a**2 - g2.r_b**2)
            - math.sqrt(a**2 - (g1.r_b + g2.r_b) ** 2)
        ) / g1.base_pitch + eps_b
        why = (
            f"total contact ratio {ratio:.3g} < 1 at a centre distance of {a:.6g} mm: a gap in the "
            f"meshing (the next tooth pair engages after the last one left) above {lim['a_max']:.6g} mm"
        )
    if lo < hi:  # the centre distance is the design's knob (profile shifts leave it at r_p1 + r_p2)
        raise SettingError(
            f"design.misalignment.d_E_mm: got {d_e!r}; allowed: {lo:.4g} < d_E_mm < {hi:.4g} mm for this pair"
            f"{f' with d_H_mm = {d_h!r}' if d_h else ''} ({why})"
        )
    key, got = (f"{tip}.profile_shift", v[tip]["profile_shift"]) if a <= lim["a_min"] else ("addendum", v["addendum"])
    raise SettingError(
        f"design.{key}: got {got!r}; allowed: a value with which the pair meshes at its centre distance {a0:.6g} mm "
        f"({why})"
    )


#: the checks of each family's meshing that need no contact solve (run before the solve at phi1 = 0)
_MESH_CHECKS = {"involute": _involute_mesh}


def check(raw, *, contact: bool = True) -> Design:
    """Resolve and build ``raw``; with ``contact``, also solve the contact at phi1 = 0 (the pitch
    point) and refuse a misalignment that moves it off the flanks. Raises SettingError naming the key."""
    from .analysis import contact_at

    values = resolve(raw)
    d = build(values)
    if contact and d.family == "hobbed_curvilinear":
        from . import hobbed

        hobbed.check_contact(d)
    elif contact:
        if d.family in _MESH_CHECKS:
            _MESH_CHECKS[d.family](d)
        c, line = contact_at(d, np.array([0.0]), face=False)  # Novikov: anywhere along the helix
        d.line_contact = line
        if not c.converged[0]:
            mis = {k: x for k, x in values["misalignment"].items() if x != 0.0}
            if not mis:
                raise SettingError(
                    f"design: no contact inside the flanks at the pitch position of the aligned pair (solve status "
                    f"{c.status_name[0]}); allowed: a pair whose flanks meet there (check teeth, module and profile "
                    "shifts)"
                )
            if len(mis) == 1:
                name, x = next(iter(mis.items()))
                limit = _largest_with_contact(values, name, x)
                raise SettingError(
                    f"design.misalignment.{name}: got {x!r}; allowed: |{name}| below about {limit:.2g} for this pair (larger "
                    f"values move the contact at the pitch position off the flanks: status {c.status_name[0]})"
                )
            raise SettingError(
                f"design.misalignment: got {mis!r}; allowed: a misalignment that keeps the contact at the pitch "
                f"position inside the flanks (solve status there: {c.status_name[0]})"
            )
    return d
