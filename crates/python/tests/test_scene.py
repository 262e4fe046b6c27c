"""Scenes read and written from Python, and every bad input a named exception."""

import pathlib

import numpy as np
import pytest

import newtonlab


def test_objects_read_and_write_the_files_keys():
    scene = newtonlab.load("example:projectile")
    ball = scene.particle("Ball")
    ball.velocity = (3.0, 4.0)
    assert ball.velocity == (3.0, 4.0)
    ball.velocity = {"magnitude": 2.0, "angle": 90.0}
    assert ball.velocity[0] == pytest.approx(0.0, abs=1e-15) and ball.velocity[1] == pytest.approx(2.0)
    ball.mass = 2
    scene.world.gravity = (0.0, -1.62)
    scene.simulation.integrator = "verlet"
    assert "mass" in dir(ball) and "velocity" in dir(ball)
    again = newtonlab.Scene.from_toml(scene.to_toml())
    assert again.particle("Ball").mass == 2.0
    assert again.world.gravity == (0.0, -1.62)
    assert again.simulation.integrator == "verlet"
    assert newtonlab.Scene.from_json(scene.to_json()).to_toml() == again.to_toml()


def test_a_rename_carries_references_along():
    scene = newtonlab.load("example:pendulum")
    rod = scene.rod(scene.rods[0])
    old = scene.particles[0]
    scene.particle(old).name = "Bob"
    assert "Bob" in scene.particles and old not in scene.particles
    assert rod.to == "Bob" or rod.__getattr__("from") == "Bob"


@pytest.mark.parametrize(
    "change, words",
    [
        (lambda s: setattr(s.particle("Ball"), "mass", -1.0), "mass must be greater than 0"),
        (lambda s: setattr(s.particle("Ball"), "mass", float("nan")), "mass"),
        (lambda s: setattr(s.particle("Ball"), "velocity", (1.0,)), r"must be \(x, y\)"),
        (lambda s: setattr(s.particle("Ball"), "position", (float("inf"), 0.0)), "position"),
        (lambda s: setattr(s.particle("Ball"), "color", "red"), "#rrggbb"),
        (lambda s: setattr(s.simulation, "integrator", "leapfrog"), "leapfrog"),
        (lambda s: setattr(s.simulation, "time_step", 0.0), "time_step|time step"),
        (lambda s: s.particle("Nobody"), "no particle named 'Nobody'"),
        (lambda s: s.spring("Nothing"), "no spring named 'Nothing'"),
    ],
)
def test_a_bad_value_raises_scene_error_and_changes_nothing(change, words):
    scene = newtonlab.load("example:projectile")
    before = scene.to_toml()
    with pytest.raises(newtonlab.SceneError, match=words):
        change(scene)
    assert scene.to_toml() == before, "the scene is as it was"
    assert len(newtonlab.run(scene, until=0.1)) == 11, "and the interpreter carries on"


@pytest.mark.parametrize(
    "change, error, words",
    [
        (lambda s: setattr(s.particle("Ball"), "mass", "heavy"), TypeError, "particle 'Ball': mass must be a number, got a str"),
        (lambda s: setattr(s.particle("Ball"), "mass", True), TypeError, "must be a number, got a bool"),
        (lambda s: setattr(s.particle("Ball"), "velocity", "fast"), TypeError, r"must be \(x, y\)"),
        (lambda s: setattr(s.particle("Ball"), "velocity", 3.0), TypeError, r"must be \(x, y\)"),
        (lambda s: setattr(s.particle("Ball"), "fixed", 1), TypeError, "True or False"),
        (lambda s: setattr(s.particle("Ball"), "name", 7), TypeError, "must be a string, got an int"),
        (lambda s: setattr(s.particle("Ball"), "mas", 1.0), AttributeError, "has no field 'mas'; did you mean 'mass'\\?"),
        (lambda s: s.particle("Ball").velocty, AttributeError, "has no field 'velocty'; did you mean 'velocity'\\?"),
        (lambda s: s.particle("Ball").zzz, AttributeError, "its fields are: mass, "),
    ],
)
def test_a_wrong_type_or_key_raises_pythons_own_error_and_changes_nothing(change, error, words):
    scene = newtonlab.load("example:projectile")
    before = scene.to_toml()
    with pytest.raises(error, match=words):
        change(scene)
    assert scene.to_toml() == before


