"""Published numbers: typed, validated frames of ``data/published/``.

The file format is documented in ``data/published/README.md``. This is the one library module
that reads files, and it reads only the directory it is handed (it never looks for files or the
workflow config by itself): workflow scripts, tests and notebooks call :func:`load`.

Every value carries the precision it was printed with; :func:`printed_precision` re-derives it
from the printed string so that a mistyped precision field is caught by the tests.
"""

from __future__ import annotations

import csv
import fnmatch
import hashlib
import io
import math
import sys
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from ._published_format import (
    CLAIM_COLUMNS,
    CLAIM_KINDS,
    PAPER_NAMES,
    PAPERS,
    PARAM_COLUMNS,
    PRECISION_KINDS,
    ROUNDINGS,
    SEEDS,
    VALUE_COLUMNS,
    PublishedDataError,
    printed_precision,
)
from ._published_lookup import design_table, document_order, param_table, parse_row, values_by
from ._published_perturb import (
    PERTURB_ENV,
    PERTURBED_UNITS,
    perturb_ulps_from_env,
    perturbed_params,
    perturbed_value,
)
from .units import KNOWN_UNITS

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
    "Published",
    "printed_precision",
    "validate_values",
    "validate_params",
    "validate_claims",
    "load",
    "PERTURB_ENV",
    "PERTURBED_UNITS",
    "perturbed_value",
    "perturbed_params",
    "perturb_ulps_from_env",
    "parse_row",
    "param_table",
    "values_by",
    "design_table",
    "document_order",
    "ERRATA_COLUMNS",
    "load_errata",
    "MANIFEST_NAME",
    "MANIFEST_COLUMNS",
    "DATA_PATTERNS",
    "file_entry",
    "build_manifest",
    "write_manifest",
    "read_manifest",
    "verify_manifest",
    "scored_rows_per_seed",
    "main",
]


@dataclass(frozen=True)
class Published:
    """All published data: ``values`` (one row per printed number), ``params``, ``claims``.

    Parameters
    ----------
    values : pandas.DataFrame
        One row per printed number (:data:`VALUE_COLUMNS` after a ``file`` column), typed.
    params : pandas.DataFrame
        One row per design parameter (:data:`PARAM_COLUMNS` after ``file``).
    claims : pandas.DataFrame
        One row per claim (:data:`CLAIM_COLUMNS` after ``file``).

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import load
    >>> tmp = tempfile.TemporaryDirectory()
    >>> _ = (pathlib.Path(tmp.name) / "params_000_x.csv").write_text(
    ...     "seed,source,line,example,parameter,printed,value,unit,notes\\n000,Table 5.1,600,5.1,module,3,3,mm,\\n"
    ... )
    >>> published = load(tmp.name)
    >>> len(published.values), published.params[["parameter", "value", "unit"]].values.tolist()  # mm
    (0, [['module', 3.0, 'mm']])
    >>> tmp.cleanup()
    """

    values: pd.DataFrame
    params: pd.DataFrame
    claims: pd.DataFrame


def _read_rows(path: Path) -> tuple[list[str], list[list[str]]]:
    """(header, data rows) of one published CSV, every cell its string; blank lines are no rows (as
    in the manifest's count) and a UTF-8 byte-order mark is dropped. Refused naming the file: a
    file that is not UTF-8 CSV (an unclosed quote included), an empty or header-only file, a
    column name given twice, and a data row whose number of fields is not the header's (pandas'
    reader, used before, filled a short row with empty cells and, where every row had one field
    more than the header, took the first column as the index and shifted every other one)."""
    try:
        with path.open(encoding="utf-8-sig", newline="") as f:
            records = [r for r in csv.reader(f, strict=True) if r]
    except (UnicodeDecodeError, csv.Error) as exc:
        raise PublishedDataError(f"{path.name}: not a readable UTF-8 CSV file: {exc}") from None
    if not records:
        raise PublishedDataError(f"{path.name}: the file is empty (not even a header row)")
    header, rows = records[0], records[1:]
    if not rows:
        raise PublishedDataError(f"{path.name}: a header row but no data rows")
    repeated = sorted({c for c in header if header.count(c) > 1})
    if repeated:
        raise PublishedDataError(f"{path.name}: column name(s) {repeated} given twice in the header row")
    for n, r in enumerate(rows, start=1):
        if len(r) != len(header):
            raise PublishedDataError(
                f"{path.name} data row {n}: {len(r)} fields, the header row has {len(header)} ({r[:3]}...)"
            )
    return header, rows


