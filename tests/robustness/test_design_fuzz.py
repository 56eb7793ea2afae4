"""Property-based hostile design files: random mutations of the example designs
(wrong types, NaN, infinity, negative and huge values, in-range values that make impossible
geometry, missing, unknown and misspelt keys, another family) and random documents go through
`gearrep check` (the command's main function, in-process): the exit code is 0 or 2, never a crash,
and every refusal is one line naming a key (``design.<key>: ...``) and the allowed values. A few go
through `gearrep tca` as a subprocess: no traceback and no output directory on refusal."""

from __future__ import annotations

import contextlib
import copy
import io
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gearrep.cli import main
from gearrep.cli.families import REGISTRY

ROOT = Path(__file__).resolve().parents[2]
BASES = {
    p.name: yaml.safe_load(p.read_text())
    for p in sorted((ROOT / "examples").glob("*.yaml"))
    if not p.name.startswith("sweep")
}
TMP = Path(tempfile.mkdtemp(prefix="gearrep-design-fuzz-"))
#: a refusal names the key first: design, design.pinion.teeth, design.analysis.flank_grid[1], ...
_KEY = r"""(?:'(?:[^'\\]|\\.)*'|"(?:[^"\\]|\\.)*"|[^\s:'"]+)"""
REFUSAL = re.compile(rf"^gearrep (check|tca): refused: design(\.{_KEY})*: .*allowed", re.S)


def _paths(decl, prefix=()):
    for k, s in decl.items():
        yield prefix + (k,), s
        if s.kind == "group":
            yield from _paths(s.fields, prefix + (k,))


PATHS = {name: sorted(_paths(fam.keys), key=lambda x: x[0]) for name, fam in REGISTRY.items()}

HOSTILE = st.one_of(
    st.sampled_from([float("nan"), float("inf"), float("-inf"), -1, -1e-300, 0, 10**400, 1e308, -(10**30)]),
    st.sampled_from([None, True, False, "", "x", "nan", "1.0", [], [1], {}, {"a": 1}, [float("nan")]]),
    st.integers(),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=8),
    st.lists(st.one_of(st.integers(), st.floats(), st.text(max_size=4)), max_size=3),
    st.dictionaries(st.text(max_size=6), st.one_of(st.integers(), st.floats(), st.none()), max_size=3),
)


def _in_range(draw, s):
    """A value inside the declared range (type and range pass; the geometry may not)."""
    if s.kind == "integer":
        lo = int(s.ge) if s.ge is not None else -100
        hi = int(s.le) if s.le is not None else 1000
        return draw(st.integers(lo, min(hi, lo + 200)))
    if s.kind == "number":
        lo = s.ge if s.ge is not None else (s.gt if s.gt is not None else -1e3)
        hi = s.le if s.le is not None else (s.lt if s.lt is not None else 1e3)
        x = draw(st.floats(lo, hi, allow_nan=False, allow_infinity=False))
        if (s.gt is not None and x <= s.gt) or (s.lt is not None and x >= s.lt):
            x = 0.5 * (lo + hi)
        return x
    if s.kind == "string":
        return draw(st.sampled_from(s.choices)) if s.choices else draw(st.text(min_size=1, max_size=6))
    if s.kind == "boolean":
        return draw(st.booleans())
    if s.kind == "array":
        return [_in_range(draw, s.item) for _ in range(draw(st.integers(s.min_items, s.max_items or 3)))]
    return {}


def _put(doc, path, value):
    d = doc
    for k in path[:-1]:
        if not isinstance(d.get(k), dict):
            d[k] = {}
        d = d[k]
    d[path[-1]] = value


def _drop(doc, path):
    d = doc
    for k in path[:-1]:
        d = d.get(k) if isinstance(d, dict) else None
        if not isinstance(d, dict):
            return
    d.pop(path[-1], None)


@st.composite
def mutation(draw, fam):
    kind = draw(st.sampled_from(["hostile", "in_range", "in_range", "missing", "unknown", "family"]))
    path, s = draw(st.sampled_from(PATHS[fam]))
    if kind == "hostile":
        v = draw(HOSTILE)
        return lambda d: _put(d, path, copy.deepcopy(v))
    if kind == "in_range":
        v = _in_range(draw, s)
        return lambda d: _put(d, path, copy.deepcopy(v))
    if kind == "missing":
        return lambda d: _drop(d, path)
    if kind == "unknown":
        name = draw(st.one_of(st.text(min_size=1, max_size=8), st.sampled_from(["modul_mm", "teeth_", "Pinion"])))
        where = path[:-1] if s.kind != "group" else path
        v = draw(HOSTILE)
        return lambda d: _put(d, where + (name,), copy.deepcopy(v))
    other = draw(st.sampled_from(sorted(set(REGISTRY) - {fam})))
    return lambda d: d.__setitem__("family", other)