def test_a_file_that_does_not_parse_names_its_line(tmp_path: pathlib.Path):
    bad = tmp_path / "bad.toml"
    bad.write_text('version = 1\n\n[[particle]]\nname = "B"\nmass = -2.0\nposition = [0.0, 0.0]\n')
    with pytest.raises(newtonlab.SceneError, match=r"bad.toml:5:8: particle 'B': mass must be greater than 0"):
        newtonlab.load(bad)
    (tmp_path / "broken.toml").write_text("version = 1\n[[particle]\n")
    with pytest.raises(newtonlab.SceneError, match="broken.toml:2"):
        newtonlab.load(str(tmp_path / "broken.toml"))
    with pytest.raises(FileNotFoundError, match="cannot read .*missing.toml"):
        newtonlab.load(tmp_path / "missing.toml")
    with pytest.raises(IsADirectoryError, match="is a folder"):
        newtonlab.load(tmp_path)
    with pytest.raises(newtonlab.SceneError, match="no example 'nope'"):
        newtonlab.load("example:nope")


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: newtonlab.run("example:projectile", until=float("nan")), "until"),
        (lambda: newtonlab.run("example:projectile", until=-1.0), "before|negative|0 or more"),
        (lambda: newtonlab.run("example:projectile", until=1.0, every=0.0), "every|interval"),
        (lambda: newtonlab.run("example:projectile", until=1e300), "too fine"),
        (lambda: newtonlab.run("example:projectile", until=2e5, every=1000.0), "no-limit"),
        (lambda: newtonlab.run("example:projectile", until=1.0, events="Ball.vx explodes"), "event"),
        (lambda: newtonlab.run("example:projectile", until=1.0, events="Nobody.vx crosses 0"), "Nobody"),
        (lambda: newtonlab.run(42, until=1.0), "a scene must be"),
        (lambda: newtonlab.sweep("example:projectile", {"Ball.mass": [1.0, float("nan")]}, 1.0, "max Ball.y"), "finite"),
        (lambda: newtonlab.sweep("example:projectile", {"Ball.mas": [1.0]}, 1.0, "max Ball.y"), "Ball.mas"),
        (lambda: newtonlab.sweep("example:projectile", {"Ball.mass": [1.0]}, 1.0, "biggest Ball.y"), "biggest"),
        (lambda: newtonlab.sweep("example:projectile", {"Ball.mass": "1:0:1"}, 1.0, "max Ball.y"), "1:0:1"),
        (lambda: newtonlab.Simulation("example:projectile").advance(to=float("inf")), "finite"),
        (lambda: newtonlab.validate(groups="nope"), "no group 'nope'"),
    ],
)
def test_bad_arguments_raise_scene_error(call, words):
    with pytest.raises(newtonlab.SceneError, match=words):
        call()


def test_a_failing_run_raises_simulation_error():
    scene = newtonlab.Scene.from_toml(
        """
version = 1
[world]
gravity = [0.0, 0.0]
[simulation]
integrator = "euler"
time_step = 0.1
[[particle]]
name = "A"
mass = 1.0
position = [2.0, 0.0]
[[spring]]
name = "S"
from = "A"
to = [0.0, 0.0]
stiffness = 1e99
natural_length = 1.0
"""
    )
    with pytest.raises(newtonlab.SimulationError):
        newtonlab.run(scene, until=100.0, every=1.0)


def test_examples_list_what_load_takes():
    names = dict(newtonlab.examples())
    assert "projectile" in names and names["projectile"]
    for name in names:
        assert isinstance(newtonlab.load(f"example:{name}"), newtonlab.Scene)


def test_the_package_has_a_version():
    assert isinstance(newtonlab.__version__, str)
    assert newtonlab.__version__.count(".") == 2, newtonlab.__version__


def test_bodies_are_objects_with_the_files_keys_and_columns():
    scene = newtonlab.load("example:block-on-incline")
    assert scene.bodies == ["held", "sliding"]
    held = scene.body("held")
    assert held.mass == 2.0 and held.angle == 20.0
    held.mass = 3.0
    assert scene.body("held").mass == 3.0
    with pytest.raises(newtonlab.SceneError, match="between 0 and 1"):
        held.restitution = 2.0
    # A density typed replaces the mass, as in the app's inspector.
    held.density = 10.0
    assert (held.mass, held.density) == (0.0, 10.0)
    held.mass = 2.0
    with pytest.raises(newtonlab.SceneError, match="no body named 'nothing'"):
        scene.body("nothing")
    traj = newtonlab.run(scene, until=1.0, every=0.5)
    assert traj.columns[1:9] == [
        "held.x", "held.y", "held.vx", "held.vy", "held.ax", "held.ay",
        "held.angle", "held.spin",
    ]
    # Held by friction: it stays where it was put.
    assert np.ptp(traj["held.x"]) < 1e-9
    # Sliding at g (sin 30° − 0.5 cos 30°): its speed after 1 s.
    speed = np.hypot(traj["sliding.vx"][-1], traj["sliding.vy"][-1])
    assert abs(speed - 9.81 * (0.5 - 0.5 * np.cos(np.radians(30.0)))) < 1e-9