def _read_csv(path: Path) -> pd.DataFrame:
    """One published CSV as a frame of strings (see :func:`_read_rows`)."""
    header, rows = _read_rows(path)
    return pd.DataFrame(rows, columns=header, dtype=str)


def _read(directory: Path, pattern: str, columns: list[str], files=None) -> pd.DataFrame:
    """The ``columns`` of every file matching ``pattern`` (and ``files``), after a ``file`` column,
    as one frame of strings built once from the files' rows."""
    cells: dict[str, list] = {c: [] for c in ["file", *columns]}
    for path in sorted(directory.glob(pattern)):
        if files is not None and not any(fnmatch.fnmatchcase(path.name, f) for f in files):
            continue
        header, rows = _read_rows(path)
        missing = [c for c in columns if c not in header]
        if missing:
            raise PublishedDataError(f"{path.name}: missing required column(s) {missing}")
        cells["file"] += [path.name] * len(rows)
        for c in columns:
            i = header.index(c)
            cells[c] += [r[i] for r in rows]
    if not cells["file"]:
        return pd.DataFrame(columns=["file", *columns])
    return pd.DataFrame(cells, dtype=str)


def _where(row: dict, n: int) -> str:
    """``<file> id='<id>'`` of a data row (``<file> data row <n>`` when it has no id)."""
    rid = str(row["id"]).strip() if "id" in row else ""
    return f"{row['file']} id={rid!r}" if rid else f"{row['file']} data row {n}"


def _number(where: str, column: str, text, kind=float):
    """``kind(text)`` or a PublishedDataError naming the row and column."""
    try:
        return kind(text)
    except (TypeError, ValueError):
        what = "an integer" if kind is int else "a number"
        raise PublishedDataError(f"{where} column {column!r}: {text!r} is not {what}") from None


def _row_numbers(files: list) -> list[int]:
    """1-based data-row number of each row within its file (the header is not counted), from the
    rows' file names in order."""
    seen: dict = {}
    out = []
    for f in files:
        seen[f] = seen.get(f, 0) + 1
        out.append(seen[f])
    return out


def _numbered_rows(df: pd.DataFrame):
    """(row as a dict of its cells, its 1-based data-row number in its file), row by row (plain
    dicts from the columns' lists: ``iterrows`` builds a Series per row, and even ``to_dict`` and a
    groupby made reading the data a tenth of a short workflow job)."""
    names = list(df.columns)
    cols = [df[c].tolist() for c in names]
    files = cols[names.index("file")]
    return zip((dict(zip(names, cells)) for cells in zip(*cols)), _row_numbers(files))


