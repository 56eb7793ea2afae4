"""Tooth and tool surfaces: one module per family, each following the protocol of
:mod:`gearrep.surface` (lengths in the unit of the design data, mm in the examples; angles in rad)."""

__all__ = ["analytic", "bevel", "catt", "hob", "involute", "novikov", "rack"]
