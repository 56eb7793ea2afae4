"""gearrep: open, tested Litvin-style gear geometry and tooth contact analysis.

Data flows one way: design parameters -> surfaces -> differential geometry -> contact ->
replications. Library code is pure: it never reads files or the workflow config.
Angles are radians and lengths are in the unit of the design data inside the library;
conversions happen at the edges with :mod:`gearrep.units`.
"""

__version__ = "0.1.0"

__all__ = ["__version__"]