def validate_values(values: pd.DataFrame) -> pd.DataFrame:
    """Type and validate a values frame; raises PublishedDataError naming file, id and column.

    Parameters
    ----------
    values : pandas.DataFrame
        Strings of :data:`VALUE_COLUMNS` after a ``file`` column.

    Returns
    -------
    pandas.DataFrame
        A copy with ``value`` float and ``precision``, ``line`` int.

    Raises
    ------
    PublishedDataError
        On the first bad cell or a repeated id.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import VALUE_COLUMNS, PublishedDataError, validate_values
    >>> cells = ["000-T4.3-k_s", "000", "Table 4.3", "366", "l1_mm=4.381", "k_s", "0.008067", "0.008067", "per_mm"]
    >>> cells += ["decimals", "6", "round", ""]
    >>> frame = pd.DataFrame([["values_000_x.csv", *cells]], columns=["file", *VALUE_COLUMNS])
    >>> validate_values(frame)[["value", "precision"]].values.tolist()  # 1/mm, 6 decimals
    [[0.008067, 6.0]]
    >>> frame.loc[0, "precision"] = "5"
    >>> try:
    ...     validate_values(frame)
    ... except PublishedDataError as exc:
    ...     print(exc)
    values_000_x.csv id='000-T4.3-k_s': printed '0.008067' implies decimals=6, file says decimals=5
    """
    v = values.copy()
    for r, n in _numbered_rows(v):
        where = _where(r, n)
        if not str(r["id"]).strip():
            raise PublishedDataError(f"{where} column 'id': empty id")
        if r["seed"] not in SEEDS:
            raise PublishedDataError(f"{where} column 'seed': {r['seed']!r} not in {SEEDS}")
        if r["unit"] not in KNOWN_UNITS:
            raise PublishedDataError(f"{where} column 'unit': {r['unit']!r} not in {sorted(KNOWN_UNITS)}")
        if r["precision_kind"] not in PRECISION_KINDS:
            raise PublishedDataError(
                f"{where} column 'precision_kind': {r['precision_kind']!r} not in {PRECISION_KINDS}"
            )
        if r["rounding"] not in ROUNDINGS:
            raise PublishedDataError(f"{where} column 'rounding': {r['rounding']!r} not in {ROUNDINGS}")
        _number(where, "line", r["line"], int)
        try:
            kind, prec = printed_precision(r["printed"])
        except PublishedDataError as exc:
            raise PublishedDataError(f"{where} column 'printed': {exc}") from None
        if (kind, prec) != (r["precision_kind"], _number(where, "precision", r["precision"], int)):
            raise PublishedDataError(
                f"{where}: printed {r['printed']!r} implies {kind}={prec}, file says "
                f"{r['precision_kind']}={r['precision']}"
            )
        value = _number(where, "value", r["value"])
        if not math.isclose(float(r["printed"]), value, rel_tol=1e-12, abs_tol=0.0):
            raise PublishedDataError(f"{where} column 'value': {r['value']} differs from printed {r['printed']}")
        if not r["row"] and not r["quantity"]:
            raise PublishedDataError(f"{where} columns 'row', 'quantity': both empty")
    _duplicates(v, "id", "duplicate ids")
    v["value"] = v["value"].astype(float)
    v["precision"] = v["precision"].astype(int)
    v["line"] = v["line"].astype(int)
    return v


def validate_params(params: pd.DataFrame) -> pd.DataFrame:
    """Type and validate a params frame; raises PublishedDataError naming file, example/parameter
    and column.

    Parameters
    ----------
    params : pandas.DataFrame
        Strings of :data:`PARAM_COLUMNS` after a ``file`` column.

    Returns
    -------
    pandas.DataFrame
        A copy with ``value`` float (NaN where not printed) and ``line`` int.

    Raises
    ------
    PublishedDataError
        On the first bad cell or a repeated parameter.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import PARAM_COLUMNS, validate_params
    >>> cells = ["000", "Table 5.1", "600", "5.1", "module", "3", "3", "mm", ""]
    >>> frame = pd.DataFrame([["params_000_x.csv", *cells]], columns=["file", *PARAM_COLUMNS])
    >>> validate_params(frame)[["parameter", "value", "line"]].values.tolist()  # mm
    [['module', 3.0, 600]]
    """
    p = params.copy()
    blank = p["value"].str.strip() == ""
    for r, n in _numbered_rows(p):
        where = f"{r['file']} {r['example']}/{r['parameter']} (data row {n})"
        if r["seed"] not in SEEDS:
            raise PublishedDataError(f"{where} column 'seed': {r['seed']!r} not in {SEEDS}")
        if r["unit"] not in KNOWN_UNITS:
            raise PublishedDataError(f"{where} column 'unit': {r['unit']!r} not in {sorted(KNOWN_UNITS)}")
        _number(where, "line", r["line"], int)
        if str(r["value"]).strip():
            _number(where, "value", r["value"])
        elif not str(r["notes"]).strip():
            # a parameter the text implies but does not print has an empty value (NaN) and a note
            raise PublishedDataError(f"{where} column 'value': empty value needs a note")
    seen, repeated = set(), []
    for key in zip(p["file"].tolist(), p["example"].tolist(), p["parameter"].tolist()):
        if key in seen:
            repeated.append(key)
        seen.add(key)
    if repeated:
        raise PublishedDataError(f"duplicate parameters: {repeated[:10]}")
    p["value"] = p["value"].where(~blank, "nan").astype(float)
    p["line"] = p["line"].astype(int)
    return p


