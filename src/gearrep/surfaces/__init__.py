"""Tooth and tool surfaces: one module per family, all following :mod:`gearrep.surfaces.base`."""

from .base import Surface, SurfacePoint, cross, fd_derivatives, unit

__all__ = ["Surface", "SurfacePoint", "cross", "fd_derivatives", "unit"]
