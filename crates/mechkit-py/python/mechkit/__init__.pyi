"""Type stubs of mechkit (the classes are implemented in Rust, in ``mechkit._native``)."""

import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

class MechkitError(Exception):
    """The base class of mechkit's errors."""

class ScenarioError(MechkitError):
    """An error in a scenario: its text, its constants, or reading it.

    ``str(e)`` is the command line's message (with the line and a caret under the problem,
    and the hint); ``file``, ``line`` and ``column`` (1-based) say where when the error is
    in the scenario's text, and are None otherwise.
    """

    kind: Optional[str]
    """``"syntax"``, ``"unknown_key"``, ``"missing"``, ``"wrong_type"``, ``"unit"``,
    ``"dimension"``, ``"formula"``, ``"invalid"`` or ``"io"``."""
    message: Optional[str]
    """The first line of the message, without place or hint."""
    file: Optional[str]
    line: Optional[int]
    column: Optional[int]
    hint: Optional[str]

class Scenario:
    """A scenario, checked when it is loaded, as ``mechkit run FILE`` reads it."""

    @staticmethod
    def load(path: Union[str, os.PathLike[str]]) -> Scenario:
        """Reads and checks a scenario file; raises ScenarioError."""
    @staticmethod
    def from_str(text: str, name: str = "<string>") -> Scenario:
        """Reads and checks a scenario from its TOML text; ``name`` stands for the file in
        error messages."""
    def run(self, **constants: Union[str, float]) -> Run:
        """Runs the scenario. Keyword arguments give ``[constants]`` other values: strings
        with units (``m="2 kg"``) or numbers in SI (``m=2.0``). The GIL is released while it
        runs; Ctrl-C stops the run and raises KeyboardInterrupt."""
    def model(self, **constants: Union[str, float]) -> Model:
        """The scenario's model with these constants: accelerations and each force's value,
        power and potential at any states, for a loop written by hand."""
    @property
    def name(self) -> str: ...
    @property
    def title(self) -> str: ...
    @property
    def constants(self) -> Dict[str, float]:
        """The ``[constants]``: name → SI value."""

class Run:
    """What a run produced."""

    @property
    def summary(self) -> Dict[str, Any]:
        """``summary.json`` as a dict."""
    @property
    def trajectory(self) -> Dict[str, npt.NDArray[np.float64]]:
        """``trajectory.csv``'s columns: name → float64 array."""
    @property
    def units(self) -> Dict[str, Optional[str]]:
        """Each trajectory column's unit (``"1"`` for a pure number)."""
    @property
    def events(self) -> List[Dict[str, Any]]:
        """The summary's located events."""
    @property
    def observables(self) -> Dict[str, float]:
        """The ``[observe]`` results."""
    @property
    def failed(self) -> bool:
        """Whether the computation failed (the command line's exit status 1)."""
    def to_pandas(self) -> Any:
        """The trajectory as a ``pandas.DataFrame`` (units in ``df.attrs["units"]``)."""
    def __len__(self) -> int:
        """The trajectory's number of rows."""


class Model:
    """A scenario's equations of motion at given states (``scenario.model()``)."""

    @property
    def coordinates(self) -> List[str]: ...
    @property
    def forces(self) -> List[str]: ...
    @property
    def initial(self) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def evaluate(
        self, t: Union[float, npt.ArrayLike], q: npt.ArrayLike, v: npt.ArrayLike
    ) -> Dict[str, Any]:
        """``accel`` (the states' shape), ``force``, ``power``, ``potential`` (name → array)."""
    def accel(
        self, t: Union[float, npt.ArrayLike], q: npt.ArrayLike, v: npt.ArrayLike
    ) -> npt.NDArray[np.float64]: ...
