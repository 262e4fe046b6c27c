"""Type stubs of NewtonLab's native module (re-exported by ``newtonlab``)."""

import os
from typing import Any, Dict, Iterable, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

Vector = Union[Tuple[float, float], Sequence[float], Mapping[str, float]]
"""``(x, y)``, or ``{"magnitude": m, "angle": degrees}``."""

SceneLike = Union["Scene", str, os.PathLike]
"""A ``Scene``, a scene file's path (``.toml`` or ``.json``), or ``"example:NAME"``."""

__version__: str
"""The package's version."""

class SceneError(ValueError):
    """A scene, a value or an argument NewtonLab cannot take; the message says which and why."""

class SimulationError(RuntimeError):
    """A run that failed: a value became infinite or not a number (the message names the particle and the time)."""

class SceneObject:
    """One object of a scene — a particle, spring, rod, string or ramp, the world or the
    settings — with the scene file's keys as attributes (``ball.mass``, ``ball.velocity``).

    Numbers are floats, vectors ``(x, y)`` tuples (set them as ``(x, y)`` or as
    ``{"magnitude": m, "angle": degrees}``), flags bools, colours ``"#rrggbb"``, a
    spring's or rod's ends a particle's name or an ``(x, y)`` fixed point. Writing a value
    checks it by the file's rules: a bad one raises ``SceneError`` and leaves the scene as
    it was. ``dir(obj)`` lists the keys.
    """

    name: str
    def __getattr__(self, key: str) -> Any: ...
    def __setattr__(self, key: str, value: Any) -> None: ...
    def __dir__(self) -> List[str]: ...

