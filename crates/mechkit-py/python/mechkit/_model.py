"""``mechkit.Model``: a scenario's equations of motion at given states, shaped for numpy."""

import numpy as np


class Model:
    """A scenario's model (``scenario.model(**constants)``): the accelerations, and each
    force's value, power and potential, at any states, computed by the same forces, units and
    formulas as ``run()``, so that a loop written by hand can be checked against the run.

    >>> import mechkit
    >>> model = mechkit.Scenario.load("examples/feather.toml").model()
    >>> model.coordinates, model.forces
    (['feather.x'], ['gravity', 'air'])
    >>> x, v = model.initial
    >>> dt = 1e-3
    >>> for k in range(100):          # the course's Euler-Cromer loop
    ...     v = v + model.accel(k * dt, x, v) * dt
    ...     x = x + v * dt
    >>> round(float(v[0]), 4)
    -0.4815
    """

    def __init__(self, native):
        self._native = native

    @property
    def coordinates(self):
        """The names of the coordinates, in the order of ``q`` and ``v``."""
        return self._native.coordinates

    @property
    def forces(self):
        """The forces' names."""
        return self._native.forces

    @property
    def initial(self):
        """The initial state ``(q, v)``: two float64 arrays."""
        return self._native.initial

    def evaluate(self, t, q, v):
        """The model at one state (``q``, ``v`` of shape ``(dof,)``, ``t`` a number) or at many
        (``(n, dof)``, ``t`` a number or ``(n,)``). Returns a dict: ``accel`` (the states'
        shape), ``force`` (name → the generalized force, the states' shape: N per position
        component), ``power`` (name → W) and ``potential`` (name → J, NaN for a force
        without one)."""
        q = np.asarray(q, dtype=np.float64)
        v = np.asarray(v, dtype=np.float64)
        if q.shape != v.shape or q.ndim not in (1, 2):
            raise ValueError(
                f"q and v must both have the shape (dof,) or (n, dof); they are {q.shape} "
                f"and {v.shape} (dof = {len(self.coordinates)}: {', '.join(self.coordinates)})"
            )
        single = q.ndim == 1
        q2 = np.ascontiguousarray(np.atleast_2d(q))
        v2 = np.ascontiguousarray(np.atleast_2d(v))
        n, dof = q2.shape
        ts = np.ascontiguousarray(np.broadcast_to(np.asarray(t, dtype=np.float64), (n,)))
        out = self._native._evaluate(ts, q2.ravel(), v2.ravel())
        names = self.forces
        nf = len(names)
        accel = out["accel"].reshape(n, dof)
        force = out["force"].reshape(n, nf, dof)
        power = out["power"].reshape(n, nf)
        potential = out["potential"].reshape(n, nf)
        pick = (lambda a: a[0]) if single else (lambda a: a)
        return {
            "accel": pick(accel),
            "force": {name: pick(force[:, i, :]) for i, name in enumerate(names)},
            "power": {name: pick(power[:, i]) for i, name in enumerate(names)},
            "potential": {name: pick(potential[:, i]) for i, name in enumerate(names)},
        }

    def accel(self, t, q, v):
        """The accelerations at one state or many (``evaluate(t, q, v)["accel"]``)."""
        return self.evaluate(t, q, v)["accel"]

    def __repr__(self):
        return repr(self._native)
