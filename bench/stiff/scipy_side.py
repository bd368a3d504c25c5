"""SciPy's Radau, BDF and LSODA on the stiff test set of `cargo bench -p mechkit --bench stiff`
(same problems, tolerances, exact Jacobians, references), printing the same tab-separated
columns. Usage: python scipy_side.py REFERENCES.json [--quick]"""

import json
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp


def vdp(mu):
    def f(t, y):
        return [y[1], mu * (1 - y[0] ** 2) * y[1] - y[0]]

    def jac(t, y):
        return [[0.0, 1.0], [-2 * mu * y[0] * y[1] - 1, mu * (1 - y[0] ** 2)]]

    return f, jac


def robertson():
    def f(t, y):
        a = -0.04 * y[0] + 1e4 * y[1] * y[2]
        c = 3e7 * y[1] ** 2
        return [a, -a - c, c]

    def jac(t, y):
        return [
            [-0.04, 1e4 * y[2], 1e4 * y[1]],
            [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]],
            [0.0, 6e7 * y[1], 0.0],
        ]

    return f, jac


def hires():
    def f(t, y):
        d7 = 280 * y[5] * y[7] - 1.81 * y[6]
        return [
            -1.71 * y[0] + 0.43 * y[1] + 8.32 * y[2] + 0.0007,
            1.71 * y[0] - 8.75 * y[1],
            -10.03 * y[2] + 0.43 * y[3] + 0.035 * y[4],
            8.32 * y[1] + 1.71 * y[2] - 1.12 * y[3],
            -1.745 * y[4] + 0.43 * y[5] + 0.43 * y[6],
            -280 * y[5] * y[7] + 0.69 * y[3] + 1.71 * y[4] - 0.43 * y[5] + 0.69 * y[6],
            d7,
            -d7,
        ]

    def jac(t, y):
        j = np.zeros((8, 8))
        j[0, :3] = [-1.71, 0.43, 8.32]
        j[1, :2] = [1.71, -8.75]
        j[2, 2:5] = [-10.03, 0.43, 0.035]
        j[3, 1:4] = [8.32, 1.71, -1.12]
        j[4, 4:7] = [-1.745, 0.43, 0.43]
        j[5, 3:8] = [0.69, 1.71, -280 * y[7] - 0.43, 0.69, -280 * y[5]]
        j[6, 5:8] = [280 * y[7], -1.81, 280 * y[5]]
        j[7, 5:8] = [-280 * y[7], 1.81, -280 * y[5]]
        return j

    return f, jac


def pleiades():
    m = np.arange(1, 8, dtype=float)

    def pairs(y):
        # d = r_j - r_i, r^2, and m_j / r^3 (zero on the diagonal)
        x, yy = y[:7], y[7:14]
        dx = x[None, :] - x[:, None]
        dy = yy[None, :] - yy[:, None]
        r2 = dx**2 + dy**2
        np.fill_diagonal(r2, 1.0)
        w = m[None, :] / (r2 * np.sqrt(r2))
        np.fill_diagonal(w, 0.0)
        return dx, dy, r2, w

    def f(t, y):
        dx, dy, _, w = pairs(y)
        return np.concatenate([y[14:21], y[21:], (w * dx).sum(1), (w * dy).sum(1)])

    def jac(t, y):
        # d a_i / d r_j = m_j (I - 3 d d^T / r^2) / r^3, and d a_i / d r_i minus their sum
        dx, dy, r2, w = pairs(y)
        kxx = w * (1 - 3 * dx**2 / r2)
        kxy = -3 * w * dx * dy / r2
        kyy = w * (1 - 3 * dy**2 / r2)
        a = np.block([[kxx, kxy], [kxy, kyy]])
        a -= np.diag(np.concatenate([kxx.sum(1), kyy.sum(1)]))
        j = np.zeros((28, 28))
        j[:14, 14:] = np.eye(14)
        j[14:, :14] = a
        # the x rows' own y column and the y rows' own x column
        j[14 + np.arange(7), 7 + np.arange(7)] -= kxy.sum(1)
        j[21 + np.arange(7), np.arange(7)] -= kxy.sum(1)
        return j

    x0 = [3, 3, -1, -3, 2, -2, 2]
    y0 = [3, -3, 2, 0, 0, -4, 4]
    vx0 = [0, 0, 0, 0, 0, 1.75, -1.5]
    vy0 = [0, 0, 0, -1.25, 1, 0, 0]
    return f, jac, np.array(x0 + y0 + vx0 + vy0, dtype=float)


