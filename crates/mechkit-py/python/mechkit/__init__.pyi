"""Type stubs of mechkit (the classes are implemented in Rust, in ``mechkit._native``)."""

import os
from typing import Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union

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
    @property
    def timings(self) -> Dict[str, float]:
        """Where the time went, in seconds: ``run`` (the simulation, in Rust), ``summary``
        (the summary made a dict), ``trajectory`` (the columns handed to numpy: moved, not
        copied)."""
    def __len__(self) -> int:
        """The trajectory's number of rows."""
    def plot(self, spec: str, *, style: Literal["paper", "slides"] = "paper") -> Plot:
        """The plot ``spec`` (``"v(x)"``, ``"energy(t)"``, ``"energy-bars"``: any plot
        ``[output] plots`` accepts) drawn as ``mechkit run`` draws it. A plot the scenario
        lists comes from this run; another runs the scenario again (the same points), with
        the GIL released. Raises ScenarioError for a spec that is not a plot of the
        scenario."""
    def animate(
        self,
        *,
        fps: float = 25.0,
        speed: Optional[float] = None,
        trails: bool = True,
        energy_bars: bool = True,
        width: int = 640,
        height: int = 480,
    ) -> Animation:
        """The run's animation, as ``mechkit animate`` draws it: the bodies to scale in their
        shapes (balls, rigid bodies' parts, springs as coils, rods, strings, walls), trails,
        a time stamp and energy bars, ``fps`` frames per second of playback at ``speed``
        simulated seconds per second (None: real time, slowed down or sped up to play 4 to
        12 s). Jupyter shows it inline as the HTML player.

        >>> a = mechkit.Scenario.load("examples/bouncing_ball_floor.toml").run().animate()
        >>> len(a) >= 20
        True
        """


class Animation:
    """A run's animation (``Run.animate()``): Jupyter shows the HTML player inline."""

    @property
    def html(self) -> str:
        """One self-contained HTML file (no network) that plays it: play/pause, a time slider."""
    def gif(self) -> bytes:
        """The animated GIF's bytes (looping)."""
    def save(self, path: Union[str, os.PathLike[str]]) -> str:
        """Writes ``.gif``, ``.html`` or ``.mp4`` (needs ffmpeg on the PATH) by the extension."""
    @property
    def fps(self) -> float: ...
    @property
    def speed(self) -> float:
        """Simulated seconds per second of playback."""
    @property
    def times(self) -> List[float]:
        """Each frame's simulated time (s)."""
    def __len__(self) -> int: ...
    def _repr_html_(self) -> str: ...


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

# calculus and data: mechkit integrate | diff | solve | units | derive, and the sample rules
#
# A value is a number (SI; ``inf`` where the command line takes ``inf``) or a string read as
# the command line reads it (``"2 m"``, ``"pi/6"``, ``"b/4"`` with ``b`` given). The other
# names of a formula take their values from keyword arguments, or from ``set``: a dict, or
# the command line's ``--set`` text (``"a=1,b=2 m"``), for names that are also arguments
# (``a``, ``b``, ``var``...). Bad input raises MechkitError with the command line's message,
# naming the argument; a value of the wrong type raises TypeError.

_Value = Union[float, str]
_Names = Union[str, List[str]]

def integrate(
    expr: str,
    var: str = "x",
    a: Optional[_Value] = None,
    b: Optional[_Value] = None,
    *,
    method: Optional[_Names] = None,
    n: Optional[Union[int, List[int]]] = None,
    set: Optional[Union[Dict[str, _Value], str]] = None,
    **params: _Value,
) -> Dict[str, Any]:
    """``mechkit integrate EXPR --var VAR --from A --to B --method M --n N --set ...``: the
    command's ``--json`` as a dict (``input``, ``var``, ``antiderivative`` (text, or None when
    the rule table has none), ``assumptions``, ``parameters``, ``definite`` (with ``a`` and
    ``b``: ``from``, ``to``, ``closed_form``, ``quadrature``, ``agree``), ``reference``,
    ``rules``), plus ``value``: the definite integral to trust, the closed form where it
    agrees with the adaptive quadrature, else the quadrature's value; None without limits or
    when the quadrature failed. ``method`` (rules such as ``"trapezoid,simpson"`` or
    ``["left", "gauss-legendre-3"]``, or ``"all"``) compares fixed rules with ``n`` intervals
    (10 unless given) against the exact value.

    >>> mechkit.integrate("x^2", "x", 0, 1)["value"]
    0.3333333333333333
    >>> mechkit.integrate("1/(a+x^2)", "x", 0, 1, set={"a": 1})["antiderivative"]
    'atan(x/sqrt(a))/sqrt(a)'
    """

