# Shared helpers for the rules: library modules as inputs, published-data files.
from pathlib import Path

PUBLISHED_DIR = config["published_dir"]


def lib(*modules):
    """Paths of gearrep modules a rule imports, declared as inputs so that a library change
    reruns exactly the jobs that use it (Snakemake does not track imported code)."""
    return [f"src/gearrep/{m.replace('.', '/')}.py" for m in modules]


def published_files(pattern="*.csv"):
    return sorted(str(p) for p in Path(PUBLISHED_DIR).glob(pattern))


def figure(path, replication):
    """A figure output flagged for `snakemake --report` under the replication's category."""
    return report(path, caption="../report/figure.rst", category=replication)