class Scene:
    """A scene: particles, springs, rods, strings and ramps in a world, with the settings of
    its simulation (the scene file's ``[world]`` and ``[simulation]``)."""

    def __init__(self) -> None:
        """An empty scene: the default world (g = 9.81 m/s² downwards) and settings."""
    @staticmethod
    def from_toml(text: str) -> "Scene":
        """A scene from the text of a TOML scene file; ``SceneError`` lists every problem with its line and column."""
    @staticmethod
    def from_json(text: str) -> "Scene":
        """A scene from the text of a JSON scene file."""
    def to_toml(self) -> str:
        """The scene as a TOML scene file's text."""
    def to_json(self) -> str:
        """The scene as a JSON scene file's text."""
    def copy(self) -> "Scene":
        """An independent copy."""
    def particle(self, name: str) -> SceneObject:
        """The particle called ``name``; ``SceneError`` when there is none."""
    def spring(self, name: str) -> SceneObject:
        """The spring called ``name``."""
    def rod(self, name: str) -> SceneObject:
        """The rod called ``name``."""
    def string(self, name: str) -> SceneObject:
        """The string called ``name``."""
    def ramp(self, name: str) -> SceneObject:
        """The ramp called ``name``."""
    def body(self, name: str) -> SceneObject:
        """The rigid body called ``name``: ``mass``, ``angle``, ``spin``, … (its shape as
        the file gives it)."""
    def add_particle(self, name: Optional[str] = None, **fields: Any) -> SceneObject:
        """Adds a particle and returns it. Keywords are the scene file's keys (``mass`` and
        ``position`` required; ``radius``, ``velocity``, ``charge``, ``fixed``, …); a missing
        or unknown one raises ``TypeError``, a bad value ``SceneError``; the name, when not
        given, is the one a file would give (``p1``, ``p2``, …)."""
    def add_spring(self, name: Optional[str] = None, **fields: Any) -> SceneObject:
        """Adds a spring: ``from_`` and ``to`` (a particle's name or a point), ``stiffness``,
        ``natural_length``, ``damping``."""
    def add_rod(self, name: Optional[str] = None, **fields: Any) -> SceneObject:
        """Adds a rod: ``from_`` and ``to``; ``length`` defaults to the ends' distance."""
    def add_string(self, name: Optional[str] = None, **fields: Any) -> SceneObject:
        """Adds a string: ``from_`` and ``to``; ``length`` defaults to the ends' distance."""
    def add_ramp(self, name: Optional[str] = None, **fields: Any) -> SceneObject:
        """Adds a ramp: ``from_`` and ``to`` (points), ``friction``, ``static_friction``, …"""
    def add_body(self, name: Optional[str] = None, **fields: Any) -> SceneObject:
        """Adds a rigid body (``shape="box"`` with ``width``, ``height``, or ``vertices``;
        ``mass`` or ``density``; ``position``; the file's other keys) and returns it."""
    def add_pin(
        self,
        name: Optional[str] = None,
        *,
        body: str,
        at: Tuple[float, float],
        motor: Optional[Mapping[str, float]] = None,
        limits: Optional[Tuple[float, float]] = None,
    ) -> str:
        """Adds a pin holding ``body`` to the world at ``at``; returns its name."""
    def add_hinge(
        self,
        name: Optional[str] = None,
        *,
        a: str,
        b: str,
        at: Tuple[float, float],
        motor: Optional[Mapping[str, float]] = None,
        limits: Optional[Tuple[float, float]] = None,
    ) -> str:
        """Adds a hinge: bodies ``a`` and ``b`` share the point ``at``; returns its name."""
    def add_pulley(
        self,
        name: Optional[str] = None,
        *,
        a: str,
        b: str,
        position: Tuple[float, float],
        radius: float,
        mass: float = 0.0,
        inertia: float = 0.5,
    ) -> str:
        """Adds a pulley: a string from ``a`` over a wheel at ``position`` to ``b``."""
    @property
    def joints(self) -> List[str]:
        """The pins', hinges' and pulleys' names."""
    def add_force(
        self,
        name: Optional[str] = None,
        *,
        fx: str = "0",
        fy: str = "0",
        on: Union[None, str, Sequence[str]] = None,
        potential: Optional[str] = None,
    ) -> str:
        """Adds a force of one's own (``[[force]]``): expressions of x, y, vx, vy, t, m, q;
        returns its name."""
    @property
    def forces(self) -> List[str]:
        """The forces of its own' names."""
    def add_particles(
        self,
        positions: npt.ArrayLike,
        masses: Union[float, npt.ArrayLike],
        velocities: Optional[npt.ArrayLike] = None,
        radii: Union[float, npt.ArrayLike, None] = None,
    ) -> List[str]:
        """Adds ``n`` particles at once: ``positions`` and ``velocities`` as (n, 2) arrays,
        ``masses`` and ``radii`` as arrays of n or one number for all; returns their names."""
    @property
    def world(self) -> SceneObject:
        """The world: ``gravity``, the pair forces' constants, ``bounds``."""
    @property
    def simulation(self) -> SceneObject:
        """The settings: ``integrator``, ``time_step``, ``start_time``, …"""
    @property
    def particles(self) -> List[str]:
        """The particles' names, in scene order."""
    @property
    def springs(self) -> List[str]: ...
    @property
    def rods(self) -> List[str]: ...
    @property
    def strings(self) -> List[str]: ...
    @property
    def ramps(self) -> List[str]: ...
    @property
    def bodies(self) -> List[str]:
        """The rigid bodies' names, in scene order."""

class Table:
    """Named columns of equal length: ``table["t"]`` is a numpy float64 array (a text
    column, a list of strings); ``table.columns`` the names in order."""

    @property
    def columns(self) -> List[str]: ...
    @overload
    def __getitem__(self, name: Literal["event", "particle", "other"]) -> List[str]: ...
    @overload
    def __getitem__(self, name: str) -> npt.NDArray[np.float64]:
        """A column of numbers; the text columns (``event``, an impact's ``particle`` and
        ``other``) are lists of strings."""
    def __contains__(self, name: str) -> bool: ...
    def __len__(self) -> int:
        """The number of rows."""
    def keys(self) -> List[str]: ...
    def to_dict(self) -> Dict[str, Union[npt.NDArray[np.float64], List[str]]]: ...
    @staticmethod
    def concat(tables: Sequence["Table"]) -> "Table":
        """The rows of ``tables`` (of the same columns), one after another."""
    @staticmethod
    def _from_columns(names: Sequence[str], columns: Sequence[Any]) -> "Table": ...
    def to_pandas(self) -> Any:
        """A pandas DataFrame of the columns, in order, indexed by ``t`` where the table
        has it (needs pandas)."""

