"""A sweep over packing fractions: one run each, and the table of Z against the literature."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import carom


def henderson(phi: np.ndarray) -> np.ndarray:
    """Henderson's equation of state of the hard-disc fluid, Z = (1 + φ²/8) / (1 - φ)² (Mol. Phys. 30, 971, 1975)."""
    return (1 + phi ** 2 / 8) / (1 - phi) ** 2


def test_a_sweep_gives_z_against_the_packing_fraction(disc: carom.Species, tmp_path: Path) -> None:
    phis = [0.2, 0.4]
    result = carom.sweep(phis, lambda phi: carom.Scene.at_packing_fraction(disc, phi, 400, seed=11, until=4.0),
                         folder=tmp_path, workers=2)
    assert result.values.tolist() == phis
    assert [r.folder for r in result.runs] == [tmp_path / "run-0", tmp_path / "run-1"]
    assert np.all(result.collisions > 0)
    assert result.Z[0] < result.Z[1]
    # A short run from random addition: Henderson's Z within 6 error bars and 5 %.
    expected = henderson(result.values)
    assert np.all(np.abs(result.Z - expected) < 6 * result.Z_error + 0.05 * expected), (result.Z, result.Z_error)
    assert set(result.table()) == {"value", "Z", "Z_error", "collisions"}
