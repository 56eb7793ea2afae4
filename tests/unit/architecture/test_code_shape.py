"""The shape of the code, kept by tests: rotations defined only in ``gearrep.frames``,
and no import fallbacks (``except ImportError``) that would let a missing module pass silently.
(Function and file sizes, test_code_size.py, and the layering of the core, test_core_layering.py,
have their own tests.)"""

import ast
import re

from conftest import ROOT

SRC = ROOT / "src" / "gearrep"
SOURCES = sorted(SRC.rglob("*.py"))
#: names of functions that would build a rotation matrix (rot_z, _rx, drot_y, rotation, ...)
ROTATION_NAME = re.compile(r"^_?(d?rot|rx|ry|rz|drx|dry|drz|rotation)(_?[xyz])?$")
#: the one function of that name outside frames, and why it is not a second definition
NOT_A_ROTATION = {
    ("motion.py", "rotation"): "a factor of a ChainMotion, evaluated by frames.rotation_about_axis_with_derivatives",
}


def _rel(path):
    return str(path.relative_to(SRC))


def test_rotations_are_defined_only_in_frames():
    found = []
    for path in SOURCES:
        if path.name == "frames.py":
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and ROTATION_NAME.match(node.name):
                if (path.name, node.name) not in NOT_A_ROTATION:
                    found.append(f"{_rel(path)}:{node.lineno} {node.name}")
    assert not found, f"rotation functions outside gearrep.frames (use frames instead): {found}"


def test_no_import_fallbacks():
    found = []
    for path in SOURCES:
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ExceptHandler) and node.type is not None:
                names = {n.id for n in ast.walk(node.type) if isinstance(n, ast.Name)}
                if names & {"ImportError", "ModuleNotFoundError"}:
                    found.append(f"{_rel(path)}:{node.lineno}")
    assert not found, f"import fallbacks (a missing module must fail loudly, or be an optional extra): {found}"


def test_the_shape_checks_see_what_they_look_for(tmp_path):
    assert ROTATION_NAME.match("rot_z") and ROTATION_NAME.match("_rz") and ROTATION_NAME.match("drot_x")
    assert not ROTATION_NAME.match("rotate_points") and not ROTATION_NAME.match("root")
    assert len(SOURCES) > 50 and any(p.name == "frames.py" for p in SOURCES)
