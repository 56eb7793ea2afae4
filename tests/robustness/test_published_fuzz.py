"""Property-based hostile published data: random mutations of a copy of
data/published (rows deleted, bytes changed, files truncated, values blanked) are caught by the
manifest check naming the file, and the loader itself either loads the copy or raises a
PublishedDataError naming the file, never another exception."""

import csv
import io
import shutil
import tempfile
from pathlib import Path

import pytest
from conftest import PUBLISHED_DIR
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gearrep import published as pub

FILES = sorted(p.name for p in PUBLISHED_DIR.glob("*.csv") if p.name != pub.MANIFEST_NAME)


def _rows(text: str) -> list[list[str]]:
    return list(csv.reader(io.StringIO(text)))


def _write_rows(rows) -> bytes:
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows)
    return buf.getvalue().encode("utf-8")


@st.composite
def mutation(draw):
    """(file name, new bytes) for one mutated published file."""
    name = draw(st.sampled_from(FILES))
    data = (PUBLISHED_DIR / name).read_bytes()
    kind = draw(st.sampled_from(["delete_rows", "change_byte", "truncate", "blank_value"]))
    if kind == "change_byte":
        i = draw(st.integers(0, len(data) - 1))
        b = draw(st.integers(0, 255))
        return name, data[:i] + bytes([b]) + data[i + 1 :]
    if kind == "truncate":
        return name, data[: draw(st.integers(0, len(data) - 1))]
    rows = _rows(data.decode("utf-8"))
    body = rows[1:]
    if kind == "delete_rows":
        keep = draw(st.lists(st.booleans(), min_size=len(body), max_size=len(body)))
        return name, _write_rows([rows[0]] + [r for r, k in zip(body, keep, strict=True) if k])
    r = draw(st.integers(0, len(body) - 1))
    c = draw(st.integers(0, len(rows[0]) - 1))
    body[r] = list(body[r]) + [""] * (len(rows[0]) - len(body[r]))
    body[r][c] = draw(st.sampled_from(["", " ", "nan", "x"]))
    return name, _write_rows([rows[0]] + body)


def _check(mutations):
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp) / "published"
        shutil.copytree(PUBLISHED_DIR, d)
        changed = set()
        for name, new in mutations:
            if new != (d / name).read_bytes():
                changed.add(name)
            (d / name).write_bytes(new)
        changed = {n for n in changed if (d / n).read_bytes() != (PUBLISHED_DIR / n).read_bytes()}
        if changed:
            with pytest.raises(pub.PublishedDataError) as exc:
                pub.verify_manifest(d)
            assert all(n in str(exc.value) for n in changed), (str(exc.value), changed)
        else:
            pub.verify_manifest(d)
        try:
            pub.load(d)
        except pub.PublishedDataError as e:
            assert any(n in str(e) for n in changed), (str(e), changed)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(mutation(), min_size=1, max_size=2))
def test_mutated_published_data_is_caught_naming_the_file(mutations):
    _check(mutations)


@pytest.mark.slow
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(mutation(), min_size=1, max_size=4))
def test_mutated_published_data_is_caught_naming_the_file_long(mutations):
    _check(mutations)