class Trajectory(Table):
    """A run's rows by ``newtonlab run``'s column names (``traj["Ball.x"]``, ``traj["t"]``),
    the same numbers bit for bit; with events, a column ``event`` names each row's event
    (empty for a sample)."""

    @property
    def impacts(self) -> Table:
        """Every impact: t, particle, other (a particle, a ramp, or ``wall``), impulse (N·s),
        normal_speed_before, normal_speed_after (m/s), kinetic_energy_lost (J); kept with
        ``run(..., impacts=True)``, ``SceneError`` otherwise."""
    @property
    def note(self) -> Optional[str]:
        """When the interval is not a whole number of time steps, why some were shortened."""

class Simulation:
    """A scene's simulation stepped from Python. Setting ``positions``, ``velocities`` or
    ``state`` continues from the state given, at the present time, as a saved state
    would (checked as a scene file is); the energy ledger starts again there."""

    def __init__(self, scene: SceneLike, ledger: bool = False) -> None: ...
    def step(self) -> None:
        """Advances by one time step."""
    def advance(self, *, to: float) -> None:
        """Advances to exactly ``to`` seconds (nothing happens for an instant not ahead)."""
    @property
    def time(self) -> float:
        """Simulated time, seconds."""
    @property
    def names(self) -> List[str]:
        """The particles' names, in the order of the arrays' rows."""
    positions: npt.NDArray[np.float64]
    """Positions, metres: an (n, 2) array."""
    velocities: npt.NDArray[np.float64]
    """Velocities, m/s: an (n, 2) array."""
    state: Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]
    """``(positions, velocities)``."""
    def energies(self) -> Dict[str, float]:
        """``kinetic``, ``potential``, ``total`` (J); with the ledger, ``dissipated_*`` too."""
    def momentum(self) -> Tuple[float, float]:
        """Momentum, kg·m/s."""

def load(source: Union[str, os.PathLike]) -> Scene:
    """Reads a scene file (``.toml`` or ``.json``) or ``"example:NAME"``.

    Raises ``SceneError`` for a scene with problems (each at its line and column),
    ``FileNotFoundError``, ``IsADirectoryError`` or ``PermissionError`` for a file that
    cannot be read."""

def examples() -> List[Tuple[str, str]]:
    """The built-in scenes: ``(name, title)`` pairs, each loadable as ``load("example:NAME")``."""

def run(
    scene: SceneLike,
    until: float,
    every: Optional[float] = None,
    events: Union[None, str, Iterable[str]] = None,
    ledger: bool = False,
    impacts: bool = False,
    no_limit: bool = False,
    threads: Optional[int] = None,
) -> Trajectory:
    """Runs ``scene`` to ``until`` seconds: ``newtonlab run``'s rows, bit for bit.

    ``every``: the sampling interval (default 0.01 s, or no samples with ``events``);
    ``events``: ``"QUANTITY crosses VALUE [up|down]"``, each a row at its located instant;
    ``ledger``: the energy ledger's columns; ``impacts``: keep every impact for
    ``traj.impacts`` (off by default: a resting pile counts thousands a step);
    ``no_limit``: run however long it takes (otherwise more than 10⁸ steps, 10⁹
    particle-steps or 10⁸ numbers raise ``SceneError``).
    """

def sweep(
    scene: SceneLike,
    vary: Mapping[str, Union[Sequence[float], npt.ArrayLike, str]],
    until: float,
    measure: Union[str, Iterable[str]],
    threads: Optional[int] = None,
) -> Table:
    """``newtonlab sweep``: a run per combination of the varied values (in parallel), one row
    of measures each; NaN (and a warning) where a run had no such number."""

def sweep_values(
    scene: SceneLike, vary: Mapping[str, Union[Sequence[float], npt.ArrayLike, str]]
) -> List[Tuple[str, List[float]]]:
    """The values each field of ``vary`` takes in a sweep, the first outermost."""

def validate(
    groups: Union[None, str, Iterable[str]] = None, tolerance: float = 1e-6, threads: Optional[int] = None
) -> List[Dict[str, Any]]:
    """``newtonlab validate``'s checks: one record per check, with ``group``, ``what``,
    ``error``, ``limit`` and ``passed``."""
