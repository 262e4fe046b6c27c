#!/usr/bin/env python3
"""Writes a cloth of N x N particles (the top row fixed, springs to the right and down
neighbours: 2 N (N - 1) springs) as a NewtonLab scene to standard output, for measuring
the app's drawing at scale:

    python3 benches/scenes/cloth.py 60 > cloth.toml
    newtonlab app cloth.toml --measure-frames 300
"""
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 60
spacing = 0.1
out = [
    "version = 1",
    f'name = "Cloth {n} x {n}"',
    "[world]",
    "gravitation = false",
    "electrostatics = false",
    "collisions = false",
    "[simulation]",
    'integrator = "rk4"',
    "time_step = 0.001",
    "[view]",
    f"center = [0.0, {-n * spacing / 2:.3f}]",
    f"width = {n * spacing * 1.5:.3f}",
]
for r in range(n):
    for c in range(n):
        out += [
            "[[particle]]",
            f'name = "p{r}_{c}"',
            "mass = 0.01",
            "radius = 0.02",
            f"position = [{(c - n / 2) * spacing:.3f}, {-r * spacing:.3f}]",
        ]
        if r == 0:
            out.append("fixed = true")
k = 0
for r in range(n):
    for c in range(n):
        for rr, cc in ((r, c + 1), (r + 1, c)):
            if rr < n and cc < n:
                k += 1
                out += [
                    "[[spring]]",
                    f'name = "s{k}"',
                    f'from = "p{r}_{c}"',
                    f'to = "p{rr}_{cc}"',
                    "stiffness = 50.0",
                    f"natural_length = {spacing}",
                    "damping = 0.05",
                ]
print("\n".join(out))
