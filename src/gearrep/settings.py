"""Numerical settings declared once: value, allowed range, unit and reason.

A replication (or any other user of the library) declares its settings as a mapping of names to
:class:`Setting` records made by :func:`number`, :func:`integer`, :func:`choice`, :func:`flag`,
:func:`array` and :func:`group`. Everything else follows from that one declaration:

- :func:`resolve` merges overrides (a config section, a test configuration) over the declared
  values and checks every one of them: unknown keys are refused with the closest declared name,
  NaN and infinity are refused, numbers must lie in their range, strings among their choices;
- :func:`json_schema` is the JSON schema of the overrides (``config/schema.json`` is generated
  from it, and a test keeps the file equal to it);
- :func:`rows` lists name, value, unit, allowed range and reason for documentation.

Every error is a :class:`SettingError` (a ``ValueError``) naming the key, the value and the
allowed range. This module reads no files.
"""

from __future__ import annotations

import copy
import difflib
import math
import reprlib
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

__all__ = [
    "Setting",
    "SettingError",
    "number",
    "integer",
    "choice",
    "flag",
    "text",
    "array",
    "group",
    "declare",
    "defaults",
    "resolve",
    "json_schema",
    "rows",
    "closest",
]


class SettingError(ValueError):
    """A setting or override that is not allowed; the message names the key, value and range.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> decl = S.declare(
    ...     tol=S.number(1e-10, "mm", "residual tolerance of the contact solves", gt=0, le=1e-3),
    ...     n=S.integer(41, "1", "angles per meshing cycle", ge=5),
    ...     grid=S.group("the start grid", steps=S.integer(10, "1", "grid steps per side", ge=1)),
    ... )
    >>> S.resolve(decl, {"tol": 1.0}, where="config.study")
    Traceback (most recent call last):
        ...
    gearrep.settings.SettingError: config.study.tol: got 1.0; allowed: a finite number in (0, 0.001] mm
    """


@dataclass(frozen=True)
class Setting:
    """One declared setting. ``kind`` is number, integer, string, boolean, array or group.

    Made by :func:`number`, :func:`integer`, :func:`choice`, :func:`flag`, :func:`text`,
    :func:`array` or :func:`group`, not directly.

    Attributes
    ----------
    value : object
        The declared value.
    unit : str
        Its unit ('1' for counts, '' where none applies).
    reason : str
        Why this value.
    kind : str
        number, integer, string, boolean, array or group.
    ge, le, gt, lt : float or None
        Inclusive and exclusive bounds.
    choices : tuple or None
        The allowed strings.
    item : Setting or None
        The setting every element of an array satisfies.
    min_items, max_items : int or None
        Length limits of an array.
    fields : Mapping or None
        The settings of a group.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.number(1e-10, "mm", "residual tolerance", gt=0, le=1e-3).allowed()
    'a finite number in (0, 0.001] mm'
    """

    value: Any
    unit: str
    reason: str
    kind: str
    ge: float | None = None
    le: float | None = None
    gt: float | None = None
    lt: float | None = None
    choices: tuple | None = None
    item: Setting | None = None
    min_items: int = 0
    max_items: int | None = None
    fields: Mapping[str, Setting] | None = field(default=None)

    def allowed(self) -> str:
        """The allowed values in words (used in every error message).

        Returns
        -------
        str
            E.g. 'a finite number in (0, 0.001] mm'.
        """
        if self.kind in ("number", "integer"):
            lo = f"[{self.ge:g}" if self.ge is not None else (f"({self.gt:g}" if self.gt is not None else "(-inf")
            hi = f"{self.le:g}]" if self.le is not None else (f"{self.lt:g})" if self.lt is not None else "inf)")
            what = "a finite number" if self.kind == "number" else "an integer"
            unit = f" {self.unit}" if self.unit and self.unit != "1" else ""
            return f"{what} in {lo}, {hi}{unit}"
        if self.kind == "string":
            return f"one of {list(self.choices)}" if self.choices else "a string"
        if self.kind == "boolean":
            return "true or false"
        if self.kind == "array":
            n = f"{self.min_items}..{self.max_items if self.max_items is not None else 'any'}"
            return f"a list of {n} items, each {self.item.allowed()}"
        return f"a mapping with keys {sorted(self.fields)}"


