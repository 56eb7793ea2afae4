"""Bad published-data files stop the loader with a PublishedDataError naming the file, the row's
id and the column (never a bare pandas or float() error)."""

import csv
import io
import shutil

import pytest
from conftest import PUBLISHED_DIR

from gearrep import published as pub

VALUES = "values_000_T4.3.csv"
PARAMS = "params_002_S2.5.csv"
CLAIMS = "claims_003.csv"


@pytest.fixture
def data(tmp_path):
    """A copy of three published files (one of each kind), so each test loads quickly."""
    d = tmp_path / "published"
    d.mkdir()
    for name in (VALUES, PARAMS, CLAIMS):
        shutil.copy(PUBLISHED_DIR / name, d / name)
    return d


def _rows(path):
    with path.open(encoding="utf-8", newline="") as f:
        return list(csv.reader(f))


def _write(path, rows):
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows(rows)
    path.write_text(out.getvalue(), encoding="utf-8")


def _set_cell(path, column, text, row=1):
    """Set ``column`` of data row ``row`` (1-based) to ``text``; returns that row's first cell."""
    rows = _rows(path)
    rows[row][rows[0].index(column)] = text
    _write(path, rows)
    return rows[row][0]


def _refused(directory, *parts):
    with pytest.raises(pub.PublishedDataError) as err:
        pub.load(directory)
    msg = str(err.value)
    for part in parts:
        assert part in msg, msg
    return msg


def test_the_copies_load(data):
    p = pub.load(data)
    assert len(p.values) and len(p.params) and len(p.claims)


def test_non_numeric_value_names_file_id_and_column(data):
    rid = _set_cell(data / VALUES, "value", "27.3x")
    msg = _refused(data, VALUES, f"id={rid!r}", "column 'value'", "'27.3x'")
    assert "could not convert" not in msg


def test_non_numeric_printed_names_file_id_and_column(data):
    rid = _set_cell(data / VALUES, "printed", "0.01o", row=3)
    _refused(data, VALUES, f"id={rid!r}", "column 'printed'", "'0.01o'")


@pytest.mark.parametrize("column", ["precision", "line"])
def test_non_integer_field_names_file_id_and_column(data, column):
    rid = _set_cell(data / VALUES, column, "3x", row=2)
    _refused(data, VALUES, f"id={rid!r}", f"column {column!r}", "'3x'", "integer")


def test_non_numeric_parameter_names_file_parameter_and_column(data):
    rows = _rows(data / PARAMS)
    header = rows[0]
    example, parameter = rows[1][header.index("example")], rows[1][header.index("parameter")]
    _set_cell(data / PARAMS, "value", "twelve")
    _refused(data, PARAMS, f"{example}/{parameter}", "column 'value'", "'twelve'")


def test_non_integer_claim_line_names_file_id_and_column(data):
    rid = _set_cell(data / CLAIMS, "line", "")
    _refused(data, CLAIMS, f"id={rid!r}", "column 'line'")


def test_empty_id_names_file_row_and_column(data):
    _set_cell(data / VALUES, "id", "", row=4)
    _refused(data, VALUES, "data row 4", "column 'id'")


@pytest.mark.parametrize("name", [VALUES, PARAMS, CLAIMS])
def test_empty_file_is_named(data, name):
    (data / name).write_bytes(b"")
    msg = _refused(data, name, "empty")
    assert "No columns to parse" not in msg


@pytest.mark.parametrize("name", [VALUES, PARAMS, CLAIMS])
def test_header_only_file_is_named(data, name):
    path = data / name
    _write(path, _rows(path)[:1])
    _refused(data, name, "header row but no data rows")


@pytest.mark.parametrize("name, column", [(VALUES, "unit"), (PARAMS, "value"), (CLAIMS, "statement")])
def test_missing_column_is_named(data, name, column):
    path = data / name
    rows = _rows(path)
    i = rows[0].index(column)
    _write(path, [r[:i] + r[i + 1 :] for r in rows])
    _refused(data, name, "missing required column", repr(column))


def test_unknown_unit_names_file_id_and_column(data):
    rid = _set_cell(data / VALUES, "unit", "furlong")
    _refused(data, VALUES, f"id={rid!r}", "column 'unit'", "'furlong'")


def test_unreadable_file_is_named(data):
    (data / VALUES).write_bytes(b"id,seed\n\xff\xfe,000\n")
    _refused(data, VALUES, "UTF-8")


def test_duplicate_ids_name_their_files(tmp_path):
    """Every data error names the file: a repeated id names both files."""
    import shutil

    from gearrep import published

    d = tmp_path / "data"
    shutil.copytree(PUBLISHED_DIR, d)
    src = (d / "values_000_T5.4.csv").read_text().splitlines()
    (d / "values_000_T5.9.csv").write_text((d / "values_000_T5.9.csv").read_text() + src[1] + "\n")
    with pytest.raises(
        published.PublishedDataError, match=r"duplicate ids: .*values_000_T5\.4\.csv.*values_000_T5\.9\.csv"
    ):
        published.load(d)


@pytest.mark.parametrize("name", [VALUES, PARAMS, CLAIMS])
def test_a_row_with_a_missing_field_is_named(data, name):
    """pandas' reader filled a short row with empty cells without a word."""
    path = data / name
    rows = _rows(path)
    rows[3] = rows[3][:-1]
    _write(path, rows)
    _refused(data, name, "data row 3", f"{len(rows[0]) - 1} fields", f"has {len(rows[0])}")


def test_one_field_more_in_every_row_is_refused_not_shifted(data):
    """pandas' reader took the first column as the index when every data row had one field more
    than the header, and shifted every column by one."""
    path = data / VALUES
    rows = _rows(path)
    _write(path, [rows[0]] + [r + ["extra"] for r in rows[1:]])
    _refused(data, VALUES, "data row 1", f"{len(rows[0]) + 1} fields")


def test_a_repeated_column_name_is_refused(data):
    """pandas' reader renamed the second one ("notes.1") and read the first."""
    path = data / CLAIMS
    rows = _rows(path)
    _write(path, [rows[0] + ["notes"]] + [r + [""] for r in rows[1:]])
    _refused(data, CLAIMS, "['notes'] given twice")


def test_an_unclosed_quote_is_refused(data):
    path = data / PARAMS
    path.write_text(path.read_text(encoding="utf-8") + '003,"Table 1,1,ex,p,1,1,mm,\n', encoding="utf-8")
    _refused(data, PARAMS, "not a readable UTF-8 CSV file")


def test_a_byte_order_mark_and_blank_lines_are_read_as_before(data):
    """A UTF-8 byte-order mark (as pandas dropped it) and blank lines (no rows, as the manifest
    counts them) change nothing."""
    before = pub.load(data)
    path = data / VALUES
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines(keepends=True)
    path.write_bytes(b"\xef\xbb\xbf" + "".join(lines[:3] + ["\n"] + lines[3:] + ["\n"]).encode("utf-8"))
    after = pub.load(data)
    for kind in ("values", "params", "claims"):
        assert getattr(before, kind).equals(getattr(after, kind))
