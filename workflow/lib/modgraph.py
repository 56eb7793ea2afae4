"""Which gearrep source files a workflow step imports, directly or in turn.

Snakemake does not track Python code imported by a script, so every rule declares the files of
the gearrep modules its script or notebook imports as inputs; a library change then reruns exactly
the jobs that use it. :class:`ModuleGraph` finds them by parsing import statements (``ast``):
absolute ``gearrep...`` imports and relative imports inside the package, plus the package
``__init__`` files Python runs on the way. Each module is parsed once per graph.
"""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

__all__ = ["ModuleGraph"]


# A line that starts (after indentation) an ``import ...`` or ``from ... import ...`` statement.
_IMPORT_START = re.compile(r"^[ \t]*(?:import|from[ \t]+[\w.]+[ \t]+import)[ \t(\\]", re.MULTILINE)


def _import_nodes(text: str, filename: str) -> list[ast.stmt]:
    """The import statements of ``text``, each parsed alone: a full ``ast.parse`` plus a walk of
    every node costs ~10 ms per module, and the workflow parses ~90 of them at every start. A
    statement is read from a line that starts one, adding lines (parentheses, backslashes) until it
    parses; a prose line in a docstring that never parses is skipped. tests/unit/workflow/test_workflow_lib.py
    checks that this finds exactly the imports of a full parse in every module of the project."""
    if "import" not in text:
        return []
    lines = text.splitlines()
    starts = {text.count("\n", 0, m.start()) for m in _IMPORT_START.finditer(text)}
    nodes = []
    for i in sorted(starts):
        for j in range(i + 1, min(i + 60, len(lines)) + 1):
            try:
                nodes += ast.parse("\n".join(lines[i:j]).strip(), filename).body
                break
            except SyntaxError:
                if j == i + 1 and "(" not in lines[i] and not lines[i].rstrip().endswith("\\"):
                    break
    return nodes


class ModuleGraph:
    """Import graph of the package ``package`` under ``src`` (paths reported relative to ``root``)."""

    def __init__(self, src: Path | str, root: Path | str, package: str = "gearrep"):
        self.root = Path(root).resolve()
        self.package = package
        self.pkg_dir = Path(src).resolve() / package
        self._imports: dict[tuple, list] = {}
        self._files: dict[tuple, Path | None] = {}
        self._script_nodes: dict[Path, list] = {}

    # -- modules -------------------------------------------------------------------------------
    def module_file(self, parts) -> Path | None:
        """The file of module ``package.<parts>`` (a list of names), or None if there is none."""
        key = tuple(parts)
        if key not in self._files:
            f = self.pkg_dir.joinpath(*parts).with_suffix(".py") if parts else self.pkg_dir / "__init__.py"
            if not f.is_file():
                f = self.pkg_dir.joinpath(*parts, "__init__.py")
            self._files[key] = f if f.is_file() else None
        return self._files[key]

    def _parse(self, nodes: list[ast.stmt], package: list[str] | None) -> list[list[str]]:
        """Modules of the package imported by the import statements ``nodes``; ``package`` is the
        importing module's package (for relative imports), None for a script outside the package."""
        found = []
        for node in nodes:
            if isinstance(node, ast.Import):
                found += [a.name.split(".")[1:] for a in node.names if a.name.split(".")[0] == self.package]
            elif isinstance(node, ast.ImportFrom):
                if node.level and package is not None:
                    base = package[: len(package) - (node.level - 1)] + (node.module.split(".") if node.module else [])
                elif not node.level and node.module and node.module.split(".")[0] == self.package:
                    base = node.module.split(".")[1:]
                else:
                    continue
                found.append(base)
                found += [base + [a.name] for a in node.names if self.module_file(base + [a.name])]
        return [m for m in found if self.module_file(m)]

    def imports(self, parts) -> list[list[str]]:
        """Modules directly imported by module ``parts``."""
        key = tuple(parts)
        if key not in self._imports:
            f = self.module_file(list(parts))
            package = list(parts) if f.name == "__init__.py" else list(parts[:-1])
            self._imports[key] = self._parse(_import_nodes(f.read_text(), str(f)), package)
        return self._imports[key]

    def closure(self, *modules: str) -> list[str]:
        """Files (relative to ``root``) of the dotted ``modules`` (without the package prefix),
        of everything they import in turn, and of the package ``__init__`` files on the way."""
        seen, todo = set(), [m.split(".") if m else [] for m in modules]
        while todo:
            parts = todo.pop()
            if self.module_file(parts) is None:
                raise ValueError(f"no module {self.package}.{'.'.join(parts)} under {self.pkg_dir.parent}")
            key = tuple(parts)
            if key in seen:
                continue
            seen.add(key)
            todo += [parts[:i] for i in range(len(parts))] + self.imports(parts)
        return sorted(str(self.module_file(list(k)).relative_to(self.root)) for k in seen)

    # -- scripts and notebooks -----------------------------------------------------------------
    def _source_nodes(self, path: Path) -> list[ast.stmt]:
        """The import statements of a script, or of a notebook's code cells (without magics and
        shell lines); each file read and parsed once per graph."""
        if path not in self._script_nodes:
            self._script_nodes[path] = _import_nodes(self._source_text(path), str(path))
        return self._script_nodes[path]

    @staticmethod
    def _source_text(path: Path) -> str:
        """The code of a script, or of a notebook's code cells (without magics and shell lines)."""
        text = path.read_text()
        if path.suffix == ".ipynb":
            cells = json.loads(text)["cells"]
            text = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
            text = "\n".join(ln for ln in text.splitlines() if not ln.lstrip().startswith(("%", "!")))
        return text

    def source_files(self, path: Path | str) -> list[Path]:
        """The script or notebook ``path`` and the scripts beside it that it imports, in turn (e.g.
        ``workflow/scripts/replication_io.py``: importable because Snakemake puts the
        scripts' directory on ``sys.path``)."""
        path = Path(path)
        seen, todo = [], [path]
        while todo:
            f = todo.pop()
            if f in seen:
                continue
            seen.append(f)
            for node in self._source_nodes(f):
                names = [a.name for a in node.names] if isinstance(node, ast.Import) else []
                if isinstance(node, ast.ImportFrom) and not node.level and node.module:
                    names = [node.module]
                for name in names:
                    sibling = f.parent / f"{name.split('.')[0]}.py"
                    if sibling.is_file():
                        todo.append(sibling)
        return seen

    def source_modules(self, path: Path | str) -> list[str]:
        """Dotted names of the package modules a script (.py) or notebook (.ipynb) imports, itself
        or through the scripts beside it that it imports (:meth:`source_files`)."""
        return self._modules_of(self.source_files(path))

    def _modules_of(self, files: list[Path]) -> list[str]:
        return sorted({".".join(m) for f in files for m in self._parse(self._source_nodes(f), None)})

    def source_closure(self, path: Path | str, *extra: str) -> list[str]:
        """:meth:`closure` of what a script or notebook imports (plus ``extra`` modules it imports
        dynamically), and the files of the scripts beside it that it imports."""
        files = self.source_files(path)
        scripts = [str(f.resolve().relative_to(self.root)) for f in files[1:]]
        return self.closure(*self._modules_of(files), *extra) + sorted(scripts)
