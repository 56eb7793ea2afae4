# Shared helpers for the rules: library modules as inputs, published-data files.
from pathlib import Path

PUBLISHED_DIR = config["published_dir"]


import ast

_SRC = Path(workflow.basedir, "src", "gearrep")


def _module_file(parts):
    """The file of gearrep module `parts` (list of names), or None if there is none."""
    f = _SRC.joinpath(*parts).with_suffix(".py") if parts else _SRC / "__init__.py"
    if f.is_file():
        return f
    f = _SRC.joinpath(*parts, "__init__.py")
    return f if f.is_file() else None


_IMPORTS = {}


def _gearrep_imports(parts):
    """gearrep modules imported by module `parts` (absolute and relative imports); parsed once."""
    key = tuple(parts)
    if key not in _IMPORTS:
        _IMPORTS[key] = _parse_gearrep_imports(list(parts))
    return _IMPORTS[key]


def _parse_gearrep_imports(parts):
    f = _module_file(parts)
    is_pkg = f.name == "__init__.py"
    package = list(parts) if is_pkg else list(parts[:-1])
    found = []
    text = f.read_text()
    if "import" not in text:
        return []
    for node in ast.walk(ast.parse(text, str(f))):
        if isinstance(node, ast.Import):
            found += [a.name.split(".")[1:] for a in node.names if a.name.split(".")[0] == "gearrep"]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - (node.level - 1)] + (node.module.split(".") if node.module else [])
            elif node.module and node.module.split(".")[0] == "gearrep":
                base = node.module.split(".")[1:]
            else:
                continue
            found.append(base)
            found += [base + [a.name] for a in node.names if _module_file(base + [a.name])]
    return [m for m in found if _module_file(m)]


def lib(*modules):
    """Paths of the gearrep modules a rule imports AND of everything they import in turn (plus the
    package __init__ files Python runs on the way), declared as inputs so that a library change
    reruns exactly the jobs that use it (Snakemake does not track imported code)."""
    seen, todo = set(), [m.split(".") for m in modules]
    while todo:
        parts = todo.pop()
        if _module_file(parts) is None:
            raise ValueError(f"lib(): no module gearrep.{'.'.join(parts)} under {_SRC}")
        key = tuple(parts)
        if key in seen:
            continue
        seen.add(key)
        todo += [parts[:i] for i in range(len(parts))] + _gearrep_imports(parts)
    return sorted(str(_module_file(list(k)).relative_to(workflow.basedir)) for k in seen)


#: I/O helpers the replications' run and check scripts import (declared as their input)
REPLICATION_IO = "workflow/scripts/replication_io.py"


def published_files(pattern="*.csv"):
    return sorted(str(p) for p in Path(PUBLISHED_DIR).glob(pattern))


def figure(path, replication):
    """A figure output flagged for `snakemake --report` under the replication's category."""
    return report(path, caption="../report/figure.rst", category=replication)