def _range(ge=None, le=None, gt=None, lt=None) -> dict:
    return {"ge": ge, "le": le, "gt": gt, "lt": lt}


def number(value, unit: str, reason: str, *, ge=None, le=None, gt=None, lt=None) -> Setting:
    """A finite real number in the given range (``ge``/``le`` inclusive, ``gt``/``lt`` exclusive).

    Parameters
    ----------
    value : float
        The declared value.
    unit : str
        Its unit.
    reason : str
        Why this value (shown in the tables and the schema).
    ge, le, gt, lt : float, optional
        Inclusive and exclusive bounds.

    Returns
    -------
    Setting
        The declaration.

    Raises
    ------
    SettingError
        If the declared value is not allowed or the reason is empty.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.number(0.5, "mm", "face-width margin", ge=0).allowed()
    'a finite number in [0, inf) mm'
    """
    return _checked(Setting(value, unit, reason, "number", **_range(ge, le, gt, lt)))


def integer(value, unit: str, reason: str, *, ge=None, le=None) -> Setting:
    """An integer in [ge, le].

    Parameters
    ----------
    value : int
        The declared value.
    unit : str
        Its unit ('1' for counts).
    reason : str
        Why this value (shown in the tables and the schema).
    ge, le : int, optional
        Inclusive bounds.

    Returns
    -------
    Setting
        The declaration.

    Raises
    ------
    SettingError
        If the declared value is not allowed or the reason is empty.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.integer(41, "1", "angles per cycle", ge=5).allowed()
    'an integer in [5, inf)'
    """
    return _checked(Setting(value, unit, reason, "integer", ge=ge, le=le))


def choice(value, choices, reason: str) -> Setting:
    """One string of ``choices``.

    Parameters
    ----------
    value : str
        The declared value.
    choices : iterable of str
        The allowed strings.
    reason : str
        Why this value (shown in the tables and the schema).

    Returns
    -------
    Setting
        The declaration.

    Raises
    ------
    SettingError
        If the declared value is not allowed or the reason is empty.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.choice("reduced", ("reduced", "conventional"), "the faster formulation").allowed()
    "one of ['reduced', 'conventional']"
    """
    return _checked(Setting(value, "", reason, "string", choices=tuple(choices)))


def text(value, reason: str) -> Setting:
    """Any non-empty string (a name or a path).

    Parameters
    ----------
    value : str
        The declared value.
    reason : str
        Why this value (shown in the tables and the schema).

    Returns
    -------
    Setting
        The declaration.

    Raises
    ------
    SettingError
        If the declared value is not allowed or the reason is empty.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.text("results", "output folder").kind
    'string'
    """
    return _checked(Setting(value, "", reason, "string"))


def flag(value, reason: str) -> Setting:
    """True or False.

    Parameters
    ----------
    value : bool
        The declared value.
    reason : str
        Why this value (shown in the tables and the schema).

    Returns
    -------
    Setting
        The declaration.

    Raises
    ------
    SettingError
        If the declared value is not allowed or the reason is empty.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.flag(True, "draw the figures").kind
    'boolean'
    """
    return _checked(Setting(value, "", reason, "boolean"))


