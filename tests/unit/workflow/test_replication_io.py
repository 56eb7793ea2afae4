"""workflow/scripts/replication_io.py: the I/O of the generic job and check scripts."""

import sys

import pandas as pd
import pytest
from conftest import ROOT

sys.path.insert(0, str(ROOT / "workflow" / "scripts"))

import replication_io  # noqa: E402


def test_a_failed_job_leaves_its_traceback_in_the_log(tmp_path):
    """Snakemake points the user to the job's log, so the log holds the traceback."""
    log = tmp_path / "logs" / "job.log"
    with pytest.raises(ZeroDivisionError):
        with replication_io.logged(str(log)):
            raise ZeroDivisionError("a failing job")
    text = log.read_text()
    assert "Traceback" in text and "ZeroDivisionError" in text


def test_tables_are_written_exactly_as_declared(tmp_path):
    out = [str(tmp_path / "a.csv"), str(tmp_path / "sub" / "b.csv")]
    t = {"a": pd.DataFrame({"x": [0.1, 1 / 3]}), "b": pd.DataFrame({"y": [1]})}
    replication_io.write_tables(t, out, str(tmp_path / "log"), "demo", 0.5)
    back = replication_io.read_tables(out)
    assert back["a"]["x"].tolist() == [0.1, 1 / 3]  # full precision round trip
    with pytest.raises(RuntimeError, match="did not return tables"):
        replication_io.write_tables({"a": t["a"]}, out, str(tmp_path / "log"), "demo", 0.5)
    with pytest.raises(RuntimeError, match="not its outputs"):
        replication_io.write_tables({**t, "c": t["a"]}, out, str(tmp_path / "log"), "demo", 0.5)
