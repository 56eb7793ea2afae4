"""gearrep.settings: one declaration gives the values, the checks, the schema and the docs."""

import math

import jsonschema
import pytest

from gearrep import settings as S

DECL = S.declare(
    tol=S.number(1e-8, "mm", "Newton residual", gt=0, le=1e-6),
    n=S.integer(5, "count", "points", ge=1, le=10),
    windows=S.array([0.5, 1.0], "rad", "start windows", S.number(None, "rad", "", gt=0, le=2 * math.pi)),
    pairs=S.array(
        [[1.0, 2.0]],
        "mm",
        "radius pairs",
        S.array(None, "mm", "", S.number(None, "mm", "", gt=0), min_items=2, max_items=2),
    ),
    pivot=S.choice("axis", ["axis", "pitch_point"], "misalignment pivot"),
    verbose=S.flag(False, "print progress"),
    block=S.group(
        "a nested block", z=S.integer(21, "1", "teeth", ge=5, le=1000), width=S.number(80.0, "mm", "face width", gt=0)
    ),
)


def test_defaults_and_partial_overrides():
    got = S.resolve(DECL, {"tol": 1e-9}, {"block": {"width": 3}}, where="demo")
    assert got["tol"] == 1e-9 and got["n"] == 5 and got["block"] == {"z": 21, "width": 3.0}
    assert isinstance(got["block"]["width"], float) and isinstance(got["n"], int)
    assert S.resolve(DECL, None, {}) == S.defaults(DECL)
    got["windows"].append(9.0)
    assert DECL["windows"].value == [0.5, 1.0]  # the declaration is never shared with a result


@pytest.mark.parametrize(
    "override, message",
    [
        ({"tol": float("nan")}, r"demo\.tol: got nan; allowed: a finite number in \(0, 1e-06\] mm"),
        ({"tol": float("inf")}, r"demo\.tol: got inf"),
        ({"tol": 0.0}, r"demo\.tol: got 0\.0"),
        ({"n": 2.5}, r"demo\.n: got 2\.5; allowed: an integer in \[1, 10\]"),
        ({"n": True}, r"demo\.n: got True"),
        ({"n": "5"}, r"demo\.n: got '5'"),
        ({"windows": []}, r"demo\.windows: got \[\]; allowed: a list of 1\.\.any items"),
        ({"windows": [1.0, 7.0]}, r"demo\.windows\[1\]: got 7\.0"),
        ({"pairs": [[1.0]]}, r"demo\.pairs\[0\]: got \[1\.0\]"),
        ({"pivot": "centre"}, r"demo\.pivot: got 'centre'; allowed: one of \['axis', 'pitch_point'\]"),
        ({"verbose": 1}, r"demo\.verbose: got 1; allowed: true or false"),
        ({"block": {"width": -1}}, r"demo\.block\.width: got -1"),
        ({"block": 3}, r"demo\.block: got 3"),
        ({"tool": 1e-9}, r"demo\.tool: unknown setting \(did you mean 'tol'\?\)"),
        ({"block": {"widht": 2}}, r"demo\.block\.widht: unknown setting \(did you mean 'width'\?\)"),
    ],
)
def test_bad_overrides_name_key_value_and_range(override, message):
    with pytest.raises(S.SettingError, match=message):
        S.resolve(DECL, override, where="demo")


def test_declaration_is_checked():
    with pytest.raises(S.SettingError, match="declared value: got 2"):
        S.number(2.0, "mm", "too large", le=1.0)
    with pytest.raises(S.SettingError, match="reason"):
        S.integer(3, "1", "")
    with pytest.raises(TypeError):
        S.declare(x=3)


def test_schema_accepts_exactly_what_resolve_accepts():
    schema = S.json_schema(DECL, "demo")
    jsonschema.validate(S.defaults(DECL), schema)
    jsonschema.validate({"block": {"z": 6}}, schema)
    for bad in ({"tol": 0.0}, {"n": 11}, {"pivot": "x"}, {"tool": 1}, {"block": {"w": 1}}, {"windows": []}):
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(bad, schema)
        with pytest.raises(S.SettingError):
            S.resolve(DECL, bad)
    assert schema["properties"]["tol"]["default"] == 1e-8
    assert "Newton residual [mm]" == schema["properties"]["tol"]["description"]


def test_rows_flatten_groups():
    names = [r["name"] for r in S.rows(DECL)]
    assert names == ["tol", "n", "windows", "pairs", "pivot", "verbose", "block.z", "block.width"]
    assert all(r["reason"] and r["allowed"] for r in S.rows(DECL))
