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
    "PAPER_NAMES",
    "PublishedDataError",
    "printed_precision",
]

#: the columns of a ``values_*.csv`` file: one row per printed number, with its printed string,
#: unit and precision
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
#: the columns of a ``params_*.csv`` file: one row per design parameter of an example
PARAM_COLUMNS = ["seed", "source", "line", "example", "parameter", "printed", "value", "unit", "notes"]
#: the columns of a ``claims_*.csv`` file: one row per statement of a paper, with what confirms and
#: what refutes it
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
#: the seed documents (papers) the data come from
SEEDS = ("000", "002", "003", "004")
#: how a value's precision is counted: digits after the point, or significant digits
PRECISION_KINDS = ("decimals", "sig")
#: how a paper reduced a value to its printed digits
ROUNDINGS = ("round", "truncate")
#: the kinds of claims: a trend, an approximate value, or a table the text lost
CLAIM_KINDS = ("trend", "approximate", "missing-table")

#: Human-readable names of the seed documents (for the scorecard and report).
PAPERS = {
    "000": "Curvilinear-tooth gears cut by a ZA hob (dissertation, ch. 4-5)",
    "002": "NASA CR-2000-209415: Novikov-Wildhaber helical gears",
    "003": "PhD thesis 2023: conventional vs reduced TCA",
    "004": "Ma et al. 2021: CATT cylindrical gears",
}

#: One name per seed document, the name its studies, results, notebooks and report section go by
#: (a study key is the name, or ``<name>_<part>`` for one of two studies of the same document): the
#: first author and year. Seed 000 prints neither (CITATION.cff), so its name says its subject, the
#: hob-cut curvilinear gear (docs/architecture.md says why). The seed ids stay the data's ids.
PAPER_NAMES = {"000": "hobcut", "002": "litvin2000", "003": "temirkhan2023", "004": "ma2021"}


class PublishedDataError(ValueError):
    """A published-data file does not follow data/published/README.md.

    Examples
    --------
    >>> from gearrep.published import PublishedDataError, printed_precision
    >>> try:
    ...     printed_precision("1,5")
    ... except PublishedDataError as exc:
    ...     print(exc)
    printed value '1,5' is not a number
    >>> issubclass(PublishedDataError, ValueError)
    True
    """


_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def printed_precision(printed: str) -> tuple[str, int]:
    """(precision_kind, precision) implied by a printed number string.

    Plain decimals give ("decimals", digits after the point); E-notation gives ("sig",
    significant digits of the mantissa).

    Parameters
    ----------
    printed : str
        The number as printed.

    Returns
    -------
    kind : {"decimals", "sig"}
        The kind of precision.
    precision : int
        Digits after the point, or significant digits.

    Raises
    ------
    PublishedDataError
        If ``printed`` is not a number.

    Examples
    --------
    >>> from gearrep.published import printed_precision
    >>> printed_precision("0.008067"), printed_precision("1.20e-3"), printed_precision("20")
    (('decimals', 6), ('sig', 3), ('decimals', 0))
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
