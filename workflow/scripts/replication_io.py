"""I/O shared by the replications' Snakemake scripts (importable because Snakemake puts the
scripts' directory on sys.path): write a run's tables to the rule's outputs, read tables back,
write a validated check table. The numerics stay in gearrep.replications.<name>."""

import contextlib
import time
import traceback
from pathlib import Path

import pandas as pd

from gearrep import checks


@contextlib.contextmanager
def logged(log: str):
    """Run the block; on failure write the traceback to the job's log (Snakemake points the user
    there) before re-raising."""
    Path(log).parent.mkdir(parents=True, exist_ok=True)
    try:
        yield
    except BaseException:
        with open(log, "a") as f:
            f.write(traceback.format_exc())
        raise


def save_figure(fig, path) -> None:
    """Write a matplotlib figure (format from the file name, the gearrep style's dpi and tight box;
    directories made as needed) and close it."""
    import matplotlib.pyplot as plt

    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path)
    plt.close(fig)


def timed(fn, *args):
    """(seconds, fn(*args))."""
    t0 = time.perf_counter()
    out = fn(*args)
    return time.perf_counter() - t0, out


def write_table(table: pd.DataFrame, path: str, float_format=None) -> None:
    """One table as CSV (directories made as needed)."""
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    table.to_csv(path, index=False, float_format=float_format)


def write_tables(tables: dict, outputs, log: str, label: str, seconds: float, float_format=None) -> None:
    """Write ``tables[stem]`` to each output path (named by its file stem); a missing table is an error."""
    expected = {Path(f).stem: f for f in outputs}
    missing = sorted(set(expected) - set(tables))
    if missing:
        raise RuntimeError(f"{label} did not return tables {missing}")
    extra = sorted(set(tables) - set(expected))
    if extra:
        raise RuntimeError(f"{label} returned tables {extra} that are not its outputs")
    for name, path in expected.items():
        write_table(tables[name], path, float_format)
    Path(log).write_text(f"{label}: {seconds:.2f} s; tables: {sorted(expected)}\n")


def read_tables(paths) -> dict:
    """{file stem: DataFrame} of a rule's table inputs."""
    return {Path(f).stem: pd.read_csv(f) for f in paths}


def write_checks(records: pd.DataFrame, path: str, log: str) -> pd.DataFrame:
    """Validate the check records and write them; the log gets the counts by status."""
    records = checks.validate_checks(records)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    records.to_csv(path, index=False)
    Path(log).write_text(f"{len(records)} check records: {records['status'].value_counts().to_dict()}\n")
    return records
