"""The manifest of data/published: the shipped manifest matches the shipped files, and a copy of
the directory that lost, emptied, cut, grew, altered or gained a file is refused naming it."""

import csv
import io
import shutil
import subprocess
import sys

import pandas as pd
import pytest
from conftest import PUBLISHED_DIR, ROOT

from gearrep import published as pub

#: the file the issue deleted by hand (scorecard 847 -> 781 rows without a word)
VICTIM = "values_000_T5.4.csv"


@pytest.fixture
def data(tmp_path):
    """A private copy of data/published with its manifest."""
    return shutil.copytree(PUBLISHED_DIR, tmp_path / "published")


def _lines(path):
    return path.read_text(encoding="utf-8").splitlines(keepends=True)


def _refused(directory, *expected):
    with pytest.raises(pub.PublishedDataError) as err:
        pub.verify_manifest(directory)
    msg = str(err.value)
    for part in expected:
        assert part in msg, msg
    return msg


def test_shipped_manifest_matches_shipped_data():
    m = pub.verify_manifest(PUBLISHED_DIR)
    assert m.equals(pub.build_manifest(PUBLISHED_DIR))
    on_disk = {p.name for p in PUBLISHED_DIR.glob("*.csv")} - {pub.MANIFEST_NAME}
    assert set(m["file"]) == on_disk


def test_manifest_counts_agree_with_the_loader(published):
    m = pub.read_manifest(PUBLISHED_DIR)
    per_kind = m.groupby("kind")["rows"].sum()
    assert per_kind["values"] == len(published.values)
    assert per_kind["params"] == len(published.params)
    assert per_kind["claims"] == len(published.claims)
    scored = pd.concat([published.values["seed"], published.claims["seed"]]).value_counts()
    assert pub.scored_rows_per_seed(m) == {s: int(scored.get(s, 0)) for s in pub.SEEDS}


def test_missing_file_is_named(data):
    (data / VICTIM).unlink()
    _refused(data, VICTIM, "missing")


def test_emptied_file_is_named(data):
    (data / VICTIM).write_bytes(b"")
    _refused(data, VICTIM, "emptied")


def test_header_only_file_is_named(data):
    path = data / VICTIM
    path.write_text(_lines(path)[0], encoding="utf-8")
    _refused(data, VICTIM, "cut to its header row")


def test_dropped_row_is_named_with_the_seed(data):
    path = data / VICTIM
    lines = _lines(path)
    path.write_text("".join(lines[:-1]), encoding="utf-8")
    n = len(lines) - 1
    _refused(data, VICTIM, f"shrunk from {n} to {n - 1} rows", f"seed 000 {n} -> {n - 1}")


def test_added_row_is_named(data):
    path = data / VICTIM
    lines = _lines(path)
    path.write_text("".join(lines + [lines[-1]]), encoding="utf-8")
    _refused(data, VICTIM, "grown")


def test_altered_value_is_named(data):
    path = data / VICTIM
    lines = _lines(path)
    header = next(csv.reader([lines[0]]))
    first = next(csv.reader([lines[1]]))
    first[header.index("value")] += "1"
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerow(first)
    path.write_text("".join([lines[0], out.getvalue(), *lines[2:]]), encoding="utf-8")
    _refused(data, VICTIM, "altered", "same")


def test_unlisted_file_is_named(data):
    shutil.copy(data / VICTIM, data / "values_000_extra.csv")
    _refused(data, "values_000_extra.csv", "not listed")


def test_csv_the_loader_would_ignore_is_named(data):
    (data / "value_000_typo.csv").write_text("id,seed\n", encoding="utf-8")
    _refused(data, "value_000_typo.csv", "not listed")
    with pytest.raises(pub.PublishedDataError, match="value_000_typo.csv.*load\\(\\) would ignore it"):
        pub.build_manifest(data)


def test_every_problem_is_reported_at_once(data):
    (data / VICTIM).unlink()
    (data / "claims_004.csv").write_bytes(b"")
    msg = _refused(data, VICTIM, "claims_004.csv")
    assert "--write-manifest" in msg, "the message says how to accept a deliberate change"


def test_missing_manifest_is_named(data):
    (data / pub.MANIFEST_NAME).unlink()
    _refused(data, pub.MANIFEST_NAME, "--write-manifest")


def test_missing_directory_is_named(tmp_path):
    _refused(tmp_path / "nowhere", "nowhere", "does not exist")


def test_rewriting_the_manifest_accepts_a_deliberate_change(data):
    path = data / VICTIM
    path.write_text("".join(_lines(path)[:-1]), encoding="utf-8")
    before = pub.read_manifest(data)
    pub.write_manifest(data)
    after = pub.verify_manifest(data)
    changed = after.merge(before, on="file", suffixes=("", "_old")).query("sha256 != sha256_old")
    assert list(changed["file"]) == [VICTIM]
    assert int(changed["rows"].iloc[0]) == int(changed["rows_old"].iloc[0]) - 1


def test_command_line_writes_and_verifies(data):
    env_cmd = [sys.executable, "-m", "gearrep.published"]
    env = {"PYTHONPATH": str(ROOT / "src"), "PATH": "/usr/bin:/bin"}
    (data / pub.MANIFEST_NAME).unlink()
    done = subprocess.run([*env_cmd, "--write-manifest", str(data)], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    assert (data / pub.MANIFEST_NAME).read_bytes() == (PUBLISHED_DIR / pub.MANIFEST_NAME).read_bytes()
    (data / VICTIM).unlink()
    done = subprocess.run([*env_cmd, "--verify", str(data)], capture_output=True, text=True, env=env)
    assert done.returncode == 1
    assert VICTIM in done.stderr and "Traceback" not in done.stderr


def test_blank_line_is_no_row_but_still_a_change(data):
    path = data / VICTIM
    path.write_text(path.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    assert pub.file_entry(path)["rows"] == pub.read_manifest(data).set_index("file").loc[VICTIM, "rows"]
    _refused(data, VICTIM, "altered")


def test_non_utf8_file_is_named(data):
    (data / VICTIM).write_bytes((data / VICTIM).read_bytes() + b"\xff\n")
    _refused(data, VICTIM, "unreadable", "UTF-8")
