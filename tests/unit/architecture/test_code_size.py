"""Size limits of the code: no function above 80 lines of code and no source
file above 900 lines, in the library (src/gearrep) and the workflow scripts (workflow/scripts).

Lines of code of a function, as counted here: the lines from its ``def`` line (decorators not
included) to its last line, less blank lines, lines whose first non-blank character is ``#``, and
the lines of docstrings (its own and those of the functions and classes nested in it). A nested
function counts in the function around it and is also measured on its own. A file's lines are all
its lines.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from conftest import ROOT

MAX_FUNCTION_LOC = 80
MAX_FILE_LINES = 900
SOURCES = sorted((ROOT / "src" / "gearrep").rglob("*.py")) + sorted((ROOT / "workflow" / "scripts").glob("*.py"))


_SCOPES = (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)


def _docstring_lines(tree: ast.AST) -> set[int]:
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, _SCOPES) and node.body:
            first = node.body[0]
            if (
                isinstance(first, ast.Expr)
                and isinstance(first.value, ast.Constant)
                and isinstance(first.value.value, str)
            ):
                out |= set(range(first.lineno, first.end_lineno + 1))
    return out


def function_sizes(source: str) -> dict[str, int]:
    """{qualified name: lines of code} of every function in ``source`` (counted as the module
    docstring states); nested names are dotted (``outer.inner``, ``Class.method``)."""
    tree = ast.parse(source)
    lines = source.splitlines()
    doc = _docstring_lines(tree)
    sizes = {}

    def visit(node, prefix):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                name = f"{prefix}{child.name}"
                if not isinstance(child, ast.ClassDef):
                    span = range(child.lineno, child.end_lineno + 1)
                    sizes[name] = sum(
                        1
                        for i in span
                        if i not in doc and lines[i - 1].strip() and not lines[i - 1].lstrip().startswith("#")
                    )
                visit(child, name + ".")
            else:
                visit(child, prefix)

    visit(tree, "")
    return sizes


def _long_functions() -> dict[str, int]:
    out = {}
    for path in SOURCES:
        rel = path.relative_to(ROOT).as_posix()
        for name, n in function_sizes(path.read_text(encoding="utf-8")).items():
            if n > MAX_FUNCTION_LOC:
                out[f"{rel}:{name}"] = n
    return out


def test_the_counting_rule():
    source = '''
@decorator
def f(x):
    """Docstring,
    two lines."""
    # a comment

    y = x + 1  # code with a comment

    def g():
        """Nested docstring."""
        return y

    class K:
        """Class docstring."""

        def m(self):
            return 1

    return (
        g()
    )
'''
    assert function_sizes(source) == {"f": 10, "f.g": 2, "f.K.m": 2}


def test_no_function_above_80_lines_of_code():
    over = _long_functions()
    assert not over, f"functions above {MAX_FUNCTION_LOC} lines of code (split them): {over}"


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_no_source_file_above_900_lines(path: Path):
    n = len(path.read_text(encoding="utf-8").splitlines())
    assert n <= MAX_FILE_LINES, f"{path.relative_to(ROOT)}: {n} lines (split it by concern)"
