"""Sphinx configuration of gearrep's API reference (``make docs``; warnings are errors)."""

import re

import gearrep

project = "gearrep"
author = "gearrep contributors"
release = version = gearrep.__version__
copyright = "gearrep contributors, MIT licence"

extensions = ["sphinx.ext.autodoc", "numpydoc"]

# the public face of each module: its ``__all__``, in source order, with the docstrings' numpydoc
# sections rendered; class members listed by autodoc (numpydoc's own member tables need stub pages)
autodoc_default_options = {"members": True, "member-order": "bysource", "show-inheritance": True}
autodoc_typehints = "none"
autodoc_preserve_defaults = True
numpydoc_show_class_members = False
numpydoc_attributes_as_param_list = True
add_module_names = False

html_theme = "alabaster"
html_theme_options = {"description": "Gear tooth contact analysis, tested and reproducible", "fixed_sidebar": True}
html_static_path = []
exclude_patterns = ["_build"]

# The docstrings write a norm as |x| (plain text, as read in the source); reStructuredText would
# take |x| for a substitution. Outside inline literals and doctest lines a bar is literal text.
_LITERAL = re.compile(r"(``.*?``)")


def _bars_as_text(app, what, name, obj, options, lines):
    for i, line in enumerate(lines):
        if "|" not in line or line.lstrip().startswith((">>>", "...")):
            continue
        parts = _LITERAL.split(line)
        lines[i] = "".join(p if p.startswith("``") else p.replace("|", r"\|") for p in parts)


def setup(app):
    app.connect("autodoc-process-docstring", _bars_as_text)