def array(value, unit: str, reason: str, item: Setting, *, min_items: int = 1, max_items=None) -> Setting:
    """A list whose every element satisfies ``item`` (a setting made with value None).

    Parameters
    ----------
    value : list
        The declared value.
    unit : str
        Unit of the elements.
    reason : str
        Why this value (shown in the tables and the schema).
    item : Setting
        What every element satisfies (made with value None).
    min_items, max_items : int, optional
        Length limits.

    Returns
    -------
    Setting
        The declaration.

    Raises
    ------
    SettingError
        If the declared value is not allowed or the reason is empty.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.array([0.0, 0.01], "mm", "misalignments", S.number(None, "mm", "", ge=0)).allowed()
    'a list of 1..any items, each a finite number in [0, inf) mm'
    """
    return _checked(Setting(value, unit, reason, "array", item=item, min_items=min_items, max_items=max_items))


def group(reason: str, **fields: Setting) -> Setting:
    """A nested block of settings; an override may give any subset of its keys.

    Parameters
    ----------
    reason : str
        What the block is.
    **fields : Setting
        Its settings.

    Returns
    -------
    Setting
        The group.

    Raises
    ------
    TypeError
        If a field is not a Setting or there is none.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> S.group("the start grid", steps=S.integer(10, "1", "steps", ge=1)).kind
    'group'
    """
    if not fields or not all(isinstance(f, Setting) for f in fields.values()):
        raise TypeError("group() takes keyword Settings")
    return Setting({k: f.value for k, f in fields.items()}, "", reason, "group", fields=dict(fields))


def declare(**settings: Setting) -> dict[str, Setting]:
    """The declaration of a study's settings (checked: every value lies in its own range).

    Parameters
    ----------
    **settings : Setting
        Name -> declaration.

    Returns
    -------
    dict
        Name -> Setting.

    Raises
    ------
    TypeError
        If a value is not a Setting.
    SettingError
        If a setting has no reason.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> decl = S.declare(
    ...     tol=S.number(1e-10, "mm", "residual tolerance of the contact solves", gt=0, le=1e-3),
    ...     n=S.integer(41, "1", "angles per meshing cycle", ge=5),
    ...     grid=S.group("the start grid", steps=S.integer(10, "1", "grid steps per side", ge=1)),
    ... )
    >>> sorted(decl)
    ['grid', 'n', 'tol']
    """
    for name, s in settings.items():
        if not isinstance(s, Setting):
            raise TypeError(f"setting {name!r} is not a Setting")
    return dict(settings)


def _checked(s: Setting) -> Setting:
    if s.value is not None:
        _coerce(s, s.value, "declared value")
    if s.kind != "group" and s.value is not None and not s.reason:
        raise SettingError("every declared setting needs its reason")
    return s


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _coerce(s: Setting, v, key: str):
    """``v`` checked against ``s`` (ints for integer settings, floats for numbers, lists for arrays)."""
    bad = SettingError(f"{key}: got {v!r}; allowed: {s.allowed()}")
    if s.kind in ("number", "integer"):
        if not _is_number(v):
            raise bad
        try:
            finite = math.isfinite(v)
        except OverflowError:  # an int beyond float range: outside every declared range
            finite = False
        if not finite:
            raise bad
        if s.kind == "integer":
            if v != int(v):
                raise bad
            v = int(v)
        else:
            v = float(v)
        if (s.ge is not None and v < s.ge) or (s.le is not None and v > s.le):
            raise bad
        if (s.gt is not None and not v > s.gt) or (s.lt is not None and not v < s.lt):
            raise bad
        return v
    if s.kind == "string":
        if not isinstance(v, str) or not v or (s.choices and v not in s.choices):
            raise bad
        return v
    if s.kind == "boolean":
        if not isinstance(v, bool):
            raise bad
        return v
    if s.kind == "array":
        if not isinstance(v, (list, tuple)):
            raise bad
        if len(v) < s.min_items or (s.max_items is not None and len(v) > s.max_items):
            raise bad
        return [_coerce(s.item, x, f"{key}[{i}]") for i, x in enumerate(v)]
    if s.kind == "group":
        return resolve(s.fields, v, key)
    raise TypeError(f"unknown setting kind {s.kind!r}")


