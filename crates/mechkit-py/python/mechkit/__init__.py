"""mechkit: computational classical mechanics.

A scenario file (TOML: bodies, forces as formulas with units, an integrator, when to stop)
is checked when it is loaded and run in Rust; the run's summary is a dict (``summary.json``)
and its trajectory a dict of numpy arrays (``trajectory.csv``'s columns).

>>> import mechkit
>>> feather = mechkit.Scenario.load("examples/feather.toml")
>>> run = feather.run()
>>> round(run.events[0]["t"], 3)
4.835
>>> round(float(run.trajectory["feather.vx"][-1]), 3)   # the terminal speed, 0.5 m/s
-0.5
>>> heavier = feather.run(g="19.6 m/s^2")   # a [constants] entry given another value

``scenario.model()`` gives the same forces at any states, for a loop written by hand
(``mechkit.Model``).

``run.plot("v(x)")`` draws a plot as ``mechkit run`` does (Jupyter shows it; ``.svg``,
``.png()``, ``.save(path)``). ``mechkit.sweep(path, v0="0:5:51")`` runs a parameter sweep and
``mechkit.md(cells=4)`` a molecular-dynamics run, in memory, as ``mechkit sweep`` and
``mechkit md`` do:

>>> throws = mechkit.sweep("examples/sweep/throw.toml", v0=[1, 2, 3], threads=1)
>>> [round(float(h), 3) for h in throws.table["x_max"]]
[1.046, 1.141, 1.241]
>>> melt = mechkit.md(cells=4, steps=10, thermo_every=5)
>>> melt.report["atoms"], melt.thermo["step"].tolist()
(256, [0, 5, 10])

Errors raise ``MechkitError`` or a subclass: a ``ScenarioError`` says where in the file
(``.line``, ``.column``) with the command line's message. The package also installs the
``mechkit`` command.
"""

from ._model import Model
from ._native import (
    Animation,
    MdResult,
    MechkitError,
    Plot,
    Run,
    Scenario,
    ScenarioError,
    SweepResult,
    __version__,
    collide,
    com,
    cumtrapz,
    derive,
    diff,
    dsolve,
    impulse,
    inertia,
    integrate,
    md,
    potential,
    simpson,
    solve,
    trapz,
    units,
)
from ._sweep import sweep

__all__ = [
    "Animation",
    "MdResult",
    "MechkitError",
    "Model",
    "Plot",
    "Run",
    "Scenario",
    "ScenarioError",
    "SweepResult",
    "__version__",
    # the course's commands as functions, each returning the command's --json (mechkit
    # integrate | diff | solve | dsolve | units | derive | potential | collide | impulse | com |
    # inertia | md | sweep), and the sample rules
    "collide",
    "com",
    "cumtrapz",
    "derive",
    "diff",
    "dsolve",
    "impulse",
    "inertia",
    "integrate",
    "md",
    "potential",
    "simpson",
    "solve",
    "sweep",
    "trapz",
    "units",
]