def dsolve(
    equation: str,
    func: str = "x",
    var: str = "t",
    ic: Optional[str] = None,
    *,
    set: Optional[Union[Dict[str, _Value], str]] = None,
    **params: _Value,
) -> Dict[str, Any]:
    """``mechkit dsolve EQUATION --func F --var T --ic IC --set ...``: an ordinary
    differential equation written with primes, solved in closed form and verified by
    substitution; the command's ``--json`` as a dict (``solution``, ``method``,
    ``constants``, ``ic``, ``determined``, ``assumptions``, ``verified``, ``verification``).
    An equation without a closed form raises MechkitError.

    >>> mechkit.dsolve("x'' + 4*x = 0", ic="x(0)=1, x'(0)=0")["solution"]
    'cos(2*t)'
    """

def diff(
    expr: str,
    var: str = "x",
    at: Optional[_Value] = None,
    step: Optional[_Value] = None,
    *,
    set: Optional[Union[Dict[str, _Value], str]] = None,
    **params: _Value,
) -> Dict[str, Any]:
    """``mechkit diff EXPR --var VAR --at X --step H --set ...``: the command's ``--json`` as a
    dict: ``input``, ``var``, ``derivative`` (text) and, with ``at``, ``at``: ``{x, symbolic,
    numeric, numeric_error, agree}`` (the numeric value by Ridders' extrapolation of central
    differences from the initial step ``step``, 0.1 unless given).

    >>> mechkit.diff("sin(x)")["derivative"]
    'cos(x)'
    """

def solve(
    equation: Union[str, List[str]],
    unknowns: Optional[_Names] = None,
    interval: Optional[Union[str, Tuple[_Value, _Value]]] = None,
    *,
    set: Optional[Union[Dict[str, _Value], str]] = None,
    **params: _Value,
) -> Dict[str, Any]:
    """``mechkit solve EQUATION --for UNKNOWNS --in A:B --set ...``: the command's ``--json`` as
    a dict. One equation (``"LHS = RHS"``, or an expression equal to zero) for one unknown
    (``"x"`` unless given): ``equation``, ``unknown``, ``symbolic`` (the roots as texts, or
    None), ``no_real_root``, ``every_value``, ``assumptions``, ``numeric`` (the roots' values;
    without a symbolic solution, the roots found on ``interval``, ``"A:B"`` or ``(a, b)``).
    Linear equations (a list, or ``;``-separated) for several unknowns (``"x,y"`` or a list):
    ``solution`` (name → text), ``parameters``, ``numeric`` (name → value, or None).

    >>> mechkit.solve("x^2 - 5*x + 6 = 0")["numeric"]
    [2.0, 3.0]
    """

def units(value: str, to: Optional[str] = None) -> Dict[str, Any]:
    """``mechkit units QUANTITY --to UNIT``: the command's ``--json`` as a dict: ``input``,
    ``si``, ``si_unit``, ``dimension``, ``quantity`` (what it measures, e.g. ``"velocity"``)
    and ``converted`` (``{value, unit}`` with ``to``, else None).

    >>> mechkit.units("60 km/h", to="m/s")["si"]
    16.666666666666668
    """

def trapz(
    y: npt.ArrayLike, x: Optional[npt.ArrayLike] = None, dx: float = 1.0
) -> float:
    """``∫ y dx`` by the trapezoid rule (the rule of ``mechkit work``), as NumPy's
    ``trapezoid``: at the samples ``x``, or ``dx`` apart. ``y`` and ``x`` are 1-D (lists are
    converted to float64) of the same length, at least 2, finite, ``x`` strictly increasing;
    MechkitError otherwise."""

