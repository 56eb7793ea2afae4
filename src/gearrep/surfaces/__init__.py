"""Tooth and tool surfaces: one module per family, each following the protocol of
:mod:`gearrep.surface`."""

__all__ = ["analytic", "bevel", "catt", "hob", "involute", "novikov", "rack"]
