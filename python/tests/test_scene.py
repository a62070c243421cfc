"""Scenes from Python values: the JSON carom reads, the packing fraction carom finds, carom's own
messages for a bad scene."""

from __future__ import annotations

import json
import math

import pytest

import carom


def test_a_scene_is_the_json_of_the_scene_format() -> None:
    scene = carom.Scene(
        width=10, height=4, boundary="walls", until=10.0, name="head-on",
        species=[carom.Species("disc", radius=0.5, mass=1.0), carom.Species("peg", radius=0.2, fixed=True)],
        particles=[carom.Disc("disc", 2, 2, vx=1), carom.Disc("disc", 8, 2, vx=-1), carom.Disc("peg", 5, 3.5)],
        generate=[carom.Block("disc", 3, "lattice", jitter=0.5, velocity=carom.maxwell(1.0), seed=7)],
        effects={"restitution": 0.9, "tc": 1e-4})
    assert json.loads(scene.dumps()) == {
        "name": "head-on",
        "box": {"width": 10, "height": 4, "boundary": "walls"},
        "species": [{"name": "disc", "radius": 0.5, "mass": 1.0}, {"name": "peg", "radius": 0.2, "fixed": True}],
        "particles": [{"species": "disc", "x": 2, "y": 2, "vx": 1, "vy": 0},
                      {"species": "disc", "x": 8, "y": 2, "vx": -1, "vy": 0},
                      {"species": "peg", "x": 5, "y": 3.5}],
        "generate": [{"species": "disc", "count": 3, "layout": "lattice", "jitter": 0.5,
                      "velocity": {"distribution": "maxwell", "temperature": 1.0}, "seed": 7}],
        "effects": {"restitution": 0.9, "tc": 1e-4},
        "until": 10.0,
    }


def test_not_a_number_is_refused_before_carom_sees_it(disc: carom.Species) -> None:
    with pytest.raises(ValueError):
        carom.Scene(width=math.nan, height=1, species=[disc]).dumps()


@pytest.mark.parametrize("count, fractions", [(101, (0.3, 0.7)), (7, (0.5, 0.5)), (250, (0.25, 0.25, 0.5))])
def test_a_mixture_at_a_packing_fraction_is_at_that_fraction_for_carom(count: int, fractions: tuple) -> None:
    kinds = [carom.Species("a", 0.5, 1.0), carom.Species("b", 0.7, 1.96), carom.Species("c", 0.6, 1.4)][:len(fractions)]
    scene = carom.Scene.at_packing_fraction(kinds, 0.3, count, fractions=fractions, aspect=1.5, seed=1,
                                            effects={"growth": 0.01}, until=0.5)
    assert scene.width == pytest.approx(1.5 * scene.height)
    assert scene.packing_fraction == pytest.approx(0.3, rel=1e-12)
    # compress reports the packing fraction carom itself finds before growing the discs.
    compression = carom.compress(scene, to_pressure=1e12).summary()["compression"]
    assert compression["packingFractionInitial"] == pytest.approx(0.3, rel=1e-12)


def test_check_returns_the_discs_carom_generated(gas: carom.Scene) -> None:
    assert gas.check()["particles"] == 200


def test_a_bad_scene_raises_carom_s_own_message(disc: carom.Species) -> None:
    massless = carom.Scene(width=10, height=10, species=[carom.Species("disc", 0.5)],
                           generate=[carom.Block("disc", 4, "lattice")])
    with pytest.raises(carom.CaromError) as refused:
        massless.check()
    assert refused.value.status == 2
    assert refused.value.message.endswith(
        "scene.json: species[0].mass: missing (a mobile species needs a mass; \"fixed\": true makes an immovable one)")
    assert str(refused.value).endswith("(carom exit status 2)")

    overlapping = carom.Scene(width=10, height=10, species=[disc],
                              particles=[carom.Disc("disc", 5, 5), carom.Disc("disc", 5.5, 5)])
    with pytest.raises(carom.CaromError) as refused:
        overlapping.check()
    assert "discs 0 and 1 overlap" in refused.value.message
