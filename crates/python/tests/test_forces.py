"""Round two's physics from Python: drag from C_d and ρ, the magnetic field, forces of
one's own built in code, against closed forms and against the same scene read from a
file; a sweep fanned out over a Dask cluster, bit for bit the local sweep."""

import math
import pickle

import numpy as np
import pytest

import newtonlab


def weightless():
    scene = newtonlab.Scene()
    scene.world.gravity = (0.0, 0.0)
    scene.world.gravitation = False
    scene.world.electrostatics = False
    return scene


def test_a_drag_coefficient_falls_to_its_terminal_speed():
    scene = newtonlab.Scene()
    scene.world.air_density = 1.2
    ball = scene.add_particle(name="ball", mass=0.6, radius=0.11, position=(0.0, 500.0), drag_coefficient=0.47)
    assert ball.drag_coefficient == 0.47
    c = 0.5 * 1.2 * 0.47 * math.pi * 0.11**2
    terminal = math.sqrt(0.6 * 9.81 / c)
    traj = newtonlab.run(scene, until=3.0, every=1.0)
    theory = -terminal * np.tanh(9.81 * traj["t"] / terminal)
    # rk4 at 1 ms against the closed form: its own error is some 1e-13.
    assert np.max(np.abs(traj["ball.vy"] - theory)) < 1e-9 * terminal
    with pytest.raises(newtonlab.SceneError, match="drag coefficient|drag_coefficient"):
        ball.quadratic_drag = 0.01


def test_the_cyclotron_circles_at_m_v_over_q_b():
    scene = weightless()
    scene.world.magnetic_field = 1.5
    m, q, v, b = 2.0, 0.5, 3.0, 1.5
    radius, omega = m * v / (q * b), q * b / m
    scene.add_particle(name="ion", mass=m, charge=q, radius=0.1, position=(0.0, radius), velocity=(v, 0.0))
    traj = newtonlab.run(scene, until=2 * math.pi / omega, every=0.5)
    t = traj["t"]
    assert np.max(np.abs(traj["ion.x"] - radius * np.sin(omega * t))) < 1e-9 * radius
    assert np.max(np.abs(traj["ion.y"] - radius * np.cos(omega * t))) < 1e-9 * radius


def test_a_force_built_in_code_is_the_files_bit_for_bit_and_meets_its_quadrature():
    scene = weightless()
    scene.add_particle(name="bob", mass=1.0, radius=0.1, position=(1.5, 0.0))
    name = scene.add_force(on="bob", fx="-2*x - 0.5*x^3", potential="x^2 + 0.125*x^4")
    assert name == "force1" and scene.forces == ["force1"]
    text = scene.to_toml()
    assert "[[force]]" in text and 'fx = "-2*x - 0.5*x^3"' in text
    from_file = newtonlab.run(newtonlab.Scene.from_toml(text), until=2.0, every=0.25, ledger=True)
    in_code = newtonlab.run(scene, until=2.0, every=0.25, ledger=True)
    for column in in_code.columns:
        assert np.array_equal(in_code[column], from_file[column]), column
    # The books close: the potential is booked.
    assert np.max(np.abs(in_code["energy_residual"])) < 1e-9
    # A quarter period by Simpson's rule of the energy integral (x = A sin θ).
    a = 1.5
    theta = np.linspace(0.0, math.pi / 2, 2001)
    f = 1.0 / np.sqrt(2.0 * (1.0 + a * a * (1.0 + np.sin(theta) ** 2) / 8.0))
    weights = np.ones_like(theta)
    weights[1:-1:2], weights[2:-1:2] = 4.0, 2.0
    quarter = float(np.sum(weights * f) * (theta[1] - theta[0]) / 3.0)
    sim = newtonlab.Simulation(scene)
    sim.advance(to=quarter)
    assert abs(sim.positions[0][0]) < 1e-9 * a


def test_bad_forces_raise_in_the_files_words():
    scene = weightless()
    scene.add_particle(name="bob", mass=1.0, position=(1.0, 0.0))
    with pytest.raises(newtonlab.SceneError, match="names 'k': a force may name x, y, vx, vy, t, m, q, pi"):
        scene.add_force(fx="-k*x")
    with pytest.raises(newtonlab.SceneError, match="there is no particle 'bib'"):
        scene.add_force(on=["bib"], fx="1")
    with pytest.raises(newtonlab.SceneError, match="the energy books would not close"):
        scene.add_force(fx="-x", potential="x^2")
    with pytest.raises(TypeError, match="on must be"):
        scene.add_force(on=3, fx="1")
    assert scene.forces == []  # nothing half-added


def test_a_table_pickles_whole_and_a_trajectory_refuses():
    table = newtonlab.sweep("example:projectile-range", {"Ball.velocity.angle": [30.0, 60.0]}, until=7.0,
                            measure="Ball.x at Ball.y crosses 0 down", threads=1)
    back = pickle.loads(pickle.dumps(table))
    assert back.columns == table.columns
    assert all(np.array_equal(back[c], table[c]) for c in table.columns)
    with pytest.raises(TypeError, match="Trajectory does not pickle"):
        pickle.dumps(newtonlab.run("example:projectile", until=0.1))


def test_a_sweep_over_a_dask_cluster_is_the_local_sweep_bit_for_bit():
    distributed = pytest.importorskip("distributed")
    scene = newtonlab.load("example:projectile-range")
    vary = {"Baseball.velocity.angle": "20:70:5", "Baseball.quadratic_drag": [0.0, 0.0005, 0.001]}
    measure = ["Baseball.x at Baseball.y crosses 0 down", "max Baseball.y"]
    local = newtonlab.sweep(scene, vary, until=7.0, measure=measure, threads=2)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            spread = newtonlab.sweep(scene, vary, until=7.0, measure=measure, client=client, parts=4)
    assert spread.columns == local.columns
    assert len(spread) == 11 * 3
    for column in local.columns:
        assert np.array_equal(spread[column].view(np.uint64), local[column].view(np.uint64)), column
    with pytest.raises(TypeError, match="parts is for a sweep over a Dask client"):
        newtonlab.sweep(scene, vary, until=7.0, measure=measure, parts=2)
