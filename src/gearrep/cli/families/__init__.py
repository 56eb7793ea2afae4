"""The gear families of the ``gearrep`` command, by the ``family`` value of design files.

:data:`REGISTRY` maps each name to its :class:`gearrep.cli.family.Family`; the command reads
keys, checks designs and runs analyses only through it. Each family lives in one module here
(its design keys, checks, pair, contact start, flank grids and figure details); adding a family
is its module and one entry below (or :func:`register` at run time).
"""

from __future__ import annotations

from ...settings import SettingError
from ..family import Family
from ..keys import short
from . import bevel, catt, hobbed_curvilinear, involute, novikov

__all__ = [
    "REGISTRY",
    "register",
    "family_of",
    "loaded_keys",
    "bevel",
    "catt",
    "hobbed_curvilinear",
    "involute",
    "novikov",
]

#: name -> family, in the order of the generated schema
REGISTRY: dict[str, Family] = {
    f.name: f for f in (involute.FAMILY, novikov.FAMILY, catt.FAMILY, hobbed_curvilinear.FAMILY, bevel.FAMILY)
}


def register(family: Family) -> Family:
    """Add ``family`` to :data:`REGISTRY` under its name (a name not yet taken); returns it."""
    if not isinstance(family, Family) or not isinstance(family.name, str) or not family.name:
        raise ValueError(f"family must be a gearrep.cli.family.Family with a name, got {family!r}")
    if family.name in REGISTRY:
        raise ValueError(f"a family named {family.name!r} is registered already")
    if family.keys.get("family") is None or family.keys["family"].choices != (family.name,):
        raise ValueError(f"family {family.name!r}: its keys must declare family: {family.name!r} (keys.head)")
    if "ltca" in family.analyses and not loaded_keys(family):
        raise ValueError(
            f"family {family.name!r}: it lists ltca among its analyses; its keys must declare load, pinion.material, "
            "gear.material and analysis.ltca_nodes (gearrep.cli.keys.LOAD, MATERIAL, LOADED_ANALYSIS)"
        )
    REGISTRY[family.name] = family
    return family


def loaded_keys(family: Family) -> bool:
    """Whether ``family`` declares the keys of the loaded analysis: ``load``, ``pinion.material``,
    ``gear.material`` and ``analysis.ltca_nodes``."""
    k = family.keys
    try:
        return (
            "load" in k
            and all("material" in k[m].fields for m in ("pinion", "gear"))
            and ("ltca_nodes" in k["analysis"].fields)
        )
    except (KeyError, TypeError):
        return False


def family_of(name) -> Family:
    """The registered family ``name``; SettingError naming ``design.family`` otherwise."""
    if name is None:
        raise SettingError(f"design.family: missing; allowed: one of {list(REGISTRY)}")
    if not isinstance(name, str) or name not in REGISTRY:
        raise SettingError(f"design.family: got {short(name)}; allowed: one of {list(REGISTRY)}")
    return REGISTRY[name]
