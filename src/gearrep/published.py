"""Published numbers: typed, validated frames of ``data/published/``.

The file format is documented in ``data/published/README.md``. This is the one library module
that reads files, and it reads only the directory it is handed (it never looks for files or the
workflow config by itself): workflow scripts, tests and notebooks call :func:`load`.

Every value carries the precision it was printed with; :func:`printed_precision` re-derives it
from the printed string so that a mistyped precision field is caught by the tests.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from .units import KNOWN_UNITS

__all__ = [
    "VALUE_COLUMNS", "PARAM_COLUMNS", "CLAIM_COLUMNS", "SEEDS", "PRECISION_KINDS", "ROUNDINGS",
    "CLAIM_KINDS", "PAPERS", "PublishedDataError", "Published", "printed_precision",
    "validate_values", "validate_params", "validate_claims", "load", "parse_row", "param_table",
]

VALUE_COLUMNS = [
    "id", "seed", "source", "line", "row", "quantity", "printed", "value", "unit",
    "precision_kind", "precision", "rounding", "notes",
]
PARAM_COLUMNS = ["seed", "source", "line", "example", "parameter", "printed", "value", "unit", "notes"]
CLAIM_COLUMNS = [
    "id", "seed", "source", "line", "kind", "statement", "parameters", "confirm_if", "refute_if", "notes",
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

_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


class PublishedDataError(ValueError):
    """A published-data file does not follow data/published/README.md."""


@dataclass(frozen=True)
class Published:
    """All published data: ``values`` (one row per printed number), ``params``, ``claims``."""

    values: pd.DataFrame
    params: pd.DataFrame
    claims: pd.DataFrame


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


def _read(directory: Path, pattern: str, columns: list[str]) -> pd.DataFrame:
    frames = []
    for path in sorted(directory.glob(pattern)):
        df = pd.read_csv(path, dtype=str, keep_default_na=False)
        missing = [c for c in columns if c not in df.columns]
        if missing:
            raise PublishedDataError(f"{path.name}: missing columns {missing}")
        df = df[columns].copy()
        df.insert(0, "file", path.name)
        frames.append(df)
    if not frames:
        return pd.DataFrame(columns=["file", *columns])
    return pd.concat(frames, ignore_index=True)


def _to_float(df: pd.DataFrame, col: str) -> pd.Series:
    try:
        return df[col].astype(float)
    except ValueError as exc:
        raise PublishedDataError(f"column {col!r}: {exc}") from exc


def validate_values(values: pd.DataFrame) -> pd.DataFrame:
    """Type and validate a values frame; raises PublishedDataError naming file, id and field."""
    v = values.copy()
    for i, r in v.iterrows():
        where = f"{r['file']} id={r['id']!r}"
        if r["seed"] not in SEEDS:
            raise PublishedDataError(f"{where}: seed {r['seed']!r} not in {SEEDS}")
        if r["unit"] not in KNOWN_UNITS:
            raise PublishedDataError(f"{where}: unit {r['unit']!r} not in {sorted(KNOWN_UNITS)}")
        if r["precision_kind"] not in PRECISION_KINDS:
            raise PublishedDataError(f"{where}: precision_kind {r['precision_kind']!r} not in {PRECISION_KINDS}")
        if r["rounding"] not in ROUNDINGS:
            raise PublishedDataError(f"{where}: rounding {r['rounding']!r} not in {ROUNDINGS}")
        kind, prec = printed_precision(r["printed"])
        if (kind, prec) != (r["precision_kind"], int(r["precision"])):
            raise PublishedDataError(
                f"{where}: printed {r['printed']!r} implies {kind}={prec}, file says "
                f"{r['precision_kind']}={r['precision']}"
            )
        if not math.isclose(float(r["printed"]), float(r["value"]), rel_tol=1e-12, abs_tol=0.0):
            raise PublishedDataError(f"{where}: value {r['value']} differs from printed {r['printed']}")
        if not r["row"] and not r["quantity"]:
            raise PublishedDataError(f"{where}: empty row and quantity")
    dup = v["id"][v["id"].duplicated()]
    if len(dup):
        raise PublishedDataError(f"duplicate ids: {sorted(set(dup))[:10]}")
    v["value"] = _to_float(v, "value")
    v["precision"] = v["precision"].astype(int)
    v["line"] = v["line"].astype(int)
    return v


def validate_params(params: pd.DataFrame) -> pd.DataFrame:
    p = params.copy()
    for _, r in p.iterrows():
        where = f"{r['file']} {r['example']}/{r['parameter']}"
        if r["seed"] not in SEEDS:
            raise PublishedDataError(f"{where}: seed {r['seed']!r} not in {SEEDS}")
        if r["unit"] not in KNOWN_UNITS:
            raise PublishedDataError(f"{where}: unit {r['unit']!r} not in {sorted(KNOWN_UNITS)}")
    key = p[["file", "example", "parameter"]].apply(tuple, axis=1)
    if key.duplicated().any():
        raise PublishedDataError(f"duplicate parameters: {list(key[key.duplicated()])[:10]}")
    blank = p["value"].str.strip() == ""
    unexplained = p[blank & (p["notes"].str.strip() == "")]
    if len(unexplained):
        r = unexplained.iloc[0]
        raise PublishedDataError(f"{r['file']} {r['example']}/{r['parameter']}: empty value needs a note")
    # a parameter the text implies but does not print has an empty value (NaN) and a note
    p["value"] = _to_float(p.assign(value=p["value"].where(~blank, "nan")), "value")
    p["line"] = p["line"].astype(int)
    return p


def validate_claims(claims: pd.DataFrame) -> pd.DataFrame:
    c = claims.copy()
    for _, r in c.iterrows():
        where = f"{r['file']} id={r['id']!r}"
        if r["kind"] not in CLAIM_KINDS:
            raise PublishedDataError(f"{where}: kind {r['kind']!r} not in {CLAIM_KINDS}")
        if not r["statement"].strip():
            raise PublishedDataError(f"{where}: empty statement")
    if c["id"].duplicated().any():
        raise PublishedDataError(f"duplicate claim ids: {sorted(set(c['id'][c['id'].duplicated()]))[:10]}")
    c["line"] = c["line"].astype(int)
    return c


def load(directory) -> Published:
    """Read and validate every ``values_*``, ``params_*`` and ``claims_*`` CSV in ``directory``."""
    d = Path(directory)
    if not d.is_dir():
        raise PublishedDataError(f"published-data directory {d} does not exist")
    values = validate_values(_read(d, "values_*.csv", VALUE_COLUMNS))
    params = validate_params(_read(d, "params_*.csv", PARAM_COLUMNS))
    claims = validate_claims(_read(d, "claims_*.csv", CLAIM_COLUMNS))
    ids = pd.concat([values["id"], claims["id"]])
    if ids.duplicated().any():
        raise PublishedDataError(f"ids shared by a value and a claim: {sorted(set(ids[ids.duplicated()]))[:10]}")
    return Published(values=values, params=params, claims=claims)


def parse_row(row: str) -> dict[str, str]:
    """``'l1_mm=4.381;side=L'`` -> ``{'l1_mm': '4.381', 'side': 'L'}``."""
    out = {}
    for part in filter(None, (p.strip() for p in str(row).split(";"))):
        k, sep, val = part.partition("=")
        if not sep:
            raise PublishedDataError(f"row key part {part!r} is not name=value")
        out[k.strip()] = val.strip()
    return out


def param_table(params: pd.DataFrame, file: str, example: str | None = None) -> dict[str, float]:
    """``{parameter: value}`` of one params file (and example), in the file's units."""
    sel = params[params["file"] == file]
    if example is not None:
        sel = sel[sel["example"] == example]
    if sel.empty:
        raise KeyError(f"no parameters for file={file!r} example={example!r}")
    return dict(zip(sel["parameter"], sel["value"]))

