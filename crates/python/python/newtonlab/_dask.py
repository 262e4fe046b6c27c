"""A sweep fanned out over a Dask cluster (``newtonlab.sweep(..., client=...)``).

The grid's outermost field is cut into parts; each part is a sweep of its own, run on a
worker from the scene's file text (a scene file reads back bit for bit), and the parts'
rows are joined in order. Every run is the run the local sweep makes, so the table is the
local sweep's, bit for bit, on any cluster; the workers' warnings come back as warnings
here. Dask schedules, retries and moves the data; NewtonLab adds no distribution of its
own.
"""

from __future__ import annotations

import math
import warnings
from typing import Any, List, Optional, Sequence, Tuple

from . import _native


def _part(
    text: str, fields: Sequence[Tuple[str, List[float]]], until: float, measure: Any
) -> Tuple[_native.Table, List[str]]:
    """One part of a sweep, on a worker: its table and the warnings it raised."""
    scene = _native.Scene.from_toml(text)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = _native.sweep(scene, dict(fields), until, measure, threads=1)
    return table, [str(w.message) for w in caught]


def sweep_on(
    client: Any,
    scene: Any,
    vary: Any,
    until: float,
    measure: Any,
    parts: Optional[int] = None,
) -> _native.Table:
    """The sweep of ``scene`` over ``vary``, its runs shared out by the Dask ``client``
    (``dask.distributed.Client``) in ``parts`` parts (default: four per worker thread, at
    most one per value of the outermost field)."""
    if isinstance(scene, str):
        scene = _native.load(scene)
    fields = _native.sweep_values(scene, vary)
    text = scene.to_toml()
    outer_field, outer = fields[0]
    if parts is None:
        threads = sum(client.nthreads().values()) or 1
        parts = 4 * threads
    if not isinstance(parts, int) or parts < 1:
        raise _native.SceneError(f"parts must be a whole number of at least 1, got {parts!r}")
    size = math.ceil(len(outer) / min(parts, len(outer)))
    chunks = [outer[k : k + size] for k in range(0, len(outer), size)]
    futures = [
        client.submit(_part, text, [(outer_field, chunk)] + fields[1:], until, measure, pure=False)
        for chunk in chunks
    ]
    results = client.gather(futures)
    for _, problems in results:
        for problem in problems:
            warnings.warn(problem, stacklevel=3)
    return _native.Table.concat([table for table, _ in results])


__all__: List[str] = ["sweep_on"]
