"""gearrep: open, tested Litvin-style gear geometry and tooth contact analysis.

Data flows one way: design parameters -> surfaces -> differential geometry -> contact ->
replications. Library code is pure: it never reads files or the workflow config.
Angles are radians and lengths are in the unit of the design data inside the library (mm in the
examples and the ``gearrep`` command); conversions happen at the edges with :mod:`gearrep.units`.

The names a library user starts with are here, each loaded when first used (so ``import gearrep``
itself stays light: a few milliseconds, numpy not imported): the gear data and flanks of an involute pair
(:class:`InvoluteGearData`, :func:`mating_flanks`, :class:`ParabolicCrowning`,
:func:`standard_centre_distance`), the pair in mesh (:class:`GearPair`, :class:`Misalignment`),
its contact (:func:`solve_contact`, :func:`trace_path`, :func:`robust_contact`, the record
:class:`ContactPoints`, :func:`contact_ellipse`), the meshing cycle (:func:`meshing_cycle`) and
curvatures (:func:`principal_curvatures`):

>>> import math, gearrep
>>> g1 = gearrep.InvoluteGearData(23, 3.0, math.radians(20), 25.0)  # teeth, module mm, rad, face mm
>>> g2 = gearrep.InvoluteGearData(41, 3.0, math.radians(20), 25.0)
>>> f1, f2 = gearrep.mating_flanks(g1, g2, crowning1=gearrep.ParabolicCrowning(1e-4))
>>> pair = gearrep.GearPair(f1, f2, 23, 41, g1.r_p + g2.r_p, misalignment=gearrep.Misalignment(d_E=0.01))
>>> round(gearrep.meshing_cycle(pair).contact_ratio, 4)  # TE and angles in rad
1.6517
>>> k = gearrep.principal_curvatures(f1.evaluate(33.0, 0.0))  # k1, k2 [1/mm]

``tca``, ``meshing``, ``curvature``, ``surfaces`` and ``units`` are the modules behind them (and the
unit conversions).
"""

__version__ = "0.1.0"

#: name -> module of the names loaded on first use (``import gearrep`` stays light)
_LAZY = {
    "GearPair": "gearrep.tca",
    "Misalignment": "gearrep.tca",
    "solve_contact": "gearrep.tca",
    "trace_path": "gearrep.tca",
    "robust_contact": "gearrep.tca",
    "ContactPoints": "gearrep.tca",
    "contact_ellipse": "gearrep.tca",
    "InvoluteGearData": "gearrep.surfaces.involute",
    "mating_flanks": "gearrep.surfaces.involute",
    "ParabolicCrowning": "gearrep.surfaces.involute",
    "standard_centre_distance": "gearrep.surfaces.involute",
    "meshing_cycle": "gearrep.meshing",
    "principal_curvatures": "gearrep.curvature",
}

#: the modules behind them, also loaded on first use
_MODULES = ("tca", "meshing", "curvature", "surfaces", "units")

__all__ = ["__version__", *_LAZY, *_MODULES]


def __getattr__(name):
    if name in _LAZY or name in _MODULES:
        import importlib

        value = importlib.import_module(f"gearrep.{name}") if name in _MODULES else None
        value = getattr(importlib.import_module(_LAZY[name]), name) if value is None else value
        globals()[name] = value
        return value
    raise AttributeError(f"module 'gearrep' has no attribute {name!r}")


def __dir__():
    return sorted([*globals(), *_LAZY, *_MODULES])