def validate_claims(claims: pd.DataFrame) -> pd.DataFrame:
    """Type and validate a claims frame; raises PublishedDataError naming file, id and column.

    Parameters
    ----------
    claims : pandas.DataFrame
        Strings of :data:`CLAIM_COLUMNS` after a ``file`` column.

    Returns
    -------
    pandas.DataFrame
        A copy with ``line`` int.

    Raises
    ------
    PublishedDataError
        On the first bad cell or a repeated id.

    Examples
    --------
    >>> import pandas as pd
    >>> from gearrep.published import CLAIM_COLUMNS, PublishedDataError, validate_claims
    >>> cells = ["000-KE", "000", "Section 5.5", "606", "guess", "The KE is small.", "", "KE < 5 arcsec", "KE > 50", ""]
    >>> try:
    ...     validate_claims(pd.DataFrame([["claims_000_x.csv", *cells]], columns=["file", *CLAIM_COLUMNS]))
    ... except PublishedDataError as exc:
    ...     print(exc)
    claims_000_x.csv id='000-KE' column 'kind': 'guess' not in ('trend', 'approximate', 'missing-table')
    """
    c = claims.copy()
    for r, n in _numbered_rows(c):
        where = _where(r, n)
        if not str(r["id"]).strip():
            raise PublishedDataError(f"{where} column 'id': empty id")
        if r["seed"] not in SEEDS:
            raise PublishedDataError(f"{where} column 'seed': {r['seed']!r} not in {SEEDS}")
        if r["kind"] not in CLAIM_KINDS:
            raise PublishedDataError(f"{where} column 'kind': {r['kind']!r} not in {CLAIM_KINDS}")
        if not r["statement"].strip():
            raise PublishedDataError(f"{where} column 'statement': empty statement")
        _number(where, "line", r["line"], int)
    _duplicates(c, "id", "duplicate claim ids")
    c["line"] = c["line"].astype(int)
    return c


def load(directory, files=None) -> Published:
    """Read and validate every ``values_*``, ``params_*`` and ``claims_*`` CSV in ``directory``
    (only those whose names match one of the glob patterns ``files``, if given: a workflow job
    reads exactly the files it declares as inputs).

    With the environment variable :data:`PERTURB_ENV` set to k >= 1 the design parameters are
    returned nudged by :func:`perturbed_params` (the portability check; never in a normal run).

    Parameters
    ----------
    directory : str or path-like
        The published-data directory.
    files : iterable of str, optional
        Glob patterns of the file names to read (their directory part is ignored).

    Returns
    -------
    Published
        The typed frames.

    Raises
    ------
    PublishedDataError
        If the directory does not exist, a file breaks the format, or an id repeats.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import load
    >>> tmp = tempfile.TemporaryDirectory()
    >>> header = "seed,source,line,example,parameter,printed,value,unit,notes\\n"
    >>> _ = (pathlib.Path(tmp.name) / "params_000_x.csv").write_text(header + "000,Table 5.1,600,5.1,module,3,3,mm,\\n")
    >>> _ = (pathlib.Path(tmp.name) / "params_002_y.csv").write_text(header + "002,Sec. 2.5,40,S2.5,N1,17,17,1,\\n")
    >>> load(tmp.name).params["parameter"].tolist(), load(tmp.name, files=["params_002_*"]).params["parameter"].tolist()
    (['module', 'N1'], ['N1'])
    >>> tmp.cleanup()
    """
    d = Path(directory)
    if not d.is_dir():
        raise PublishedDataError(f"published-data directory {d} does not exist")
    files = None if files is None else [Path(f).name for f in files]
    values = validate_values(_read(d, "values_*.csv", VALUE_COLUMNS, files))
    params = validate_params(_read(d, "params_*.csv", PARAM_COLUMNS, files))
    ulps = perturb_ulps_from_env()
    if ulps:
        params = perturbed_params(params, ulps)
    claims = validate_claims(_read(d, "claims_*.csv", CLAIM_COLUMNS, files))
    both = pd.concat([values[["file", "id"]], claims[["file", "id"]]], ignore_index=True)
    _duplicates(both, "id", "ids shared by a value and a claim")
    return Published(values=values, params=params, claims=claims)


