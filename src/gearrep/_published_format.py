"""The vocabulary of the published-data files (``data/published/README.md``): their columns, the
seeds, the precision and claim kinds, the papers' names, the error a file that breaks the format
raises and the precision a printed number implies. Public names of :mod:`gearrep.published`; this
module is their home.
"""

from __future__ import annotations

import re

__all__ = [
    "VALUE_COLUMNS",
    "PARAM_COLUMNS",
    "CLAIM_COLUMNS",
    "SEEDS",
    "PRECISION_KINDS",
    "ROUNDINGS",
    "CLAIM_KINDS",
    "PAPERS",
    "PublishedDataError",
    "printed_precision",
]

VALUE_COLUMNS = [
    "id",
    "seed",
    "source",
    "line",
    "row",
    "quantity",
    "printed",
    "value",
    "unit",
    "precision_kind",
    "precision",
    "rounding",
    "notes",
]
PARAM_COLUMNS = ["seed", "source", "line", "example", "parameter", "printed", "value", "unit", "notes"]
CLAIM_COLUMNS = [
    "id",
    "seed",
    "source",
    "line",
    "kind",
    "statement",
    "parameters",
    "confirm_if",
    "refute_if",
    "notes",
]
SEEDS = ("000", "002", "003", "004")
PRECISION_KINDS = ("decimals", "sig")
ROUNDINGS = ("round", "truncate")
CLAIM_KINDS = ("trend", "approximate", "missing-table")

#: Human-readable names of the seed documents (for the scorecard and report).
PAPERS = {
    "000": "Curvilinear-tooth gears cut by a ZA hob (dissertation, ch. 4-5)",
    "002": "NASA CR-2000-209415: Novikov-Wildhaber helical gears",
    "003": "PhD thesis 2023: conventional vs reduced TCA",
    "004": "Ma et al. 2021: CATT cylindrical gears",
}


class PublishedDataError(ValueError):
    """A published-data file does not follow data/published/README.md."""


_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def printed_precision(printed: str) -> tuple[str, int]:
    """(precision_kind, precision) implied by a printed number string.

    Plain decimals give ("decimals", digits after the point); E-notation gives ("sig",
    significant digits of the mantissa).
    """
    s = str(printed).strip()
    if not _NUMBER.match(s):
        raise PublishedDataError(f"printed value {printed!r} is not a number")
    mant, _, exp = s.lower().partition("e")
    mant = mant.lstrip("+-")
    if exp:
        digits = mant.replace(".", "").lstrip("0")
        return "sig", max(len(digits), 1)
    return "decimals", len(mant.partition(".")[2])