def chain(n=20, k=1e6, c=2e4, pull=1e3):
    kk = np.zeros((n, n))
    for i in range(n):
        kk[i, i] = -k if i == n - 1 else -2 * k
        if i > 0:
            kk[i, i - 1] = k
        if i < n - 1:
            kk[i, i + 1] = k
    cc = kk * (c / k)
    force = np.zeros(n)
    force[-1] = pull
    jac = np.block([[np.zeros((n, n)), np.eye(n)], [kk, cc]])

    def f(t, y):
        return np.concatenate([y[n:], kk @ y[:n] + cc @ y[n:] + force])

    return f, (lambda t, y: jac), n


def problems():
    f, j = vdp(1000.0)
    yield "vdp", f, j, [2.0, 0.0], 2000.0, 1.0, 1, [1e-4, 1e-5, 1e-6, 1e-7, 1e-8]
    f, j = robertson()
    yield "robertson", f, j, [1.0, 0.0, 0.0], 40.0, 1e-6, 3, [1e-4, 1e-6, 1e-8]
    f, j = hires()
    y0 = [1.0, 0, 0, 0, 0, 0, 0, 0.0057]
    yield "hires", f, j, y0, 321.8122, 1e-4, 8, [1e-4, 1e-6, 1e-8]
    f, j, y0 = pleiades()
    yield "pleiades", f, j, y0, 3.0, 1.0, 14, [1e-4, 1e-6, 1e-8]
    f, j, n = chain()
    yield "chain", f, j, np.zeros(2 * n), 0.1, 1e-3, 20, [1e-4, 1e-6, 1e-8]
    f, j, n = chain(n=200)
    yield "chain200", f, j, np.zeros(2 * n), 1.0, 1e-3, 20, [1e-4, 1e-6, 1e-8]


def main():
    references = json.load(open(sys.argv[1]))
    quick = "--quick" in sys.argv
    print("problem\tsolver\ttol\terror\tsteps\tevaluations\tjacobians\twall_s")
    for name, f, jac, y0, t_end, atol_factor, compared, tolerances in problems():
        ref = np.array(references[name])
        for tol in tolerances[2:3] if quick else tolerances:
            for method in ["Radau", "BDF", "LSODA"]:
                kwargs = dict(method=method, rtol=tol, atol=tol * atol_factor)
                if jac is not None:
                    kwargs["jac"] = jac
                sol = solve_ivp(f, (0.0, t_end), y0, **kwargs)
                if not sol.success:
                    print(f"{name}\tscipy-{method}\t{tol:e}\tfailed\t-\t-\t-\t-")
                    continue
                y = sol.y[:compared, -1]
                err = np.max(np.abs(y - ref) / np.abs(ref))
                runs, start = 0, time.perf_counter()
                while runs < 2 or time.perf_counter() - start < 1.0:
                    solve_ivp(f, (0.0, t_end), y0, **kwargs)
                    runs += 1
                wall = (time.perf_counter() - start) / runs
                steps = len(sol.t) - 1
                print(
                    f"{name}\tscipy-{method}\t{tol:e}\t{err:.3e}\t{steps}\t{sol.nfev}\t{sol.njev}\t{wall:.3e}",
                    flush=True,
                )


main()
