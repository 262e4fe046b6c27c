"""`newtonlab.run` and `newtonlab.Simulation` against the command line and against theory."""

import math

import numpy as np
import pytest

import newtonlab


def same_bits(table, rows, columns):
    """Every numeric column of `table` holds the CSV's numbers bit for bit."""
    header, body = rows[0], rows[1:]
    assert header == columns, "the same columns, in the same order"
    assert len(table) == len(body), "the same rows"
    for k, name in enumerate(header):
        if name == "event":
            assert table[name] == [row[k] for row in body], "the same events"
            continue
        expected = np.array([float(row[k]) for row in body])
        # Bits, not closeness: the CSV's numbers are the shortest text of each f64.
        assert np.array_equal(table[name].view(np.uint64), expected.view(np.uint64)), name


@pytest.mark.parametrize(
    "example, options",
    [
        ("spring-damped-light", dict(until=10.0, every=0.05)),
        ("collision", dict(until=3.0, every=0.003, ledger=True)),
        ("pendulum", dict(until=4.0, every=0.1, events=["bob.vx crosses 0 down"], ledger=True)),
        ("ball-pit", dict(until=0.5, every=0.05)),
        ("bowling", dict(until=2.0, every=0.01, ledger=True)),
    ],
)
def test_a_run_is_the_command_lines_csv_bit_for_bit(newtonlab_cli, example, options):
    args = ["run", f"example:{example}", "--until", str(options["until"]), "--every", str(options["every"])]
    for event in options.get("events", []):
        args += ["--events", event]
    if options.get("ledger"):
        args.append("--ledger")
    rows = newtonlab_cli(*args)
    traj = newtonlab.run(f"example:{example}", **options)
    same_bits(traj, rows, traj.columns)


def test_any_number_of_threads_gives_the_same_bits():
    one = newtonlab.run("example:ball-pit", until=0.3, every=0.05, threads=1)
    three = newtonlab.run("example:ball-pit", until=0.3, every=0.05, threads=3)
    for name in one.columns:
        assert np.array_equal(one[name].view(np.uint64), three[name].view(np.uint64)), name


def test_events_alone_are_rows_at_their_located_instants(newtonlab_cli):
    rows = newtonlab_cli("run", "example:pendulum", "--until", "5", "--events", "bob.vx crosses 0 down")
    traj = newtonlab.run("example:pendulum", until=5.0, events="bob.vx crosses 0 down")
    # Python names the event of every row; the command line only where rows are mixed.
    assert traj.columns[-1] == "event" and set(traj["event"]) == {"bob.vx crosses 0 down"}
    same_bits(traj, [rows[0] + ["event"]] + [r + ["bob.vx crosses 0 down"] for r in rows[1:]], traj.columns)
    assert np.all(np.abs(traj["bob.vx"]) < 1e-9), "each row is at a turning point"


PROJECTILE = """
version = 1
[world]
gravity = [0.0, -9.81]
[simulation]
integrator = "{integrator}"
time_step = 0.01
[[particle]]
name = "Ball"
mass = 0.3
position = [1.0, 2.0]
velocity = {{ magnitude = 5.0, angle = 53.13010235415598 }}
"""


@pytest.mark.parametrize("integrator", ["rk4", "verlet", "pefrl", "dopri5"])
def test_a_projectile_follows_kinematics(integrator):
    scene = newtonlab.Scene.from_toml(PROJECTILE.format(integrator=integrator))
    traj = newtonlab.run(scene, until=0.8, every=0.02)
    t = traj["t"]
    v0 = 5.0 * np.array([math.cos(math.radians(53.13010235415598)), math.sin(math.radians(53.13010235415598))])
    # Constant acceleration: each of these methods integrates a quadratic exactly, so
    # only rounding is left (some 1e-15 m a step).
    assert np.max(np.abs(traj["Ball.x"] - (1.0 + v0[0] * t))) < 1e-12
    assert np.max(np.abs(traj["Ball.y"] - (2.0 + v0[1] * t - 0.5 * 9.81 * t**2))) < 1e-12
    assert np.max(np.abs(traj["Ball.vy"] - (v0[1] - 9.81 * t))) < 1e-12


def test_impacts_are_a_table_with_names():
    with pytest.raises(newtonlab.SceneError, match="impacts=True"):
        newtonlab.run("example:collision", until=3.0, every=0.1).impacts
    traj = newtonlab.run("example:collision", until=3.0, every=0.1, impacts=True)
    impacts = traj.impacts
    assert impacts.columns == [
        "t", "particle", "other", "impulse", "normal_speed_before", "normal_speed_after", "kinetic_energy_lost",
    ]
    assert len(impacts) >= 1
    scene = newtonlab.load("example:collision")
    assert set(impacts["particle"]) <= set(scene.particles)
    assert impacts["t"].dtype == np.float64


