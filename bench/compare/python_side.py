"""The Python side of bench/compare: the feather loop in numba (compiled once, timed on the
second call) and trapz on 10^7 samples in NumPy. One line per workload:
workload<TAB>tool<TAB>ns per unit<TAB>check value."""

import time

import numpy as np

try:
    import numba
except ImportError:  # numba is optional: the driver installs it
    numba = None

N = 10_000_000


def feather(n, dt):
    g, dmg = 9.8, 4.0
    x, v = 2.4, 0.0
    for _ in range(n):
        a = -g - g * dmg * v * abs(v)
        v += a * dt
        x += v * dt
    return v


if numba is not None:
    fast = numba.njit(feather)
    fast(10, 1e-6)  # compile
    t0 = time.perf_counter()
    v = fast(N, 1e-6)
    t = time.perf_counter() - t0
    print(f"feather\tnumba {numba.__version__}\t{t / N * 1e9:.2f}\t{v:.6f}")

x = np.linspace(0.0, 1.0, N)
y = x * x
trap = getattr(np, "trapezoid", None) or np.trapz
trap(y, x)  # warm-up: the temporaries' pages are mapped once
t0 = time.perf_counter()
value = trap(y, x)
t = time.perf_counter() - t0
print(f"trapz\tNumPy {np.__version__} trapezoid\t{t / N * 1e9:.3f}\t{value:.9f}")
