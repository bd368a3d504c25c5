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

Errors raise ``MechkitError`` or a subclass: a ``ScenarioError`` says where in the file
(``.line``, ``.column``) with the command line's message. The package also installs the
``mechkit`` command.
"""

from ._model import Model
from ._native import MechkitError, Run, Scenario, ScenarioError, __version__

__all__ = ["MechkitError", "Model", "Run", "Scenario", "ScenarioError", "__version__"]