#: the columns of the errata file (``data/errata.csv``)
ERRATA_COLUMNS = ["seed", "location", "printed", "correction", "evidence"]


def load_errata(path) -> pd.DataFrame:
    """The errata file (``data/errata.csv``): one row per erratum with its seed, location, the
    printed form, the correction and the evidence. An empty or header-only file, a missing
    column, an unknown seed or an erratum without evidence is refused naming the file and row.

    Parameters
    ----------
    path : str or path-like
        The errata file.

    Returns
    -------
    pandas.DataFrame
        :data:`ERRATA_COLUMNS` as strings.

    Raises
    ------
    PublishedDataError
        If the file is missing or breaks its format.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import load_errata
    >>> tmp = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(tmp.name) / "errata.csv"
    >>> _ = path.write_text(
    ...     "seed,location,printed,correction,evidence\\n"
    ...     "000,eq 4.37,b_11 as printed,the sign changes,expanding the determinant gives the opposite sign\\n"
    ... )
    >>> load_errata(path)[["seed", "location"]].values.tolist()
    [['000', 'eq 4.37']]
    >>> tmp.cleanup()
    """
    path = Path(path)
    if not path.is_file():
        raise PublishedDataError(f"{path}: the errata file does not exist")
    df = _read_csv(path)
    missing = [c for c in ERRATA_COLUMNS if c not in df.columns]
    if missing:
        raise PublishedDataError(f"{path.name}: missing required column(s) {missing}")
    for n, row in enumerate(df.itertuples(index=False), start=1):
        if row.seed not in SEEDS:
            raise PublishedDataError(
                f"{path.name} data row {n} column 'seed': {row.seed!r} is not one of {list(SEEDS)}"
            )
        if len(row.evidence.strip()) < 20:
            raise PublishedDataError(f"{path.name} data row {n} column 'evidence': an erratum needs its evidence")
    return df


def _duplicates(frame: pd.DataFrame, column: str, message: str) -> None:
    """Refuse rows whose ``column`` repeats, naming each file and value (``<file> id='...'``)."""
    dup = frame[column].duplicated(keep=False)
    if dup.any():
        where = sorted({f"{f} {column}={v!r}" for f, v in zip(frame.loc[dup, "file"], frame.loc[dup, column])})
        raise PublishedDataError(f"{message}: {where[:10]}")


# ----------------------------------------------------------------------------- manifest

#: The manifest of a published-data directory: one row per data file.
MANIFEST_NAME = "MANIFEST.csv"
#: The data files :func:`load` reads, by kind.
DATA_PATTERNS = {"values": "values_*.csv", "params": "params_*.csv", "claims": "claims_*.csv"}
#: the columns of the manifest: the file, its kind, checksum, bytes and data rows (all and per seed)
MANIFEST_COLUMNS = ["file", "kind", "sha256", "bytes", "rows", *(f"rows_{s}" for s in SEEDS)]
_COUNT_COLUMNS = ["bytes", "rows", *(f"rows_{s}" for s in SEEDS)]
_REGENERATE = "python -m gearrep.published --write-manifest"


def _kind(name: str) -> str | None:
    return next((k for k, pat in DATA_PATTERNS.items() if fnmatch.fnmatchcase(name, pat)), None)


def _data_files(directory: Path) -> list[Path]:
    """Every CSV of ``directory`` but the manifest: the files a manifest must list."""
    return sorted(p for p in directory.glob("*.csv") if p.name != MANIFEST_NAME)


