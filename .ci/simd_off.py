"""Print the value of NPY_DISABLE_CPU_FEATURES that switches off this machine's best SIMD group.

numpy dispatches its kernels to the best instruction-set group the CPU has beyond the baseline it
was built for (on x86-64: X86_V3 = AVX2, X86_V4 and AVX512_* = AVX-512). Turning off every group
above the lowest one found (or the only one) makes numpy round as a machine without them would;
the portability pass of .ci/run runs the number-comparing tests so. Prints nothing when numpy
dispatches to no group beyond its baseline.
"""

import numpy as np

found = [f for f in np._core._multiarray_umath.__cpu_dispatch__ if np._core._multiarray_umath.__cpu_features__.get(f)]
print(" ".join(found[1:] if len(found) > 1 else found))