def cumtrapz(
    y: npt.ArrayLike,
    x: Optional[npt.ArrayLike] = None,
    dx: float = 1.0,
    initial: Optional[float] = 0.0,
) -> npt.NDArray[np.float64]:
    """The running trapezoid integral ``∫_{x_0}^{x_i} y dx`` at every sample, plus
    ``initial``: SciPy's ``cumulative_trapezoid(y, x, initial=0)`` (+ ``initial``); with
    ``initial=None``, without the first value (SciPy's default, one value fewer than ``y``).
    Inputs as for ``trapz``."""

def simpson(
    y: npt.ArrayLike, x: Optional[npt.ArrayLike] = None, dx: float = 1.0
) -> float:
    """``∫ y dx`` by composite Simpson on any spacing (the rule of ``mechkit work --method
    simpson``), as SciPy's ``simpson`` (1.11 and later): parabolas through pairs of
    intervals; with an odd number of intervals (an even number of samples) the last interval
    is integrated on the parabola through the last three samples (Cartwright 2017); two
    samples give the trapezoid. Inputs as for ``trapz``."""

def derive(
    path_or_t: Union[str, os.PathLike[str], npt.ArrayLike],
    x: Optional[
        Union[npt.ArrayLike, Dict[str, npt.ArrayLike], str, int, List[Union[str, int]]]
    ] = None,
    *,
    t: Optional[Union[str, int]] = None,
    method: Optional[str] = None,
    smooth: Optional[Union[int, Tuple[int, int], str]] = None,
) -> Dict[str, Any]:
    """``mechkit derive FILE --t T --x X --method M --smooth W:O``: velocity and acceleration
    of positions sampled in time.

    From a data file (``path_or_t`` a path): ``t`` is the time column and ``x`` the position
    column(s), by name or number from 1 (the first column, and every other one, unless
    given); a header's units (``t [ms]``) convert to SI. From arrays (``path_or_t`` the
    times): ``x`` is an array of positions, or a dict of name → array for several; ``t`` is
    the time's name (``"t"`` unless given; a unit in brackets, ``"t [ms]"``, converts as in a
    file). ``method`` is ``"central"`` (the default), ``"forward"`` or ``"backward"``;
    ``smooth`` a Savitzky-Golay window (``21``, ``(21, 2)`` or ``"21:2"``, order 2 unless
    given; uniform time steps only), instead of ``method``.

    Returns the command's ``--json`` as a dict (``file``, ``rows``, ``time``, ``time_unit``,
    ``uniform_step``, ``method``, ``columns``: each ``name``, ``velocity`` and
    ``acceleration`` summaries, ``units``), with the series as float64 arrays: ``t``, and
    each column's ``x``, ``v`` and ``a``.
    """

# batch: md, sweep and plots

class Plot:
    """A plot drawn as the ``mechkit`` command draws it: Jupyter shows it (SVG, or PNG)."""

    @property
    def svg(self) -> str:
        """The SVG text: the bytes ``mechkit run`` writes to the plot's ``.svg`` file."""
    def png(self, dpi: int = 192) -> bytes:
        """The PNG file's bytes at ``dpi`` (24 to 1200; 96 gives 900x600 pixels)."""
    def save(self, path: Union[str, os.PathLike[str]], *, dpi: int = 192) -> None:
        """Writes ``.svg`` or ``.png`` by the extension, replacing the file at once."""
    @property
    def spec(self) -> str: ...
    @property
    def title(self) -> str: ...
    @property
    def style(self) -> str:
        """``"paper"`` or ``"slides"``."""
    @property
    def file_stem(self) -> str:
        """The file name ``mechkit`` gives the plot, without extension (``v_x``)."""
    @property
    def labels(self) -> Tuple[str, str]:
        """The axis labels with units."""
    @property
    def series(self) -> List[Dict[str, Any]]:
        """The curves: ``label``, and ``x`` and ``y`` as float64 arrays."""
    def _repr_svg_(self) -> str: ...
    def _repr_png_(self) -> bytes: ...