def closest(name: str, known) -> str:
    """' (did you mean X?)' for the closest of ``known`` to ``name``, or '' if none is close.

    Parameters
    ----------
    name : str
        The unknown name.
    known : iterable
        The declared names.

    Returns
    -------
    str
        The hint, or ''.

    Examples
    --------
    >>> from gearrep.settings import closest
    >>> closest("litvin200", ["litvin2000", "ma2021"]), closest("xyz", ["litvin2000"])
    (" (did you mean 'litvin2000'?)", '')
    """
    m = difflib.get_close_matches(str(name), [str(k) for k in known], n=1, cutoff=0.6)
    return f" (did you mean {m[0]!r}?)" if m else ""


def defaults(decl: Mapping[str, Setting]) -> dict:
    """The declared values as a plain (deep-copied) dict.

    Parameters
    ----------
    decl : Mapping
        A declaration (:func:`declare`).

    Returns
    -------
    dict
        Name -> value (groups as dicts).

    Examples
    --------
    >>> from gearrep import settings as S
    >>> decl = S.declare(
    ...     tol=S.number(1e-10, "mm", "residual tolerance of the contact solves", gt=0, le=1e-3),
    ...     n=S.integer(41, "1", "angles per meshing cycle", ge=5),
    ...     grid=S.group("the start grid", steps=S.integer(10, "1", "grid steps per side", ge=1)),
    ... )
    >>> S.defaults(decl)
    {'tol': 1e-10, 'n': 41, 'grid': {'steps': 10}}
    """
    return {k: copy.deepcopy(s.value) for k, s in decl.items()}


def resolve(decl: Mapping[str, Setting], *layers: Mapping | None, where: str = "settings") -> dict:
    """The declared values overridden by each layer in turn, every value checked.

    ``where`` prefixes the key in error messages (e.g. the config section). A layer may be None
    or empty; a group may be overridden in part.

    Parameters
    ----------
    decl : Mapping
        A declaration (:func:`declare`).
    *layers : Mapping or None
        Overrides, applied in order.
    where : str, optional
        Prefix of the keys in error messages.

    Returns
    -------
    dict
        The resolved values.

    Raises
    ------
    SettingError
        For an unknown key (with the closest declared name), a value of the wrong type, NaN,
        infinity or a value out of range: one line naming the key, the value and what is allowed.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> decl = S.declare(
    ...     tol=S.number(1e-10, "mm", "residual tolerance of the contact solves", gt=0, le=1e-3),
    ...     n=S.integer(41, "1", "angles per meshing cycle", ge=5),
    ...     grid=S.group("the start grid", steps=S.integer(10, "1", "grid steps per side", ge=1)),
    ... )
    >>> S.resolve(decl, {"tol": 1e-9}, None, {"grid": {"steps": 4}})
    {'tol': 1e-09, 'n': 41, 'grid': {'steps': 4}}
    >>> S.resolve(decl, {"tl": 1e-9}, where="config.study")
    Traceback (most recent call last):
        ...
    gearrep.settings.SettingError: config.study.tl: unknown setting (did you mean 'tol'?), got 1e-09; declared: ['grid', 'n', 'tol']
    """
    out = defaults(decl)
    for layer in layers:
        if layer is None:
            continue
        if not isinstance(layer, Mapping):
            raise SettingError(f"{where}: got {layer!r}; allowed: a mapping of settings {sorted(decl)}")
        for k, v in layer.items():
            key = f"{where}.{k}"
            if k not in decl:
                raise SettingError(
                    f"{key}: unknown setting{closest(k, decl)}, got {reprlib.repr(v)}; declared: {sorted(decl)}"
                )
            s = decl[k]
            if s.kind == "group":
                if not isinstance(v, Mapping):
                    raise SettingError(f"{key}: got {v!r}; allowed: {s.allowed()}")
                # the values so far as the first layer, without the unset (None: required) ones
                so_far = {kk: vv for kk, vv in out[k].items() if vv is not None}
                out[k] = resolve(s.fields, so_far, v, where=key)
            else:
                out[k] = _coerce(s, v, key)
    return out


