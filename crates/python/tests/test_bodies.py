"""Bodies and joints built in code: the same scene as its file, bit for bit; a physical
pendulum and an Atwood machine built in Python against their closed forms; bad
arguments in Python's voice."""

import math

import numpy as np
import pytest

import newtonlab


def test_a_block_built_in_code_is_its_file_bit_for_bit():
    scene = newtonlab.Scene()
    scene.add_ramp(from_=(-3.0, 0.0), to=(3.0, 0.0), friction=0.5)
    block = scene.add_body(name="block", width=0.4, height=0.2, mass=2.0, position=(0.0, 0.5),
                           velocity=(1.0, 0.0), friction=0.4, static_friction=0.6, restitution=0.0)
    wedge = scene.add_body(vertices=[(0.0, 0.0), (0.6, 0.0), (0.0, 0.3)], density=25.0,
                           position=(2.0, 2.0))
    assert block.mass == 2.0 and wedge.name == "body2" and scene.bodies == ["block", "body2"]
    text = scene.to_toml()
    assert 'shape = "box"' in text and 'shape = "polygon"' in text
    in_code = newtonlab.run(scene, until=1.0, every=0.25)
    from_file = newtonlab.run(newtonlab.Scene.from_toml(text), until=1.0, every=0.25)
    for column in in_code.columns:
        assert np.array_equal(in_code[column], from_file[column]), column


def test_a_ruler_on_a_nail_built_in_code_swings_at_its_period():
    scene = newtonlab.Scene()
    scene.world.gravitation = False
    scene.world.electrostatics = False
    length, width, m, g = 1.0, 0.02, 0.3, 9.81
    scene.add_body(name="ruler", width=width, height=length, mass=m, position=(0.0, -length / 2),
                   spin=0.02)
    assert scene.add_pin(body="ruler", at=(0.0, 0.0)) == "pin1"
    assert scene.joints == ["pin1"]
    # A small swing (amplitude 0.005 rad: the period's amplitude term is 1.3e-6 of it):
    # T = 2π √(I/(m g d)), I = m (L² + w²)/12 + m d² about the nail, d = L/2.
    d = length / 2
    inertia = m * (length**2 + width**2) / 12 + m * d * d
    period = 2 * math.pi * math.sqrt(inertia / (m * g * d))
    traj = newtonlab.run(scene, until=2.2 * period, events="pin1.angle crosses 0 up")
    times = traj["t"]
    assert len(times) == 2, times
    assert abs((times[1] - times[0]) - period) < 1e-5 * period
    assert abs(times[0] - period) < 1e-5 * period


def test_an_atwood_machine_built_in_code_accelerates_at_its_law():
    scene = newtonlab.Scene()
    scene.world.gravitation = False
    scene.world.electrostatics = False
    scene.add_body(name="m1", width=0.2, height=0.2, mass=3.0, position=(-0.5, 0.0))
    scene.add_body(name="m2", width=0.2, height=0.2, mass=1.0, position=(0.5, 0.0))
    scene.add_pulley(a="m1", b="m2", position=(0.0, 2.0), radius=0.5)
    traj = newtonlab.run(scene, until=0.5, every=0.5)
    a = (3.0 - 1.0) * 9.81 / (3.0 + 1.0)
    assert abs(traj["m1.y"][-1] - (0.0 - 0.5 * a * 0.25)) < 1e-9
    assert abs(traj["m2.y"][-1] - (0.0 + 0.5 * a * 0.25)) < 1e-9


def test_bodies_and_joints_refuse_in_pythons_voice():
    scene = newtonlab.Scene()
    with pytest.raises(newtonlab.SceneError, match="a mass or a density, not both"):
        scene.add_body(width=1.0, height=1.0, mass=1.0, density=2.0, position=(0, 0))
    with pytest.raises(TypeError, match="vertices must be a list"):
        scene.add_body(vertices="square", mass=1.0, position=(0, 0))
    with pytest.raises(newtonlab.SceneError, match="shape must be"):
        scene.add_body(shape="circle", mass=1.0, position=(0, 0))
    with pytest.raises(TypeError, match="did you mean 'width'"):
        scene.add_body(widht=1.0, height=1.0, mass=1.0, position=(0, 0))
    with pytest.raises(newtonlab.SceneError, match="no body 'door'"):
        scene.add_pin(body="door", at=(0.0, 0.0))
    scene.add_body(name="door", width=1.0, height=0.1, mass=1.0, position=(0.5, 0.0))
    with pytest.raises(TypeError, match="motor must be"):
        scene.add_pin(body="door", at=(0.0, 0.0), motor={"torque": 1.0, "spin": 2.0})
    with pytest.raises(newtonlab.SceneError, match="motor"):
        scene.add_pin(body="door", at=(0.0, 0.0), motor={"torque": math.inf})
    assert scene.joints == []