def md(
    *,
    lattice: str = "fcc",
    cells: int = 20,
    density: float = 0.8442,
    temperature: Optional[float] = None,
    positions: Union[str, os.PathLike[str], npt.ArrayLike, None] = None,
    velocities: Union[str, os.PathLike[str], npt.ArrayLike, None] = None,
    box: Union[float, Sequence[float], None] = None,
    boundary: Optional[Literal["periodic", "open"]] = None,
    potential: Literal["lj", "soft-sphere", "spring"] = "lj",
    epsilon: float = 1.0,
    sigma: float = 1.0,
    k: float = 1.0,
    rest_length: float = 1.0,
    mass: float = 1.0,
    seed: int = 87287,
    steps: int = 100,
    dt: float = 0.005,
    cutoff: float = 2.5,
    shift: bool = False,
    skin: float = 0.3,
    neigh_every: int = 1,
    neigh_check: bool = True,
    threads: int = 1,
    thermo_every: int = 50,
    xyz_every: Optional[int] = None,
    export_lammps: Union[str, os.PathLike[str], None] = None,
) -> MdResult:
    """``mechkit md`` in memory: the options under the command's names and defaults (the
    Lennard-Jones melt). ``positions``/``velocities``: a CSV or XYZ file, or an ``(N, d)``
    array. ``export_lammps``: a directory to write the run's start into as LAMMPS files
    (``in.lammps``, ``data.lammps``; run there with ``lmp -in in.lammps``).
    ``neigh_every``/``neigh_check``: LAMMPS's ``neigh_modify every N check yes|no`` (the
    report's ``dangerous_builds`` counts builds that came late). The GIL is
    released; Ctrl-C stops the run and raises KeyboardInterrupt. Bad values raise
    MechkitError naming the argument."""

class MdResult:
    """The result of ``mechkit.md()``."""

    @property
    def report(self) -> Dict[str, Any]:
        """``mechkit md --json`` as a dict."""
    @property
    def thermo(self) -> Dict[str, npt.NDArray[Any]]:
        """``thermo.csv``'s columns (``step`` as integers)."""
    @property
    def thermo_units(self) -> Dict[str, Optional[str]]: ...
    @property
    def rdf(self) -> Dict[str, npt.NDArray[np.float64]]:
        """``rdf.csv``'s columns ``r`` and ``g``."""
    @property
    def positions(self) -> npt.NDArray[np.float64]:
        """The final positions, ``(N, d)``."""
    @property
    def velocities(self) -> npt.NDArray[np.float64]:
        """The final velocities, ``(N, d)``."""
    @property
    def frames(self) -> Optional[npt.NDArray[np.float64]]:
        """With ``xyz_every``: the positions of every frame, ``(F, N, d)``."""
    @property
    def frame_steps(self) -> Optional[npt.NDArray[Any]]: ...
    @property
    def failed(self) -> bool:
        """Whether the run diverged (the command's exit status 1)."""
    @property
    def divergence(self) -> Optional[str]: ...
    def to_pandas(self) -> Any:
        """The thermo rows as a ``pandas.DataFrame``."""

def sweep(
    scenario: Union[Scenario, str, os.PathLike[str]],
    set: Union[str, Sequence[str], Mapping[str, Union[str, float, Sequence[float]]], None] = None,
    *,
    client: Any = None,
    random: Optional[int] = None,
    seed: Optional[int] = None,
    shard: Optional[str] = None,
    threads: Optional[int] = None,
    plot: Union[str, Literal[False], None] = None,
    **params: Union[str, float, Sequence[float]],
) -> SweepResult:
    """``mechkit sweep`` in memory. ``set``: ``--set`` texts (``"v0=0:5:51"``); keyword
    arguments: ``v0="0:5:51"``, ``k=[1, 2, 4]``, ``m=2.0`` (SI); the last varies fastest.
    ``random``/``seed``/``shard``/``threads`` as the command's options; ``plot``: the plot
    each run records for the overlay (None: the scenario's first; False: none). The GIL is
    released; Ctrl-C stops the sweep and raises KeyboardInterrupt. ``set`` may also be a
    dict of the keyword forms (``{"v0": "0:5:51"}``).

    ``client``: a ``dask.distributed.Client`` (``pip install 'mechkit[dask]'``) runs the
    sweep on its cluster, a few shards per worker thread, from the scenario's text; the parts
    are merged as ``mechkit sweep-merge`` merges them, so the result equals the one without
    a client to the bit. Ctrl-C cancels the shards; a failing run raises its
    ``MechkitError`` here. ``shard`` and ``threads`` go without ``client``."""

