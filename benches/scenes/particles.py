#!/usr/bin/env python3
"""Writes a scene of N particles on a square grid (each with a name, mass, position,
velocity and radius) to standard output, for measuring what reading a long scene file
costs:

    python3 benches/scenes/particles.py 1000000 > million.toml
    /usr/bin/time -v newtonlab check million.toml
"""
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
side = max(1, int(n ** 0.5))
out = sys.stdout
out.write('version = 1\nname = "%d particles"\n[simulation]\ntime_step = 0.001\n\n' % n)
for i in range(n):
    out.write(
        '[[particle]]\nname = "p%d"\nmass = 1\nposition = [%d, %d]\n'
        "velocity = [0, 0]\nradius = 0.3\n\n" % (i, i % side, i // side)
    )