def json_schema(decl: Mapping[str, Setting], description: str = "") -> dict:
    """JSON schema (draft 2020-12 subset) of an override block of ``decl``: every key optional,
    unknown keys refused, ranges and choices as declared; the description carries unit and reason.

    Parameters
    ----------
    decl : Mapping
        A declaration (:func:`declare`).
    description : str, optional
        The block's description.

    Returns
    -------
    dict
        The schema.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> decl = S.declare(
    ...     tol=S.number(1e-10, "mm", "residual tolerance of the contact solves", gt=0, le=1e-3),
    ...     n=S.integer(41, "1", "angles per meshing cycle", ge=5),
    ...     grid=S.group("the start grid", steps=S.integer(10, "1", "grid steps per side", ge=1)),
    ... )
    >>> S.json_schema(decl)["properties"]["tol"]
    {'type': 'number', 'maximum': 0.001, 'exclusiveMinimum': 0, 'description': 'residual tolerance of the contact solves [mm]', 'default': 1e-10}
    """
    props = {k: _schema_of(s) for k, s in decl.items()}
    out = {"type": "object"}
    if description:
        out["description"] = description
    out.update({"properties": props, "additionalProperties": False})
    return out


def _schema_of(s: Setting) -> dict:
    if s.kind == "group":
        return json_schema(s.fields, s.reason)
    d: dict = {}
    if s.kind in ("number", "integer"):
        d["type"] = s.kind
        for ours, theirs in (
            ("ge", "minimum"),
            ("le", "maximum"),
            ("gt", "exclusiveMinimum"),
            ("lt", "exclusiveMaximum"),
        ):
            if getattr(s, ours) is not None:
                d[theirs] = getattr(s, ours)
    elif s.kind == "string":
        d["type"] = "string"
        if s.choices:
            d["enum"] = list(s.choices)
    elif s.kind == "boolean":
        d["type"] = "boolean"
    elif s.kind == "array":
        d["type"] = "array"
        d["items"] = _schema_of(s.item)
        if s.min_items:
            d["minItems"] = s.min_items
        if s.max_items is not None:
            d["maxItems"] = s.max_items
    if s.value is not None:
        unit = f" [{s.unit}]" if s.unit and s.unit != "1" else ""
        d["description"] = f"{s.reason}{unit}"
        d["default"] = copy.deepcopy(s.value)
    return d


def rows(decl: Mapping[str, Setting], prefix: str = "") -> list[dict]:
    """One row per setting (groups flattened with dotted names): name, value, unit, allowed, reason.

    Parameters
    ----------
    decl : Mapping
        A declaration (:func:`declare`).
    prefix : str, optional
        Prefix of the names.

    Returns
    -------
    list of dict
        One row per setting.

    Examples
    --------
    >>> from gearrep import settings as S
    >>> decl = S.declare(
    ...     tol=S.number(1e-10, "mm", "residual tolerance of the contact solves", gt=0, le=1e-3),
    ...     n=S.integer(41, "1", "angles per meshing cycle", ge=5),
    ...     grid=S.group("the start grid", steps=S.integer(10, "1", "grid steps per side", ge=1)),
    ... )
    >>> [(r["name"], r["allowed"]) for r in S.rows(decl)]
    [('tol', 'a finite number in (0, 0.001] mm'), ('n', 'an integer in [5, inf)'), ('grid.steps', 'an integer in [1, inf)')]
    """
    out = []
    for k, s in decl.items():
        if s.kind == "group":
            out += rows(s.fields, f"{prefix}{k}.")
        else:
            out.append(
                {"name": f"{prefix}{k}", "value": s.value, "unit": s.unit, "allowed": s.allowed(), "reason": s.reason}
            )
    return out