@st.composite
def designs(draw):
    if draw(st.integers(0, 19)) == 0:  # now and then a document that is not a design at all
        return draw(
            st.recursive(
                st.one_of(st.none(), st.booleans(), st.integers(), st.floats(), st.text(max_size=5)),
                lambda c: st.lists(c, max_size=3) | st.dictionaries(st.text(max_size=5), c, max_size=3),
                max_leaves=6,
            )
        )
    name = draw(st.sampled_from(sorted(BASES)))
    doc = copy.deepcopy(BASES[name])
    for m in draw(st.lists(mutation(doc["family"]), min_size=1, max_size=3)):
        m(doc)
    return doc


def _check_cli(doc) -> tuple[int, str]:
    fd, path = tempfile.mkstemp(suffix=".yaml", dir=TMP)
    with os.fdopen(fd, "w") as f:
        yaml.safe_dump(doc, f)
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        rc = main(["check", path])
    os.unlink(path)
    return rc, err.getvalue()


COUNTS = {"ok": 0, "refused": 0}


@settings(max_examples=500, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(designs())
def test_random_and_malformed_designs_pass_or_are_refused_naming_a_key(doc):
    rc, err = _check_cli(doc)
    assert rc in (0, 2), err
    if rc == 2:
        line = err.strip()
        assert "\n" not in line and "Traceback" not in line, line
        assert REFUSAL.match(line), line
        COUNTS["refused"] += 1
    else:
        COUNTS["ok"] += 1


def test_the_fuzz_saw_both_outcomes():
    """Run after the property test in the same worker (whole files per worker): the mutations
    produce accepted designs as well as refusals, so neither branch is vacuous."""
    if sum(COUNTS.values()) == 0:  # run alone
        return
    assert COUNTS["ok"] > 0 and COUNTS["refused"] > 0, COUNTS


def _just_above(s) -> list[float]:
    """The smallest values a number key with an exclusive lower bound admits: the next floats above
    it (above 0, the subnormal 5e-324 and 1e-300, whose squares underflow). An inclusive bound is
    one value the property test above draws often."""
    if s.ge is not None or s.gt is None:
        return []
    g = float(s.gt)
    return [g + 5e-324, g + 1e-300] if g == 0 else [g * (1 + 1e-15) if g > 0 else g * (1 - 1e-15)]


@pytest.mark.parametrize("name", sorted(BASES))
def test_every_number_key_just_above_its_exclusive_bound_passes_or_is_refused(name):
    """Each number key of each example design with an exclusive lower bound set, one at a time, to
    the smallest values it admits: the design is accepted or refused in one line naming a key,
    never a crash (a relief length of 1e-300 mm once divided by its underflowed square)."""
    base = BASES[name]
    bad = []
    for path, s in PATHS[base["family"]]:
        if s.kind != "number":
            continue
        for v in _just_above(s):
            doc = copy.deepcopy(base)
            _put(doc, path, v)
            rc, err = _check_cli(doc)
            if rc not in (0, 2) or (rc == 2 and not REFUSAL.match(err.strip())):
                bad.append((".".join(path), v, rc, err.strip()[:160]))
    assert not bad, bad


def test_a_few_bad_designs_through_tca_as_a_subprocess(tmp_path):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "MPLBACKEND": "Agg"}
    bad = [
        {**BASES["crowned_spur.yaml"], "module_mm": float("nan")},
        {**BASES["helical.yaml"], "pinion": {"teeth": 5}},
        {**BASES["novikov.yaml"], "face_width_mm": "wide"},
        {**BASES["catt.yaml"], "misalignment": {"d_E_mm": 80.0}},
        {**BASES["hobbed_curvilinear.yaml"], "pinion": {"teeth": 40, "cutter_radius_mm": 15.0}},
    ]
    for i, doc in enumerate(bad):
        p = tmp_path / f"bad{i}.yaml"
        p.write_text(yaml.safe_dump(doc))
        out = tmp_path / f"out{i}"
        r = subprocess.run(
            [sys.executable, "-m", "gearrep", "tca", str(p), "-o", str(out)], env=env, capture_output=True, text=True
        )
        assert r.returncode == 2, r.stderr
        assert REFUSAL.match(r.stderr.strip()) and "Traceback" not in r.stderr, r.stderr
        assert not out.exists() and not list(tmp_path.glob(f".out{i}*"))
