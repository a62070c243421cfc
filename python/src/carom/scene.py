"""Scenes built from Python values, written as carom's scene JSON (docs/scene-format.md).

Nothing here checks the physics: carom's strict reader does, when a scene is run or :meth:`Scene.check`
ed, with the same ``error:`` lines as on the command line (raised as :class:`carom.CaromError`).
"""

from __future__ import annotations

import json
import math
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

from ._command import PathLike, Progress, run_carom

Json = Dict[str, Any]


@dataclass(frozen=True)
class Species:
    """A kind of disc: a name unique in the scene, a radius, and a mass (none for a fixed species)."""

    name: str
    radius: float
    mass: Optional[float] = None
    fixed: bool = False

    def to_json(self) -> Json:
        d: Json = {"name": self.name, "radius": self.radius}
        if self.mass is not None:
            d["mass"] = self.mass
        if self.fixed:
            d["fixed"] = True
        return d


def maxwell(temperature: float) -> Json:
    """Velocities of a thermal gas at kT = ``temperature`` (zero momentum, kinetic energy exactly count x kT)."""
    return {"distribution": "maxwell", "temperature": temperature}


def uniform(scale: float) -> Json:
    """Each velocity component uniform in [-scale, scale]."""
    return {"distribution": "uniform", "scale": scale}


@dataclass(frozen=True)
class Block:
    """A ``generate`` block: ``count`` discs of one species, or of a mixture (a list of names with
    ``fractions``), in a ``layout`` (``"lattice"``, ``"triangular"`` or ``"random"``), with optional
    ``jitter``, ``velocity`` (:func:`maxwell`, :func:`uniform`) and ``seed``."""

    species: Union[str, Sequence[str]]
    count: int
    layout: str = "random"
    fractions: Optional[Sequence[float]] = None
    jitter: Optional[float] = None
    velocity: Optional[Mapping[str, Any]] = None
    seed: Optional[int] = None

    def to_json(self) -> Json:
        d: Json = {"species": self.species if isinstance(self.species, str) else list(self.species)}
        if self.fractions is not None:
            d["fractions"] = list(self.fractions)
        d["count"] = self.count
        d["layout"] = self.layout
        for key in ("jitter", "velocity", "seed"):
            value = getattr(self, key)
            if value is not None:
                d[key] = dict(value) if key == "velocity" else value
        return d

    def counts(self) -> Dict[str, int]:
        """Discs of each species, as carom splits a mixture: round(count x fraction) each, the last
        listed species taking what remains."""
        if isinstance(self.species, str):
            return {self.species: self.count}
        names = list(self.species)
        fractions = list(self.fractions or [])
        split: Dict[str, int] = {}
        for name, fraction in zip(names[:-1], fractions[:-1]):
            split[name] = math.floor(self.count * fraction + 0.5)  # Java's Math.round: half up
        split[names[-1]] = self.count - sum(split.values())
        return split


@dataclass(frozen=True)
class Disc:
    """One disc listed in ``particles``: its species' name, centre and velocity."""

    species: str
    x: float
    y: float
    vx: float = 0.0
    vy: float = 0.0

    def to_json(self) -> Json:
        d: Json = {"species": self.species, "x": self.x, "y": self.y}
        if self.vx or self.vy:
            d.update(vx=self.vx, vy=self.vy)
        return d


