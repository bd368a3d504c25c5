"""SciPy side of the Kepler benchmark (see README.md): solve_ivp with RK45 and DOP853.

Kepler orbit, GM = 1, a = 1, e = 0.5, from perihelion, t = 0 .. 100 * 2*pi, rtol = 1e-9,
atol = 1e-12. The exact final state is the initial state. Run: python3 scipy_kepler.py
"""

import math
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp

E = 0.5
T_END = 100.0 * 2.0 * math.pi
RTOL, ATOL = 1e-9, 1e-12
REPEATS = 5  # best (and median) of this many timed runs

Y0 = np.array([1.0 - E, 0.0, 0.0, math.sqrt((1.0 + E) / (1.0 - E))])


def rhs(t, y):
    x, yy, vx, vy = y
    r2 = x * x + yy * yy
    s = -1.0 / (r2 * math.sqrt(r2))
    return np.array([vx, vy, s * x, s * yy])


def energy(y):
    return 0.5 * (y[2] ** 2 + y[3] ** 2) - 1.0 / math.hypot(y[0], y[1])


def main():
    print(f"SciPy {scipy.__version__}, NumPy {np.__version__}")
    print(
        f"Kepler e = {E}, 100 orbits (t_end = {T_END}), rtol = {RTOL:g}, atol = {ATOL:g}; "
        f"time: best (median) of {REPEATS} runs; dense_output=False, t_eval=None\n"
    )
    print(
        "| method | nfev | steps (accepted) | rejected (derived) | position error | rel. energy error "
        "| wall time / run, ms: best (median) | us per RHS eval |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for method in ("RK45", "DOP853"):
        times = []
        sol = None
        for _ in range(REPEATS):
            start = time.perf_counter()
            sol = solve_ivp(rhs, (0.0, T_END), Y0, method=method, rtol=RTOL, atol=ATOL)
            times.append(time.perf_counter() - start)
        assert sol.success, sol.message
        times.sort()
        y = sol.y[:, -1]
        pos_err = math.hypot(y[0] - Y0[0], y[1] - Y0[1])
        e_err = abs(energy(y) + 0.5) / 0.5
        steps = len(sol.t) - 1
        # SciPy evaluates f at the new point in every attempt (RK45: 6 evaluations per
        # attempt, DOP853: 12), plus 2 at the start (f(t0, y0) and the initial-step probe).
        per_attempt = 6 if method == "RK45" else 12
        attempts, rest = divmod(sol.nfev - 2, per_attempt)
        rejected = f"{attempts - steps}" if rest == 0 else "?"
        best, median = times[0], times[len(times) // 2]
        print(
            f"| SciPy {method} | {sol.nfev} | {steps} | {rejected} | {pos_err:.2e} | {e_err:.2e} "
            f"| {best * 1e3:.1f} ({median * 1e3:.1f}) | {best * 1e6 / sol.nfev:.2f} |"
        )

    # bare cost of one Python RHS call
    n = 200_000
    y = Y0.copy()
    start = time.perf_counter()
    for _ in range(n):
        rhs(0.0, y)
    bare = (time.perf_counter() - start) / n
    print(f"\nBare Python RHS call (no integrator): {bare * 1e6:.2f} us")


if __name__ == "__main__":
    main()
