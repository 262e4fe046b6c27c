"""`newtonlab.sweep` against `newtonlab sweep`; `validate`; the lock released; memory kept."""

import threading
import time

import numpy as np
import pytest

import newtonlab

MEASURES = ["Ball.x at Ball.y crosses 0 down", "max Ball.y", "t at Ball.y crosses 0 down"]


def test_a_sweep_is_the_command_lines_bit_for_bit(newtonlab_cli):
    args = ["sweep", "example:projectile-range", "--vary", "Ball.velocity.angle=10:80:5", "--until", "7"]
    for measure in MEASURES:
        args += ["--measure", measure]
    rows = newtonlab_cli(*args)
    table = newtonlab.sweep("example:projectile-range", {"Ball.velocity.angle": "10:80:5"}, until=7.0, measure=MEASURES, threads=2)
    assert table.columns == rows[0]
    for k, name in enumerate(rows[0]):
        expected = np.array([float(row[k]) if row[k] else np.nan for row in rows[1:]])
        assert np.array_equal(table[name].view(np.uint64), expected.view(np.uint64)), name


def test_a_sweep_over_an_array_meets_theory_and_any_thread_count_gives_the_same_bits():
    angles = np.arange(10.0, 81.0, 10.0)
    one = newtonlab.sweep("example:projectile-range", {"Ball.velocity.angle": angles}, until=7.0, measure="Ball.x at Ball.y crosses 0 down", threads=1)
    three = newtonlab.sweep("example:projectile-range", {"Ball.velocity.angle": angles}, until=7.0, measure="Ball.x at Ball.y crosses 0 down", threads=3)
    ranges = one["Ball.x at Ball.y crosses 0 down"]
    assert np.array_equal(ranges, three["Ball.x at Ball.y crosses 0 down"])
    theory = 30.0**2 * np.sin(2 * np.radians(angles)) / 9.81
    # The landing is located to 1e-12 s inside its step; rk4 is exact for the parabola.
    assert np.max(np.abs(ranges - theory)) < 1e-9


def test_a_measure_that_finds_nothing_is_nan_with_a_warning():
    with pytest.warns(UserWarning, match="happened 0 times"):
        table = newtonlab.sweep("example:projectile-range", {"Ball.velocity.angle": [45.0]}, until=1.0, measure="Ball.x at Ball.y crosses 0 down")
    assert np.isnan(table["Ball.x at Ball.y crosses 0 down"][0])


def test_the_lock_is_released_while_a_sweep_runs():
    counted = []
    done = threading.Event()

    def count():
        while not done.is_set():
            counted.append(1)
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    started = len(counted)
    # Some seconds of work on one thread: 600 runs of 7 s at 1 ms steps.
    newtonlab.sweep("example:projectile-range", {"Baseball.velocity.angle": np.linspace(10, 80, 600)}, until=7.0, measure="max Baseball.y", threads=1)
    during = len(counted) - started
    done.set()
    counter.join()
    # Holding the lock, the counter would not have run at all.
    assert during > 50, during


def resident_bytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    raise AssertionError("no VmRSS")


def test_a_thousand_runs_do_not_grow_memory():
    scene = newtonlab.load("example:collision")
    for _ in range(50):
        newtonlab.run(scene, until=0.2, every=0.01)
    before = resident_bytes()
    for _ in range(1000):
        traj = newtonlab.run(scene, until=0.2, every=0.01)
        traj["t"]
    grown = resident_bytes() - before
    assert grown < 10_000_000, f"grew {grown / 1e6:.1f} MB"


def test_validate_returns_the_checks_as_records():
    records = newtonlab.validate(groups=["events", "drag"])
    assert records and {r["group"] for r in records} == {"events", "drag"}
    assert all(set(r) == {"group", "what", "error", "limit", "passed"} for r in records)
    assert all(r["passed"] for r in records), [r for r in records if not r["passed"]]