class SweepResult:
    """The result of ``mechkit.sweep()``."""

    @property
    def table(self) -> Dict[str, npt.NDArray[Any]]:
        """``sweep.csv``'s columns (``stop_reason`` as strings)."""
    @property
    def units(self) -> Dict[str, Optional[str]]: ...
    @property
    def rows(self) -> List[Dict[str, Any]]:
        """One summary per run."""
    @property
    def params(self) -> List[str]: ...
    @property
    def observables(self) -> List[str]: ...
    @property
    def runs(self) -> int: ...
    @property
    def manifest(self) -> Dict[str, Any]:
        """``sweep.manifest.json`` as a dict."""
    def to_csv(self) -> str:
        """The text of ``sweep.csv``, byte for byte."""
    def to_pandas(self) -> Any: ...
    def plot(self, *, style: Literal["paper", "slides"] = "paper") -> Plot:
        """The runs' plots in one figure, as ``mechkit sweep -o DIR`` draws it."""
    def __len__(self) -> int: ...

# mechanics: potential, collide, impulse, com, inertia. Each returns the dict that
# ``mechkit <command> ... --json`` prints; a value is a number in SI or a string as the
# command line takes it ("2 kg", "3, -1 m/s", "pi/6"); bad input raises MechkitError whose
# message names the argument (``m1: ...`` where the command line says ``--m1: ...``).

_Vector = Union[float, str, Sequence[_Value]]

def potential(
    U: Optional[str] = None,
    var: Union[str, Sequence[str], None] = None,
    *,
    force: Optional[str] = None,
    range: Union[str, Tuple[_Value, _Value], None] = None,
    energy: Optional[_Value] = None,
    mass: Optional[_Value] = None,
    x0: Optional[_Value] = None,
    v0: Optional[_Value] = None,
    at: Union[_Value, Sequence[Any], None] = None,
    samples: int = 2000,
    table: bool = False,
    **params: _Value,
) -> Dict[str, Any]:
    """``mechkit potential``: the analysis of a potential ``U(var)`` (or of a force,
    ``force="-k*x"``, with ``U = -∫F dx``) on ``range`` (``(a, b)`` or ``"a:b"``): the force,
    ``U''``, the equilibria with their stability, the singular points; with ``energy`` the
    turning points and allowed/forbidden regions; with ``mass``, ``x0`` (and ``v0``) the
    motion of a body released there; ``U``, ``F`` (and ``v``) at the points ``at``.
    ``**params`` give the formula's other names (``k=2``, ``U0="1 eV"``; a string may use the
    names before it). ``samples`` grid intervals find the equilibria and turning points.

    ``var="x,y"`` (or ``("x", "y", "z")``): a potential field; the result is ``F = -∇U`` and
    its values at the points ``at`` (``[(0, 1), (1, 0)]``).

    ``table=True`` adds ``"table"``: the energy diagram's columns (``x``, ``U``, ``F`` and
    ``v`` with a released body, as ``potential.csv``) as numpy arrays.

    >>> r = mechkit.potential("k*x^2/2", range=(-1, 1), k=2)
    >>> r["force"], r["equilibria"][0]["stability"]
    ('-k*x', 'stable')
    """

def collide(
    m1: _Value,
    v1: _Vector,
    m2: _Value,
    v2: _Vector,
    *,
    restitution: Union[float, str],
    normal: Optional[_Vector] = None,
    r1: Optional[_Vector] = None,
    r2: Optional[_Vector] = None,
    friction: Optional[_Value] = None,
    g: Optional[_Value] = None,
) -> Dict[str, Any]:
    """``mechkit collide``: two bodies collide with a coefficient of ``restitution`` (0 to 1,
    or ``"elastic"``, ``"perfectly-inelastic"``), in 1-D, 2-D or 3-D (velocities of 1 to 3
    components; a single 0 is at rest in any dimension). A mass may be ``float("inf")`` or
    ``"wall"`` (immovable). In 2-D/3-D give the contact ``normal`` from body 1 to body 2, or
    the centres ``r1`` and ``r2`` of two spheres; ``friction`` is Coulomb's coefficient along
    the contact plane; with ``g`` the rise ``v²/(2g)`` of each body afterwards.

    The result has ``collided``; when true, the velocities after (``v1``, ``v2``), the
    ``impulse`` on body 2, the kinetic energy lost, the centre-of-mass velocity and frame.

    >>> mechkit.collide(1, 2, 1, 0, restitution=1)["v2"]
    [2.0]
    """

