"""The core modules (src/gearrep/*.py): units, settings, frames, the surface protocol, curvature,
envelopes, the Newton solver, meshing, contact ellipses, published data, check records, plotting
and benchmarks."""
