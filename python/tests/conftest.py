"""The tests run the real carom: the command :func:`carom.find_command` finds (``CAROM``, set by the
JUnit test that runs this suite in the build, or the ./carom launcher of this clone)."""

from __future__ import annotations

import pytest

import carom


@pytest.fixture
def gas() -> carom.Scene:
    """200 equal discs at packing fraction 0.4 in a periodic box, thermal at kT = 1, to t = 2."""
    disc = carom.Species("disc", radius=0.5, mass=1.0)
    return carom.Scene.at_packing_fraction(disc, 0.4, 200, seed=3, until=2.0, name="gas")


@pytest.fixture
def disc() -> carom.Species:
    return carom.Species("disc", radius=0.5, mass=1.0)
