"""Property-based hostile configurations: random mutations of
config/config.yaml (unknown sections and keys, misspelt names, NaN, infinity, negative, huge and
wrongly typed values) either resolve or stop with a SettingError naming the mutated key path,
never with another exception."""

import copy
import sys

import pytest
import yaml
from conftest import ROOT
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(ROOT / "workflow" / "lib"))

import wfconfig  # noqa: E402

from gearrep.settings import SettingError  # noqa: E402

BASE = yaml.safe_load((ROOT / "config" / "config.yaml").read_text()) or {}
DECL = wfconfig.declaration()


def _paths(decl, prefix=()):
    """Every declared key path (groups and their fields)."""
    for k, s in decl.items():
        yield prefix + (k,)
        if s.kind == "group":
            yield from _paths(s.fields, prefix + (k,))


PATHS = sorted(_paths(DECL))


def _setting(path):
    decl, s = DECL, None
    for k in path:
        s = decl[k]
        decl = s.fields or {}
    return s


GROUPS = [()] + [p for p in PATHS if _setting(p).kind == "group"]

HOSTILE = st.one_of(
    st.sampled_from([float("nan"), float("inf"), float("-inf"), -1, -1e-300, 0, 10**400, 1e308, -(10**30)]),
    st.sampled_from([None, True, False, "", "x", "nan", [], [1], {}, {"a": 1}, [float("nan")], ["litvin2000"]]),
    st.integers(),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=8),
    st.lists(st.one_of(st.integers(), st.floats(), st.text(max_size=4)), max_size=3),
    st.dictionaries(st.text(max_size=6), st.one_of(st.integers(), st.floats(), st.none()), max_size=3),
)


def _misspell(draw, name: str) -> str:
    i = draw(st.integers(0, len(name)))
    how = draw(st.sampled_from(["double", "drop", "insert", "swapcase"]))
    if how == "double" and i < len(name):
        return name[:i] + name[i] + name[i:]
    if how == "drop" and len(name) > 1 and i < len(name):
        return name[:i] + name[i + 1 :]
    if how == "swapcase" and name.swapcase() != name:
        return name.swapcase()
    return name[:i] + draw(st.sampled_from("aqz_")) + name[i:]


def _put(config, path, value):
    d = config
    for k in path[:-1]:
        if not isinstance(d.get(k), dict):
            d[k] = {}
        d = d[k]
    d[path[-1]] = value


@st.composite
def mutation(draw):
    """(path named by the error if refused, function applying the mutation to a config dict)."""
    kind = draw(st.sampled_from(["value", "unknown", "misspelt"]))
    if kind == "value":
        path = draw(st.sampled_from(PATHS))
        value = draw(HOSTILE)
        return path, lambda c: _put(c, path, copy.deepcopy(value))
    group = draw(st.sampled_from(GROUPS))
    known = list(DECL if not group else _setting(group).fields)
    if kind == "unknown":
        name = draw(
            st.one_of(st.text(min_size=1, max_size=10), st.integers(), st.sampled_from(["litvin200", "Thesis"]))
        )
        if name in known:
            name = f"{name}_x"
    else:
        name = _misspell(draw, draw(st.sampled_from(known)))
        if name in known:
            name = f"{name}_"
    path = group + (name,)
    value = draw(st.one_of(HOSTILE, st.just({})))
    return path, lambda c: _put(c, path, copy.deepcopy(value))


def _check(mutations):
    config = copy.deepcopy(BASE)
    for _, apply in mutations:
        apply(config)
    try:
        wfconfig.resolve_config(config, ROOT)
    except SettingError as e:
        named = ["config." + ".".join(str(k) for k in path) for path, _ in mutations]
        assert any(n in str(e) for n in named), (str(e), named)


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(mutation(), min_size=1, max_size=3))
def test_mutated_config_resolves_or_names_the_key(mutations):
    _check(mutations)


@pytest.mark.slow
@settings(max_examples=3000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(mutation(), min_size=1, max_size=5))
def test_mutated_config_resolves_or_names_the_key_long(mutations):
    _check(mutations)


@pytest.mark.parametrize(
    "override, named",
    [
        ({"temirkhan2023": {"tol": float("nan")}}, "config.temirkhan2023.tol"),
        ({"litvin200": {}}, "config.litvin200"),
        ({"published_dir": "no/such/dir"}, "config.published_dir"),
        ({"bench": {"repeats": 10**400}}, "config.bench.repeats"),
    ],
)
def test_known_hostile_overrides_are_named(override, named):
    with pytest.raises(SettingError, match=named.replace(".", r"\.")):
        wfconfig.resolve_config(override, ROOT)