def file_entry(path) -> dict:
    """The manifest row of one data file: kind, sha256 and size of its bytes, number of data rows
    (the header not counted, quoted line breaks inside a field not splitting a row) and the
    number of rows of each seed.

    Parameters
    ----------
    path : str or path-like
        A data file.

    Returns
    -------
    dict
        One row of :data:`MANIFEST_COLUMNS` (``bytes`` [bytes]).

    Raises
    ------
    PublishedDataError
        If the name is not a data file's, or the file is not UTF-8 CSV with a ``seed`` column.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import file_entry
    >>> tmp = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(tmp.name) / "params_000_x.csv"
    >>> _ = path.write_text("seed,source,line,example,parameter,printed,value,unit,notes\\n000,T5.1,600,5.1,m,3,3,mm,\\n")
    >>> entry = file_entry(path)
    >>> entry["kind"], entry["rows"], entry["rows_000"], entry["bytes"] == path.stat().st_size, len(entry["sha256"])
    ('params', 1, 1, True, 64)
    >>> tmp.cleanup()
    """
    path = Path(path)
    kind = _kind(path.name)
    if kind is None:
        raise PublishedDataError(
            f"{path.name}: not a published-data file name ({', '.join(DATA_PATTERNS.values())}); load() would ignore it"
        )
    raw = path.read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise PublishedDataError(f"{path.name}: not UTF-8 text: {exc}") from None
    records = [r for r in csv.reader(io.StringIO(text, newline="")) if r]  # blank lines are no rows
    header, rows = (records[0], records[1:]) if records else ([], [])
    if "seed" not in header:
        raise PublishedDataError(f"{path.name}: no 'seed' column in the header row {header}")
    col = header.index("seed")
    seeds = [r[col] if col < len(r) else "" for r in rows]
    return {
        "file": path.name,
        "kind": kind,
        "sha256": hashlib.sha256(raw).hexdigest(),
        "bytes": len(raw),
        "rows": len(rows),
        **{f"rows_{s}": seeds.count(s) for s in SEEDS},
    }


def build_manifest(directory) -> pd.DataFrame:
    """The manifest of a published-data directory (:data:`MANIFEST_COLUMNS`, one row per file,
    sorted by file name).

    Parameters
    ----------
    directory : str or path-like
        The published-data directory.

    Returns
    -------
    pandas.DataFrame
        The manifest.

    Raises
    ------
    PublishedDataError
        If the directory does not exist, holds no data file, or a file is not a data file.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import build_manifest
    >>> tmp = tempfile.TemporaryDirectory()
    >>> _ = (pathlib.Path(tmp.name) / "params_000_x.csv").write_text(
    ...     "seed,source,line,example,parameter,printed,value,unit,notes\\n000,T5.1,600,5.1,m,3,3,mm,\\n"
    ... )
    >>> build_manifest(tmp.name)[["file", "kind", "rows"]].values.tolist()
    [['params_000_x.csv', 'params', 1]]
    >>> tmp.cleanup()
    """
    d = Path(directory)
    if not d.is_dir():
        raise PublishedDataError(f"published-data directory {d} does not exist")
    entries = [file_entry(p) for p in _data_files(d)]
    if not entries:
        raise PublishedDataError(f"{d}: no published-data files")
    return pd.DataFrame(entries, columns=MANIFEST_COLUMNS)


def write_manifest(directory) -> Path:
    """(Re)write ``<directory>/MANIFEST.csv`` from the files as they are; returns its path.

    Parameters
    ----------
    directory : str or path-like
        The published-data directory.

    Returns
    -------
    pathlib.Path
        The manifest's path.

    Raises
    ------
    PublishedDataError
        As :func:`build_manifest`.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import write_manifest
    >>> tmp = tempfile.TemporaryDirectory()
    >>> _ = (pathlib.Path(tmp.name) / "params_000_x.csv").write_text(
    ...     "seed,source,line,example,parameter,printed,value,unit,notes\\n000,T5.1,600,5.1,m,3,3,mm,\\n"
    ... )
    >>> write_manifest(tmp.name).name
    'MANIFEST.csv'
    >>> tmp.cleanup()
    """
    d = Path(directory)
    manifest = build_manifest(d)
    out = d / MANIFEST_NAME
    manifest.to_csv(out, index=False, lineterminator="\n")
    return out