def test_to_pandas_keeps_the_columns_in_order_indexed_by_time():
    pandas = pytest.importorskip("pandas")
    traj = newtonlab.run("example:spring-undamped", until=1.0, every=0.1)
    frame = traj.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert frame.index.name == "t" and np.array_equal(frame.index.to_numpy(), traj["t"])
    assert list(frame.columns) == traj.columns[1:] and len(frame) == len(traj) == 11
    assert frame.loc[0.5].equals(frame.iloc[5]), "a row by its instant"
    table = newtonlab.sweep("example:projectile-range", vary={"Ball.velocity.angle": [30.0, 60.0]},
                            until=7.0, measure="Ball.x at Ball.y crosses 0 down")
    assert list(table.to_pandas().columns) == table.columns, "no time: no index"


def test_a_simulation_steps_and_reads_like_a_run():
    scene = newtonlab.Scene.from_toml(PROJECTILE.format(integrator="rk4"))
    sim = newtonlab.Simulation(scene)
    for k in range(1, 51):
        sim.advance(to=k * 0.01)
    traj = newtonlab.run(scene, until=0.5, every=0.01)
    positions, velocities = sim.state
    assert positions.shape == (1, 2) and velocities.shape == (1, 2)
    # To k × 0.01, as the run's rows are: the same steps, the same bits.
    assert positions[0, 0] == traj["Ball.x"][-1] and velocities[0, 1] == traj["Ball.vy"][-1]
    stepped = newtonlab.Simulation(scene)
    for _ in range(50):
        stepped.step()
    # Step by step the time is a sum of 0.01s, not k × 0.01: equal to rounding.
    assert stepped.time == pytest.approx(0.5, abs=1e-12)
    assert stepped.positions[0, 1] == pytest.approx(positions[0, 1], abs=1e-12)
    sim.advance(to=0.8)
    assert sim.time == 0.8
    energies = sim.energies()
    assert energies["total"] == pytest.approx(0.5 * 0.3 * 25.0 + 0.3 * 9.81 * 2.0, rel=1e-12)


def test_setting_the_state_continues_from_it():
    scene = newtonlab.Scene.from_toml(PROJECTILE.format(integrator="rk4"))
    sim = newtonlab.Simulation(scene)
    sim.advance(to=0.3)
    sim.state = (np.array([[0.0, 10.0]]), np.array([[2.0, 0.0]]))
    sim.advance(to=1.3)
    x, v = sim.state
    # From (0, 10) at 2 m/s level, one second later: x = 2, y = 10 − g/2.
    assert x[0, 0] == pytest.approx(2.0, abs=1e-12)
    assert x[0, 1] == pytest.approx(10.0 - 9.81 / 2, abs=1e-12)
    assert v[0, 1] == pytest.approx(-9.81, abs=1e-12)
    with pytest.raises(newtonlab.SceneError, match="one row per particle"):
        sim.positions = np.zeros((2, 2))
    with pytest.raises(newtonlab.SceneError):
        sim.velocities = np.array([[float("nan"), 0.0]])
    assert sim.time == pytest.approx(1.3), "a refused state leaves the simulation as it was"


def test_a_bowled_disc_rolls_on_at_two_thirds_of_its_speed():
    """A disc (inertia ½) bowled at v₀ on a lane of friction μ rolls on at 2v₀/3 from
    t* = v₀/(3μg); its spin is then −v/r, and the run has its turning columns."""
    scene = newtonlab.load("example:bowling")
    ball = scene.particle("Ball")
    v0, r, mu = ball.velocity[0], ball.radius, scene.ramp("lane").friction
    trajectory = newtonlab.run(scene, until=2.0, every=0.5)
    assert "Ball.spin" in trajectory.columns and "angular_momentum" in trajectory.columns
    assert trajectory.columns.index("Ball.angle") == trajectory.columns.index("Ball.ay") + 1
    assert trajectory["Ball.vx"][-1] == pytest.approx(2 * v0 / 3, abs=1e-12)
    assert trajectory["Ball.spin"][-1] == pytest.approx(-2 * v0 / 3 / r, abs=1e-9)
    assert v0 / (3 * mu * 9.81) < 2.0


def test_turning_keys_are_checked_and_the_walls_friction_round_trips():
    scene = newtonlab.load("example:spin-bounce")
    ball = scene.particle("Ball")
    with pytest.raises(newtonlab.SceneError, match="inertia"):
        ball.inertia = -1.0
    assert ball.inertia == 0.4
    ball.spin = 10.0
    assert scene.particle("Ball").spin == 10.0
    (low, high, friction) = scene.world.bounds
    assert friction == 0.8
    scene.world.bounds = (low, high)
    assert len(scene.world.bounds) == 2
    with pytest.raises(newtonlab.SceneError, match="friction"):
        scene.world.bounds = (low, high, -1.0)