@dataclass(frozen=True)
class Scene:
    """A scene: a box (``width`` x ``height``, ``boundary`` ``"periodic"`` or ``"walls"``), species,
    generated blocks, listed discs, effects (the keys of docs/scene-format.md's effects table, such as
    ``{"restitution": 0.9, "tc": 1e-4}`` or ``{"growth": 0.01}``) and the end time ``until``.

    Immutable: :meth:`with_` gives a changed copy.
    """

    width: float
    height: float
    species: Sequence[Species]
    generate: Sequence[Block] = ()
    particles: Sequence[Disc] = ()
    boundary: str = "periodic"
    effects: Mapping[str, Any] = field(default_factory=dict)
    until: float = 10.0
    name: Optional[str] = None

    @classmethod
    def at_packing_fraction(cls, species: Union[Species, Sequence[Species]], packing_fraction: float, count: int, *,
                            fractions: Optional[Sequence[float]] = None, layout: str = "random",
                            temperature: float = 1.0, seed: int = 0, aspect: float = 1.0,
                            jitter: Optional[float] = None, boundary: str = "periodic",
                            effects: Optional[Mapping[str, Any]] = None, until: float = 10.0,
                            name: Optional[str] = None) -> "Scene":
        """``count`` discs of one species or of a mixture (``fractions``, one per species) at a Maxwell
        ``temperature``, in a box of width/height ``aspect`` sized so that the discs cover
        ``packing_fraction`` of it: area = Σ n_s π r_s² / φ, with n_s as carom splits the mixture.
        Random placement jams near 0.547 and slows above about 0.45: use ``layout="triangular"`` (with
        some ``jitter``) for denser starts."""
        kinds = [species] if isinstance(species, Species) else list(species)
        names: Union[str, List[str]] = kinds[0].name if len(kinds) == 1 else [s.name for s in kinds]
        block = Block(names, count, layout, fractions=fractions if len(kinds) > 1 else None, jitter=jitter,
                      velocity=maxwell(temperature), seed=seed)
        radius = {s.name: s.radius for s in kinds}
        covered = sum(n * math.pi * radius[s] ** 2 for s, n in block.counts().items())
        height = math.sqrt(covered / packing_fraction / aspect)
        return cls(width=aspect * height, height=height, species=kinds, generate=[block], boundary=boundary,
                   effects=dict(effects or {}), until=until,
                   name=name or f"phi-{packing_fraction:g}")

    def with_(self, **changes: Any) -> "Scene":
        """A copy with the fields named changed (``scene.with_(until=50, effects={"growth": 0.01})``)."""
        return replace(self, **changes)

    @property
    def packing_fraction(self) -> float:
        """The share of the box the discs cover, Σ π r² / (width x height)."""
        radius = {s.name: s.radius for s in self.species}
        covered = sum(n * math.pi * radius[s] ** 2 for b in self.generate for s, n in b.counts().items())
        covered += sum(math.pi * radius[d.species] ** 2 for d in self.particles)
        return covered / (self.width * self.height)

    def to_json(self) -> Json:
        """The scene as carom's JSON object."""
        d: Json = {}
        if self.name is not None:
            d["name"] = self.name
        d["box"] = {"width": self.width, "height": self.height, "boundary": self.boundary}
        d["species"] = [s.to_json() for s in self.species]
        if self.particles:
            d["particles"] = [p.to_json() for p in self.particles]
        if self.generate:
            d["generate"] = [b.to_json() for b in self.generate]
        if self.effects:
            d["effects"] = dict(self.effects)
        d["until"] = self.until
        return d

    def dumps(self) -> str:
        """The scene file's text. Floats are written as Python's shortest repr, which carom reads back to
        the same doubles; NaN and infinities are refused here, as JSON has none."""
        return json.dumps(self.to_json(), indent=2, allow_nan=False) + "\n"

    def write(self, path: PathLike) -> Path:
        """Writes the scene file to ``path`` and returns that path."""
        target = Path(path)
        target.write_text(self.dumps(), encoding="utf-8")
        return target

    def check(self, *, carom: Optional[PathLike] = None, progress: Progress = False) -> Json:
        """Has carom read, generate and check the scene (strict keys and types, ranges, discs inside the
        box, no overlaps, fits the heap) and returns the summary of a run to t = 1e-9 (``particles``:
        the discs generated). Raises :class:`carom.CaromError` with carom's message for a bad scene."""
        with tempfile.TemporaryDirectory(prefix="carom-check-") as folder:
            scene = self.write(Path(folder) / "scene.json")
            summary = Path(folder) / "summary.json"
            run_carom(["simulate", scene, "--until", "1e-9", "--summary", summary], carom=carom, progress=progress)
            with open(summary, encoding="utf-8") as f:
                return json.load(f)


def scene_file(scene: Union[Scene, PathLike], folder: Path) -> Path:
    """The scene's file: ``scene`` itself if it is a path, else a Scene written to ``folder/scene.json``."""
    if isinstance(scene, Scene):
        return scene.write(folder / "scene.json")
    return Path(scene)