def impulse(
    file: Union[str, os.PathLike[str], None] = None,
    *,
    t: Union[str, int, npt.ArrayLike, None] = None,
    f: Union[str, int, npt.ArrayLike, None] = None,
    method: str = "trapezoid",
    mass: Optional[_Value] = None,
    v0: Optional[_Value] = None,
) -> Dict[str, Any]:
    """``mechkit impulse``: the impulse ``J = ∫F dt`` of a force measured at times, its
    average ``J/Δt`` and peak, and with ``mass`` the change of velocity ``Δv = J/m`` (from
    ``v0``). The samples are a data file (``t`` and ``f`` name its columns, or number them
    from 1; by default the first two), or, without a file, two arrays ``t=`` and ``f=``
    (seconds and newtons). ``method``: trapezoid, simpson, left, right or midpoint. The
    running impulse is ``"cumulative"``.
    """

def com(
    body: Union[
        str, os.PathLike[str], npt.NDArray[Any], Sequence[Tuple[_Value, _Vector]], None
    ] = None,
    *,
    text: Optional[str] = None,
    velocities: Optional[Sequence[_Vector]] = None,
    unit: Optional[str] = None,
    total_mass: Optional[_Value] = None,
    about: Optional[_Vector] = None,
    threshold: Optional[float] = None,
    channel: Optional[str] = None,
    invert: bool = False,
    density_from_darkness: bool = False,
    pixel_size: Optional[_Value] = None,
    scale: Union[str, Tuple[_Value, _Value], None] = None,
    origin: Union[str, Tuple[_Value, _Value], None] = None,
    mark: Union[str, os.PathLike[str], None] = None,
) -> Dict[str, Any]:
    """``mechkit com``: the centre of mass of

    - point masses, a list of ``(mass, position)`` pairs (``[("2 kg", "0 m"), (1, 3)]``;
      a list, as a numpy array is an image),
      with their ``velocities`` (momentum, centre-of-mass frame, kinetic energy split);
      ``unit`` also expresses the centre of mass in a length (``"6371 km"``);
    - a body file (TOML parts: a path, or its text as ``text=``), rescaled to ``total_mass``,
      with its distance from ``about``;
    - an image: a PNG or JPEG path, or a numpy array of pixels, ``(height, width)`` grey,
      ``(height, width, 3)`` RGB or ``(height, width, 4)`` RGBA (composed on white), of
      ``uint8`` levels (or another integer type, 0 to 255) or floats from 0 to 1 (rounded to
      the nearest of 256 levels). The body is the pixels whose ``channel`` (``"sum"`` R+G+B
      from 0 to 3, or ``"r"``, ``"g"``, ``"b"``) is below ``threshold`` (1.5 for the sum,
      0.5 for one channel), or above it with ``invert``; ``density_from_darkness`` weighs
      each by its shade. ``pixel_size`` (``"0.5 mm"``) or ``scale`` (``"240 px = 12 cm"``)
      gives physical units; ``origin`` is the pixel of the physical origin (default the
      bottom-left corner, y up); ``total_mass`` spreads a mass over the pixels; ``about``
      adds ``I_zz`` about a point; ``mark`` writes a PNG with the body tinted and the centre
      marked. An array's ``file`` is ``"<array>"``; otherwise it reports what the same image
      read from a file does.
    """

def inertia(
    body: Union[str, os.PathLike[str], None] = None,
    *,
    text: Optional[str] = None,
    about: Optional[_Vector] = None,
    axis: Optional[_Vector] = None,
    total_mass: Optional[_Value] = None,
    unit: Optional[str] = None,
) -> Dict[str, Any]:
    """``mechkit inertia``: the mass, centre of mass, inertia tensor about the centre of mass
    and about the point ``about`` (parallel-axis theorem; default the origin), the principal
    moments and axes of a body file (a path, or its TOML as ``text=``), and with ``axis`` the
    moment and radius of gyration about the axis through ``about`` along it. ``total_mass``
    rescales the parts; ``unit`` expresses the moments in another unit (``"g*cm^2"``).
    A file that is not a valid body raises ScenarioError.
    """
