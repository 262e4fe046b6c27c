"""What a student writes, as mypy must accept it (checked by test_types.py)."""

import numpy as np

import newtonlab

scene = newtonlab.Scene()
ball = scene.add_particle(name="Ball", mass=0.145, radius=0.037, position=(0.0, 0.0),
                          velocity=(30.0, 20.0))
scene.add_rod(from_=(0.0, 5.0), to="Ball")
names: list[str] = scene.add_particles(positions=np.arange(6.0).reshape(3, 2) + 10.0,
                                          masses=1.0)
traj = newtonlab.run(scene, until=2.0, every=0.1)
highest: float = float(traj["Ball.y"].max())
times = traj["t"] * 1000.0
events: list[str] = newtonlab.run(scene, until=1.0, events="Ball.vy crosses 0")["event"]
frame = traj.to_pandas()
table = newtonlab.sweep(scene, vary={"Ball.mass": [1.0, 2.0]}, until=1.0, measure="max Ball.y")
force: str = scene.add_force(on="Ball", fx="-0.1*vx", fy="0.2*sin(t)")
joined = newtonlab.Table.concat([table, table])
board = scene.add_body(name="board", width=1.0, height=0.1, mass=2.0, position=(3.0, 1.0))
nail: str = scene.add_pin(body="board", at=(2.5, 1.0), motor={"torque": 0.5})
print(highest, times.shape, events, len(names), frame.shape, len(table), ball.mass, force, len(joined),
      board.mass, nail, scene.joints)