def read_manifest(directory) -> pd.DataFrame:
    """``<directory>/MANIFEST.csv`` as a frame (counts as int).

    Parameters
    ----------
    directory : str or path-like
        The published-data directory.

    Returns
    -------
    pandas.DataFrame
        :data:`MANIFEST_COLUMNS`.

    Raises
    ------
    PublishedDataError
        If the manifest is missing, lacks a column, has a count that is not an integer or lists a
        file twice.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import read_manifest, write_manifest
    >>> tmp = tempfile.TemporaryDirectory()
    >>> _ = (pathlib.Path(tmp.name) / "params_000_x.csv").write_text(
    ...     "seed,source,line,example,parameter,printed,value,unit,notes\\n000,T5.1,600,5.1,m,3,3,mm,\\n"
    ... )
    >>> _ = write_manifest(tmp.name)
    >>> read_manifest(tmp.name)[["file", "rows", "rows_000"]].values.tolist()
    [['params_000_x.csv', 1, 1]]
    >>> tmp.cleanup()
    """
    path = Path(directory) / MANIFEST_NAME
    if not path.is_file():
        raise PublishedDataError(f"{path}: no manifest; write it with `{_REGENERATE} {directory}`")
    m = _read_csv(path)
    missing = [c for c in MANIFEST_COLUMNS if c not in m.columns]
    if missing:
        raise PublishedDataError(f"{path.name}: missing required column(s) {missing}")
    for (_, r), n in zip(m.iterrows(), range(1, len(m) + 1)):
        for c in _COUNT_COLUMNS:
            _number(f"{path.name} file={r['file']!r} (data row {n})", c, r[c], int)
    if m["file"].duplicated().any():
        raise PublishedDataError(f"{path.name}: files listed twice: {sorted(set(m['file'][m['file'].duplicated()]))}")
    return m.astype({c: int for c in _COUNT_COLUMNS})[MANIFEST_COLUMNS]


def _difference(listed: pd.Series, path: Path) -> str | None:
    """What is wrong with one listed file (None if it matches its manifest row)."""
    name, rows = listed["file"], int(listed["rows"])
    if not path.is_file():
        return f"{name}: listed in {MANIFEST_NAME} ({rows} rows) but missing"
    if path.stat().st_size == 0:
        return f"{name}: emptied (0 bytes; {MANIFEST_NAME} lists {rows} rows)"
    try:
        now = file_entry(path)
    except PublishedDataError as exc:
        return f"{name}: unreadable ({exc})"
    if now["sha256"] == listed["sha256"]:
        return None
    per_seed = ", ".join(
        f"seed {s} {listed[f'rows_{s}']} -> {now[f'rows_{s}']}"
        for s in SEEDS
        if now[f"rows_{s}"] != int(listed[f"rows_{s}"])
    )
    seeds = f" ({per_seed})" if per_seed else ""
    if now["rows"] == 0:
        return f"{name}: cut to its header row ({MANIFEST_NAME} lists {rows} rows)"
    if now["rows"] < rows:
        return f"{name}: shrunk from {rows} to {now['rows']} rows{seeds}"
    if now["rows"] > rows:
        return f"{name}: grown from {rows} to {now['rows']} rows{seeds}"
    return (
        f"{name}: altered (same {rows} rows{seeds}, sha256 {now['sha256'][:12]}... is not {listed['sha256'][:12]}...)"
    )


def verify_manifest(directory, manifest: pd.DataFrame | None = None) -> pd.DataFrame:
    """Check a published-data directory against its manifest (``<directory>/MANIFEST.csv``
    unless ``manifest`` is given): every listed file present with the listed checksum, and no
    CSV that the manifest does not list. Raises one PublishedDataError naming every file that
    is missing, emptied, cut to its header, shrunk, grown, altered or unlisted; returns the
    manifest when all match.

    Parameters
    ----------
    directory : str or path-like
        The published-data directory.
    manifest : pandas.DataFrame, optional
        The manifest to check against (default: the directory's).

    Returns
    -------
    pandas.DataFrame
        The manifest.

    Raises
    ------
    PublishedDataError
        If the directory or its manifest is missing, or a file differs from it.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import PublishedDataError, verify_manifest, write_manifest
    >>> tmp = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(tmp.name) / "params_000_x.csv"
    >>> header = "seed,source,line,example,parameter,printed,value,unit,notes\\n"
    >>> _ = path.write_text(header + "000,T5.1,600,5.1,m,3,3,mm,\\n")
    >>> _ = write_manifest(tmp.name)
    >>> len(verify_manifest(tmp.name))
    1
    >>> _ = path.write_text(header)  # the data cut to the header row
    >>> try:
    ...     verify_manifest(tmp.name)
    ... except PublishedDataError as exc:
    ...     print(str(exc).splitlines()[1])
      params_000_x.csv: cut to its header row (MANIFEST.csv lists 1 rows)
    >>> tmp.cleanup()
    """
    d = Path(directory)
    if not d.is_dir():
        raise PublishedDataError(f"published-data directory {d} does not exist")
    m = read_manifest(d) if manifest is None else manifest
    problems = [msg for _, r in m.iterrows() if (msg := _difference(r, d / r["file"]))]
    listed = set(m["file"])
    problems += [f"{p.name}: not listed in {MANIFEST_NAME}" for p in _data_files(d) if p.name not in listed]
    if problems:
        raise PublishedDataError(
            f"published data in {d} differ from {MANIFEST_NAME}:\n  "
            + "\n  ".join(problems)
            + f"\nIf the change is deliberate, run `{_REGENERATE} {d}` and commit the manifest "
            "with the data."
        )
    return m


