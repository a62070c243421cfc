"""A parameter sweep: one carom run per value, and the table of their reduced pressures."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Sequence

import numpy as np

from ._command import PathLike
from .runs import Run, simulate
from .scene import Scene


@dataclass(frozen=True)
class Sweep:
    """One run per value, in the order given: ``values``, each run's reduced pressure ``Z`` and its
    error bar ``Z_error`` (NaN where carom gives none), the collisions carried out (pair plus wall) and
    the :class:`Run` objects themselves (their folders hold every output)."""

    values: np.ndarray
    Z: np.ndarray
    Z_error: np.ndarray
    collisions: np.ndarray
    runs: List[Run]

    def table(self) -> Dict[str, np.ndarray]:
        """The sweep as columns: ``value``, ``Z``, ``Z_error``, ``collisions``."""
        return {"value": self.values, "Z": self.Z, "Z_error": self.Z_error, "collisions": self.collisions}


def sweep(values: Sequence[float], scene_for: Callable[[float], Scene], *, folder: Optional[PathLike] = None,
          workers: int = 1, **simulate_options: Any) -> Sweep:
    """Runs ``carom simulate`` on ``scene_for(v)`` for each of ``values``: the first alone, then the
    others ``workers`` at a time (each run is its own carom process; mind the cores and the heap each
    takes), into ``folder/run-K`` (a new
    temporary folder for each if ``folder`` is None). ``simulate_options`` go to every
    :func:`carom.simulate` call (``engine``, ``until``, ``every``, ``observe``, ``carom``, ...). The first
    run that fails raises its :class:`carom.CaromError`.

    For an equation of state: ``sweep([0.2, 0.4, 0.6], lambda phi: Scene.at_packing_fraction(disc, phi, 400))``.
    """
    base = Path(folder) if folder is not None else None

    def one(k: int) -> Run:
        target = base / f"run-{k}" if base is not None else None
        return simulate(scene_for(values[k]), folder=target, **simulate_options)

    if not len(values):
        raise ValueError("sweep: no values")
    # The first run alone: a first use of the ./carom launcher builds carom, which two processes at once
    # must not do.
    runs = [one(0)]
    with ThreadPoolExecutor(max_workers=max(1, workers)) as pool:
        runs += list(pool.map(one, range(1, len(values))))
    summaries = [r.summary() for r in runs]
    z = [s["pressure"]["Z"] if s.get("pressure") else None for s in summaries]
    z_error = [s["pressure"]["Zerror"] if s.get("pressure") else None for s in summaries]
    return Sweep(values=np.asarray(values, dtype=np.float64), Z=_floats(z), Z_error=_floats(z_error),
                 collisions=np.array([s["collisions"]["pair"] + s["collisions"]["wall"] for s in summaries],
                                     dtype=np.int64),
                 runs=runs)


def _floats(values: Sequence[Optional[float]]) -> np.ndarray:
    return np.array([np.nan if v is None else v for v in values], dtype=np.float64)
