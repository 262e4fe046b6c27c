"""Scenes built in code: the same scene as the file that says it, bit for bit; thousands
of particles from numpy arrays; every bad argument a Python exception that names it."""

import numpy as np
import pytest

import newtonlab

PENDULUM_FILE = """version = 1

[world]
gravity = [0.0, -9.81]

[simulation]
integrator = "rk4"
time_step = 0.001

[[particle]]
name = "bob"
mass = 0.5
radius = 0.1
position = [1.2, -1.6]

[[particle]]
name = "ball"
mass = 0.145
radius = 0.037
position = [-3.0, 0.5]
velocity = [4.0, 6.5]

[[spring]]
name = "k"
from = "ball"
to = [-3.0, 3.0]
stiffness = 20.0
natural_length = 1.0

[[rod]]
name = "arm"
from = [0.0, 0.0]
to = "bob"

[[string]]
name = "line"
from = "ball"
to = "bob"
length = 6.0

[[ramp]]
name = "floor"
from = [-6.0, -3.0]
to = [6.0, -3.0]
friction = 0.2
static_friction = 0.3
"""


def built_pendulum():
    s = newtonlab.Scene()
    s.simulation.integrator = "rk4"
    s.simulation.time_step = 0.001
    bob = s.add_particle(name="bob", mass=0.5, radius=0.1, position=(1.2, -1.6))
    s.add_particle(name="ball", mass=0.145, radius=0.037, position=np.array([-3.0, 0.5]),
                   velocity=(np.float64(4.0), 6.5))
    s.add_spring(name="k", from_="ball", to=(-3.0, 3.0), stiffness=20.0, natural_length=1.0)
    s.add_string(name="line", from_="ball", to="bob", length=6.0)
    s.add_rod(name="arm", from_=(0.0, 0.0), to="bob")
    s.add_ramp(name="floor", from_=(-6.0, -3.0), to=(6.0, -3.0), friction=0.2, static_friction=0.3)
    return s, bob


def test_a_scene_built_in_code_is_its_file_bit_for_bit():
    built, bob = built_pendulum()
    read = newtonlab.Scene.from_toml(PENDULUM_FILE)
    assert built.to_toml() == read.to_toml()
    assert bob.mass == 0.5 and bob.position == (1.2, -1.6)
    assert built.rod("arm").length == pytest.approx(2.0, abs=1e-15), "a rod's length: the ends' distance"
    assert built.rods == ["arm"] and built.strings == ["line"], "rods before strings, as a file reads them"
    a = newtonlab.run(built, until=1.0, every=0.25)
    b = newtonlab.run(read, until=1.0, every=0.25)
    for column in a.columns:
        assert np.array_equal(a[column], b[column]), column
    # Saved and read back, still the same scene.
    assert newtonlab.Scene.from_toml(built.to_toml()).to_toml() == read.to_toml()


def test_names_are_given_as_a_file_gives_them_and_kept_unique():
    s = newtonlab.Scene()
    assert s.add_particle(mass=1.0, position=(0, 0)).name == "p1"
    s.add_particle(name="p2", mass=1.0, position=(1, 0))
    assert s.add_particle(mass=1.0, position=(2, 0)).name == "p3"
    assert s.add_rod(from_="p1", to="p3").name == "rod1"
    with pytest.raises(newtonlab.SceneError, match="p1"):
        s.add_particle(name="p1", mass=1.0, position=(3, 0))
    assert s.particles == ["p1", "p2", "p3"], "a refused object leaves the scene as it was"


def test_thousands_of_particles_from_numpy_arrays():
    rng = np.random.default_rng(7)
    n = 2000
    grid = np.stack(np.meshgrid(np.arange(50), np.arange(40)), axis=-1).reshape(-1, 2) * 0.25
    velocities = rng.normal(size=(n, 2))
    masses = rng.uniform(0.5, 2.0, size=n)
    s = newtonlab.Scene()
    s.world.collisions = False
    names = s.add_particles(positions=grid, velocities=velocities, masses=masses, radii=0.05)
    assert len(names) == n and names[0] == "p1" and s.particles[-1] == f"p{n}"
    last = s.particle(names[-1])
    assert last.position == tuple(grid[-1]) and last.velocity == tuple(velocities[-1])
    assert last.mass == masses[-1] and last.radius == 0.05
    with pytest.raises(newtonlab.SceneError, match="3 values for 2 positions"):
        s.add_particles(positions=np.zeros((2, 2)) + 100.0, masses=np.ones(3))
    with pytest.raises(newtonlab.SceneError, match="mass must be greater than 0"):
        s.add_particles(positions=np.full((2, 2), 200.0), masses=np.array([1.0, -1.0]))
    with pytest.raises(TypeError, match=r"positions must be a numpy array of shape \(n, 2\)"):
        s.add_particles(positions=[1.0, 2.0], masses=1.0)
    assert len(s.particles) == n, "nothing added by a refused call"


@pytest.mark.parametrize(
    "call, error, words",
    [
        (lambda s: s.add_particle(mass=1.0), TypeError, r"add_particle\(\) missing required keyword argument: 'position'"),
        (lambda s: s.add_particle(mas=1.0, position=(0, 0)), TypeError, r"unexpected keyword argument 'mas'; did you mean 'mass'\?"),
        (lambda s: s.add_spring(frm="a", to=(0, 0)), TypeError, "unexpected keyword argument 'frm'; did you mean 'from_'"),
        (lambda s: s.add_rod(to=(0, 0)), TypeError, "missing required keyword argument: 'from_'"),
        (lambda s: s.add_particle(mass="heavy", position=(0, 0)), TypeError, r"add_particle\(\): mass must be a number, got a str"),
        (lambda s: s.add_particle(mass=-2.0, position=(0, 0)), newtonlab.SceneError, "mass must be greater than 0, got -2"),
        (lambda s: s.add_spring(from_="ghost", to=(0, 0), stiffness=1.0, natural_length=1.0), newtonlab.SceneError, "ghost"),
        (lambda s: s.add_ramp(from_=(0, 0), to=(1, 0), static_friction="x"), TypeError, "static_friction must be a number"),
    ],
)
def test_a_bad_argument_names_itself_and_changes_nothing(call, error, words):
    s = newtonlab.Scene()
    before = s.to_toml()
    with pytest.raises(error, match=words):
        call(s)
    assert s.to_toml() == before