def scored_rows_per_seed(manifest: pd.DataFrame) -> dict[str, int]:
    """``{seed: rows}`` of the values and claims files: the scorecard has one row for each.

    Parameters
    ----------
    manifest : pandas.DataFrame
        A manifest (:func:`read_manifest`).

    Returns
    -------
    dict
        Rows of values and claims per seed.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import CLAIM_COLUMNS, build_manifest, scored_rows_per_seed
    >>> tmp = tempfile.TemporaryDirectory()
    >>> _ = (pathlib.Path(tmp.name) / "claims_000_x.csv").write_text(
    ...     ",".join(CLAIM_COLUMNS) + "\\n000-KE,000,Sec. 5.5,606,trend,The KE is small.,,KE < 5,KE > 50,\\n"
    ... )
    >>> scored_rows_per_seed(build_manifest(tmp.name))
    {'000': 1, '002': 0, '003': 0, '004': 0}
    >>> tmp.cleanup()
    """
    scored = manifest[manifest["kind"].isin(["values", "claims"])]
    return {s: int(scored[f"rows_{s}"].astype(int).sum()) for s in SEEDS}


def main(argv: list[str] | None = None) -> int:
    """``python -m gearrep.published --write-manifest DIR`` / ``--verify DIR``.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default: the command line's).

    Returns
    -------
    int
        The exit status: 0, or 1 after an error message.

    Examples
    --------
    >>> import pathlib
    >>> import tempfile
    >>> from gearrep.published import main
    >>> tmp = tempfile.TemporaryDirectory()
    >>> _ = (pathlib.Path(tmp.name) / "params_000_x.csv").write_text(
    ...     "seed,source,line,example,parameter,printed,value,unit,notes\\n000,T5.1,600,5.1,m,3,3,mm,\\n"
    ... )
    >>> main(["--write-manifest", tmp.name])
    wrote .../MANIFEST.csv: 1 files, 1 rows; scored rows per seed {'000': 0, '002': 0, '003': 0, '004': 0}
    0
    >>> import contextlib
    >>> import io
    >>> printed = io.StringIO()
    >>> with contextlib.redirect_stdout(printed):
    ...     status = main(["--verify", tmp.name])
    >>> status, printed.getvalue().endswith(": 1 files match MANIFEST.csv and load\\n")
    (0, True)
    >>> tmp.cleanup()
    """
    import argparse

    ap = argparse.ArgumentParser(prog="python -m gearrep.published", description=main.__doc__)
    group = ap.add_mutually_exclusive_group(required=True)
    group.add_argument("--write-manifest", metavar="DIR", help=f"(re)write DIR/{MANIFEST_NAME}")
    group.add_argument("--verify", metavar="DIR", help=f"check DIR against DIR/{MANIFEST_NAME} and load it")
    args = ap.parse_args(argv)
    try:
        if args.write_manifest:
            out = write_manifest(args.write_manifest)
            m = read_manifest(args.write_manifest)
            print(
                f"wrote {out}: {len(m)} files, {int(m['rows'].sum())} rows; scored rows per seed "
                f"{scored_rows_per_seed(m)}"
            )
        else:
            m = verify_manifest(args.verify)
            load(args.verify)
            print(f"{args.verify}: {len(m)} files match {MANIFEST_NAME} and load")
    except PublishedDataError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
