"""Design files of the ``gearrep`` command: resolved against their family's keys and checked
before any work.

A design is a mapping (read from YAML by the command; this module reads no files). Its ``family``
names a registered family (:data:`gearrep.cli.families.REGISTRY`), whose module declares the keys
once with :mod:`gearrep.settings` (value, range, unit, reason; value ``None`` marks a required
key); :func:`json_schema` generates the schema shipped in ``examples/design.schema.json`` from the
same declarations. :func:`check` resolves a mapping against its family's keys, builds the pair
(the family's geometry checks: undercut limits, cutter radii against the face width, relief
lengths, ...) and lets the family check the contact where the analyses start (inside the flanks
under the given misalignment). Every refusal is a :class:`gearrep.settings.SettingError` whose
message starts with the key (``design.<key>``), the value and the allowed range.

Lengths are in mm, angles in degrees in the file (radians inside the library). The ``analysis``
block holds the numerical settings of the analyses (hashed apart from the design in provenance).
"""

from __future__ import annotations

import copy
import hashlib
import json
import re
from collections.abc import Mapping

import numpy as np

from .. import settings as st
from ..settings import SettingError
from .families import REGISTRY, family_of
from .family import Design
from .keys import ANALYSIS_REQUIRED, analysis_only, lookup, lookup_value, required, set_dotted, short

__all__ = [
    "Design",
    "check",
    "build",
    "resolve",
    "json_schema",
    "canonical_hash",
    "split_settings",
    "set_dotted",
    "require_analysis",
]


def _mark_required(schema: dict, decl, prefix: str = "") -> dict:
    """``schema`` with the keys of ``decl`` a design must give marked required, and the unit and
    reason of the keys without a default described (as a default's are)."""
    req = [
        k for k, s in decl.items() if s.kind != "group" and s.value is None and f"{prefix}{k}" not in analysis_only()
    ]
    req += [k for k, s in decl.items() if s.kind == "group" and required(s.fields, f"{prefix}{k}.")]
    if req:
        schema["required"] = req
    for k, s in decl.items():
        if s.kind == "group":
            _mark_required(schema["properties"][k], s.fields, f"{prefix}{k}.")
        elif s.value is None:
            unit = f" [{s.unit}]" if s.unit and s.unit != "1" else ""
            schema["properties"][k]["description"] = f"{s.reason}{unit}"
    return schema


def json_schema() -> dict:
    """JSON schema of a design file: one alternative per registered family (keys, ranges, units,
    required keys)."""
    alts = []
    for name, family in REGISTRY.items():
        sch = _mark_required(st.json_schema(family.keys, f"a {name} gear pair"), family.keys)
        sch["required"] = ["family"] + sch.get("required", [])
        alts.append(sch)
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "gearrep design file",
        "description": "generated from the design keys of gearrep.cli.families.REGISTRY (python -m gearrep schema)",
        "oneOf": alts,
    }


def resolve(raw) -> dict:
    """The design mapping resolved against its family's keys (types, ranges, unknown and missing
    keys); no geometry checks. Raises SettingError naming the key."""
    if not isinstance(raw, Mapping):
        raise SettingError(f"design: got {short(raw)}; allowed: a mapping with keys family, ... (see the schema)")
    decl = family_of(raw.get("family")).keys
    _refuse_unknown(decl, raw, "design")
    out = st.resolve(decl, _without_unset(raw), where="design")
    for key in required(decl):
        if lookup_value(out, key) is None:
            raise SettingError(f"design.{key}: missing; allowed: {lookup(decl, key).allowed()}")
    return out


def _without_unset(raw: Mapping) -> Mapping:
    """``raw`` without the keys only one analysis requires where they are None (not given: a
    resolved design holds them so, and resolving it again gives it back)."""
    out = raw
    for key in analysis_only():
        *parents, last = key.split(".")
        node = raw
        for part in parents:
            node = node.get(part) if isinstance(node, Mapping) else None
        if isinstance(node, Mapping) and last in node and node[last] is None:
            out = copy.deepcopy(out) if out is raw else out
            target = out
            for part in parents:
                target = target[part]
            del target[last]
    return out


def _refuse_unknown(decl, raw: Mapping, where: str):
    """An unknown key anywhere in ``raw`` refused with its value, the closest declared key and the
    keys allowed there."""
    for k, v in raw.items():
        if k not in decl:
            name = k if isinstance(k, str) and re.fullmatch(r"[A-Za-z_]\w*", k) else repr(k)
            raise SettingError(
                f"{where}.{name}: got {short(v)} under an unknown key{st.closest(k, decl)}; allowed keys here: "
                f"{sorted(decl)}"
            )
        if decl[k].kind == "group" and isinstance(v, Mapping):
            _refuse_unknown(decl[k].fields, v, f"{where}.{k}")


def split_settings(values: dict) -> tuple[dict, dict]:
    """(design without ``analysis``, the ``analysis`` settings)."""
    d = {k: v for k, v in values.items() if k != "analysis"}
    return d, dict(values.get("analysis", {}))


def canonical_hash(obj) -> str:
    """sha256 of the canonical JSON of ``obj`` (sorted keys; floats by repr)."""
    return hashlib.sha256(json.dumps(obj, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def build(values: dict) -> Design:
    """The pair of a resolved design (its family's geometry checks included, no contact solve)."""
    family = family_of(values["family"])
    try:
        with np.errstate(all="ignore"):
            return family.build(values)
    except SettingError:
        raise
    except (ValueError, ZeroDivisionError, OverflowError) as e:  # a library refusal the checks above missed
        raise SettingError(f"design: {e}; allowed: a design the {values['family']} family can build") from None


def check(raw, *, contact: bool = True) -> Design:
    """Resolve and build ``raw``; with ``contact``, also let its family check the contact where the
    analyses start (:meth:`gearrep.cli.family.Family.check_contact`: at phi1 = 0, inside the flanks
    under the misalignment). Raises SettingError naming the key."""
    design = build(resolve(raw))
    if contact:
        design.family.check_contact(design)
    return design


def require_analysis(design: Design, analysis: str) -> None:
    """Refuse (SettingError naming ``design.family``) a design whose family does not support
    ``analysis`` (one of :data:`gearrep.cli.family.ANALYSES`), with the family's reason
    (:meth:`gearrep.cli.family.Family.why_not`), and one that lacks a key only that analysis
    requires (:data:`gearrep.cli.keys.ANALYSIS_REQUIRED`)."""
    if analysis not in design.family.analyses:
        others = [name for name, f in REGISTRY.items() if analysis in f.analyses]
        why = design.family.why_not(design, analysis)
        raise SettingError(
            f"design.family: got {design.family.name!r}; allowed: for {analysis}, a family that supports it: {others}"
            + (f" ({why})" if why else "")
        )
    for key in ANALYSIS_REQUIRED.get(analysis, ()):
        if lookup_value(design.values, key) is None:
            raise SettingError(
                f"design.{key}: missing; allowed: {lookup(design.family.keys, key).allowed()} (gearrep {analysis} needs it)"
            )
