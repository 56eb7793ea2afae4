"""nbformat's validators of the current notebook format, compiled on import. The warm process
imports this module for the notebook steps (``NOTEBOOK_MODULES`` and ``RENDER_MODULES`` in
workflow/rules/common.smk), so that every step that reads or writes a notebook (five executions,
five renderings) inherits them: nbformat compiles each with fastjsonschema (0.05-0.08 s of CPU) the
first time a process validates a notebook, and keeps it in ``nbformat.validator.validators``.
Executing a notebook validates with the strict schema; rendering one also with the relaxed one
(additional properties allowed)."""

from __future__ import annotations

from nbformat import current_nbformat, validator

#: the validators compiled here (relax_add_props False and True)
COMPILED = tuple(validator.get_validator(current_nbformat, relax_add_props=relax) for relax in (False, True))
