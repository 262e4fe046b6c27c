"""NewtonLab's exact 2D physics in Python.

Load a scene, change it, run it, sweep it, and read the numbers as numpy arrays — the same
numbers, bit for bit, as the ``newtonlab`` command line::

    import newtonlab
    scene = newtonlab.load("example:projectile")
    scene.particle("Ball").velocity = {"magnitude": 20.0, "angle": 45.0}
    traj = newtonlab.run(scene, until=3.0, every=0.01)
    traj["Ball.x"], traj["Ball.y"]        # numpy float64 arrays

``run`` is ``newtonlab run``, ``sweep`` is ``newtonlab sweep`` (or, given a Dask
``client``, the same sweep fanned out over a cluster), ``validate`` is
``newtonlab validate``; ``Simulation`` steps a scene from your own loop. Every bad input
raises ``SceneError`` (a ``ValueError``) with the scene file's own words, a file that
cannot be read ``FileNotFoundError``, ``IsADirectoryError`` or ``PermissionError``; a
run that fails raises ``SimulationError``.
"""

import os
from typing import Any, Iterable, Mapping, Optional, Union

from ._native import (
    __version__,
    Scene,
    SceneError,
    SceneObject,
    Simulation,
    SimulationError,
    Table,
    Trajectory,
    examples,
    load,
    run,
    validate,
)
from . import _native


def sweep(
    scene: Union[str, "os.PathLike[str]", Scene],
    vary: Mapping[str, Any],
    until: float,
    measure: Union[str, Iterable[str]],
    threads: Optional[int] = None,
    client: Any = None,
    parts: Optional[int] = None,
) -> Table:
    """``newtonlab sweep``: a run per combination of the varied values, one row of measures
    each; NaN (and a warning) where a run had no such number.

    Runs in parallel on this machine (``threads``, every core when left out), or, given a
    ``dask.distributed.Client`` as ``client``, on its cluster in ``parts`` parts of the
    outermost field's values (default four per worker thread): the same table, bit for
    bit, either way.
    """
    if client is None:
        if parts is not None:
            raise TypeError("sweep(): parts is for a sweep over a Dask client (client=...)")
        return _native.sweep(scene, vary, until, measure, threads)
    if threads is not None:
        raise TypeError("sweep(): threads is for a local sweep; a Dask cluster has its workers")
    from ._dask import sweep_on

    return sweep_on(client, scene, vary, until, measure, parts)


__all__ = [
    "__version__",
    "Scene",
    "SceneError",
    "SceneObject",
    "Simulation",
    "SimulationError",
    "Table",
    "Trajectory",
    "examples",
    "load",
    "run",
    "sweep",
    "validate",
]
