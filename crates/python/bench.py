"""How fast NewtonLab is from Python, against its own command line and against pymunk.

    python crates/python/bench.py [--cli target/release/newtonlab] [--repeat 3]

1. `newtonlab.run` against `newtonlab run` on the 1,000-ball pit over 1 s (rows every
   0.01 s), each the best of --repeat runs, interleaved: the cost of calling from Python.
2. `Simulation.step()` in a Python loop of a 10-particle scene: steps per second.
3. The 1,000-ball pit stepped for 1 s at 1 ms by NewtonLab (`Simulation.advance`) and by
   pymunk (if it is installed: `pip install pymunk`), built from the same scene: the same
   balls, box, restitution and gravity. pymunk is a game engine (soft contacts, no located
   impacts), so this compares speed, not results.

The machine is shared and noisy: compare figures of one run only, as ratios.
"""

import argparse
import pathlib
import subprocess
import time

import newtonlab

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def best(seconds):
    return min(seconds)


def timed(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def run_against_cli(cli, repeat):
    python, command_line = [], []
    for _ in range(repeat):
        python.append(timed(lambda: newtonlab.run("example:ball-pit", until=1.0, every=0.01)))
        command_line.append(
            timed(
                lambda: subprocess.run(
                    [cli, "run", "example:ball-pit", "--until", "1", "--every", "0.01", "--out", "/dev/null"],
                    check=True,
                )
            )
        )
    return best(python), best(command_line)


TEN = """
version = 1
[world]
gravity = [0.0, -9.81]
[world.bounds]
min = [-5.0, 0.0]
max = [5.0, 10.0]
[simulation]
integrator = "verlet"
time_step = 0.001
"""


def step_loop(steps=200_000):
    text = TEN + "".join(
        f'[[particle]]\nname = "p{i}"\nmass = 1.0\nradius = 0.1\nposition = [{i - 4.5}, {2 + i % 3}]\n'
        f"velocity = [{(-1) ** i * 0.7}, 0.0]\n"
        for i in range(10)
    )
    simulation = newtonlab.Simulation(newtonlab.Scene.from_toml(text))
    step = simulation.step
    seconds = timed(lambda: [step() for _ in range(steps)])
    return steps / seconds


def pit_newtonlab():
    simulation = newtonlab.Simulation("example:ball-pit")
    return 1000 / timed(lambda: simulation.advance(to=1.0))


def pit_pymunk():
    try:
        import pymunk
    except ImportError:
        return None
    scene = newtonlab.load("example:ball-pit")
    (xmin, ymin), (xmax, ymax) = scene.world.bounds
    # pymunk's restitution of a contact is the product of its two shapes' elasticities:
    # each shape gets the square root, so that ball on ball and ball on wall both bounce
    # at the scene's restitution.
    elasticity = scene.world.restitution ** 0.5
    space = pymunk.Space()
    space.gravity = scene.world.gravity
    walls = [((xmin, ymin), (xmax, ymin)), ((xmin, ymin), (xmin, ymax)), ((xmax, ymin), (xmax, ymax)), ((xmin, ymax), (xmax, ymax))]
    for a, b in walls:
        wall = pymunk.Segment(space.static_body, a, b, 0.0)
        wall.elasticity = elasticity
        space.add(wall)
    for name in scene.particles:
        ball = scene.particle(name)
        body = pymunk.Body(ball.mass, pymunk.moment_for_circle(ball.mass, 0, ball.radius))
        body.position = ball.position
        body.velocity = ball.velocity
        shape = pymunk.Circle(body, ball.radius)
        shape.elasticity = elasticity
        space.add(body, shape)
    return 1000 / timed(lambda: [space.step(0.001) for _ in range(1000)])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cli", default=str(REPOSITORY / "target" / "release" / "newtonlab"))
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    python, command_line = run_against_cli(args.cli, args.repeat)
    print(f"ball pit 1,000, 0-1 s, rows every 0.01 s: Python {python:.3f} s, command line {command_line:.3f} s, "
          f"Python / command line = {python / command_line:.3f}")
    print(f"Simulation.step() in a Python loop, 10 particles (verlet, 1 ms): {step_loop():,.0f} steps/s")
    ours = pit_newtonlab()
    theirs = pit_pymunk()
    print(f"ball pit 1,000 at 1 ms for 1 s: NewtonLab {ours:,.0f} steps/s", end="")
    if theirs is None:
        print("; pymunk is not installed")
    else:
        print(f", pymunk {pymunk_version()} {theirs:,.0f} steps/s, NewtonLab / pymunk = {ours / theirs:.2f}")


def pymunk_version():
    import pymunk

    return pymunk.version


if __name__ == "__main__":
    main()
