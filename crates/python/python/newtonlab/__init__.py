"""NewtonLab's exact 2D physics in Python.

Load a scene, change it, run it, sweep it, and read the numbers as numpy arrays — the same
numbers, bit for bit, as the ``newtonlab`` command line::

    import newtonlab
    scene = newtonlab.load("example:projectile")
    scene.particle("Ball").velocity = {"magnitude": 20.0, "angle": 45.0}
    traj = newtonlab.run(scene, until=3.0, every=0.01)
    traj["Ball.x"], traj["Ball.y"]        # numpy float64 arrays

``run`` is ``newtonlab run``, ``sweep`` is ``newtonlab sweep``, ``validate`` is
``newtonlab validate``; ``Simulation`` steps a scene from your own loop. Every bad input
raises ``SceneError`` (a ``ValueError``) with the scene file's own words, a file that
cannot be read ``FileNotFoundError``, ``IsADirectoryError`` or ``PermissionError``; a
run that fails raises ``SimulationError``.
"""

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
    sweep,
    validate,
)

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
