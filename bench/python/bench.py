"""The Python package's benchmarks (issue 24), one run, the peers measured beside it:

1. the feather's 10^7 Euler-Cromer steps (bench/workloads/feather_1e7.toml): `Scenario.run()`
   from Python against the `mechkit` binary running the same file (best of 3 each);
2. a 10^6-row trajectory handed to numpy: the same workload keeping every 10th step, the
   time `Run` took to turn the library's trajectory into numpy arrays (`run.timings`);
3. the Kepler orbit (GM = 1, e = 0.5, 100 periods, rtol 1e-9, atol 1e-12, as
   bench/ode_compare): `Scenario.run()` with dopri5 and dop853 against SciPy's `solve_ivp`
   (RK45, DOP853) at the same tolerances, with the errors of the final position.

    python bench/python/bench.py [--cli target/release/mechkit]

Needs the package installed (pip install ./crates/mechkit-py) and scipy for part 3. Prints
a markdown table per part; docs/benchmarks.md records them.
"""

import argparse
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import mechkit

ROOT = Path(__file__).resolve().parents[2]
FEATHER = ROOT / "bench" / "workloads" / "feather_1e7.toml"

KEPLER = """
title = "Kepler e = 0.5, 100 periods"
dimensions = 2
[constants]
GM = "1 m^3/s^2"
e = 0.5
A = "1 m"
rp = "(1 - e)*A"
vp = "sqrt(GM*(1 + e)/rp)"
[[body]]
name = "p"
mass = "1 kg"
position = ["rp", "0 m"]
velocity = ["0 m/s", "vp"]
[[force]]
kind = "newtonian-gravity"
GM = "GM"
center = ["0 m", "0 m"]
[integrator]
method = "{method}"
rtol = 1e-9
atol = 1e-12
[stop]
t_max = "{t_end!r} s"
[output]
plots = []
"""
T_END = 100 * 2 * math.pi
E = 0.5
Y0 = np.array([1 - E, 0.0, 0.0, math.sqrt((1 + E) / (1 - E))])


def best(f, n=3):
    """The smallest wall time of `n` calls of f() and the last call's value."""
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        value = f()
        times.append(time.perf_counter() - t0)
    return min(times), value


def feather(cli):
    scenario = mechkit.Scenario.load(FEATHER)
    t_py, run = best(scenario.run)
    with tempfile.TemporaryDirectory() as out:
        t_cli, _ = best(
            lambda: subprocess.run(
                [cli, "run", str(FEATHER), "--out", out, "--quiet"],
                check=True,
                stdout=subprocess.DEVNULL,
            )
        )
    steps = run.summary["steps"]
    print("| feather, 10^7 steps | wall s (best of 3) | ns per step |")
    print("|---|---|---|")
    print(f"| mechkit binary (`{Path(cli).name} run`) | {t_cli:.3f} | {t_cli / steps * 1e9:.1f} |")
    print(f"| Python `Scenario.run()` | {t_py:.3f} | {t_py / steps * 1e9:.1f} |")
    print(f"\nPython / binary: {t_py / t_cli:.3f} ({steps} steps)\n")


def rows_to_numpy():
    text = FEATHER.read_text().replace("every = 100000", "every = 10")
    scenario = mechkit.Scenario.from_str(text, name="feather_1e6_rows.toml")
    _, run = best(scenario.run, n=1)
    convert = []
    for _ in range(3):
        run = scenario.run()
        convert.append(run.timings["trajectory"])
    rows, columns = len(run), len(run.trajectory)
    x = run.trajectory["feather.x"]
    assert isinstance(x, np.ndarray) and x.dtype == np.float64 and len(x) == rows
    print("| trajectory to numpy | rows | columns | ms (best of 3) |")
    print("|---|---|---|---|")
    print(f"| `Run` from the library's trajectory | {rows} | {columns} | {min(convert) * 1e3:.2f} |\n")


def kepler():
    try:
        from scipy.integrate import solve_ivp
        import scipy
    except ImportError:
        print("(scipy is not installed: the Kepler comparison is skipped)")
        return

    def rhs(_t, y):
        x, yy, vx, vy = y
        r2 = x * x + yy * yy
        s = -1.0 / (r2 * math.sqrt(r2))
        return [vx, vy, s * x, s * yy]

    print("| Kepler, 100 periods, rtol 1e-9, atol 1e-12 | evaluations | position error | ms (best of 3) |")
    print("|---|---|---|---|")
    rows = {}
    for ours, theirs in [("dopri5", "RK45"), ("dop853", "DOP853")]:
        scenario = mechkit.Scenario.from_str(KEPLER.format(method=ours, t_end=T_END), name="kepler.toml")
        t_m, run = best(scenario.run)
        traj = run.trajectory
        err_m = math.hypot(traj["p.x"][-1] - Y0[0], traj["p.y"][-1] - Y0[1])
        t_s, sol = best(lambda: solve_ivp(rhs, (0.0, T_END), Y0, method=theirs, rtol=1e-9, atol=1e-12))
        err_s = math.hypot(sol.y[0, -1] - Y0[0], sol.y[1, -1] - Y0[1])
        print(f"| mechkit `{ours}` from Python | {run.summary['evaluations']} | {err_m:.2e} | {t_m * 1e3:.1f} |")
        print(f"| SciPy {scipy.__version__} `solve_ivp` {theirs} | {sol.nfev} | {err_s:.2e} | {t_s * 1e3:.1f} |")
        rows[ours] = t_s / t_m
    print()
    for ours, ratio in rows.items():
        print(f"SciPy / mechkit ({ours}): {ratio:.0f}x")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "target" / "release" / "mechkit"))
    args = parser.parse_args()
    print(f"mechkit {mechkit.__version__}, Python {sys.version.split()[0]}, numpy {np.__version__}\n")
    feather(args.cli)
    rows_to_numpy()
    kepler()


if __name__ == "__main__":
    main()
