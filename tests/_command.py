"""The `gearrep` command run in the test's process, and design files written for it."""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

import yaml

from gearrep.cli import main


def run(*argv) -> tuple[int, str, str]:
    """``gearrep argv...`` in this process: (exit code, standard output, standard error)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in argv])
    return rc, out.getvalue(), err.getvalue()


def write(tmp_path, name, doc) -> Path:
    """``doc`` written as the YAML design file ``tmp_path/name``; its path."""
    p = tmp_path / name
    p.write_text(yaml.safe_dump(doc, sort_keys=False))
    return p
