"""carom's output files read into numpy: CSV tables (final state, packings, observables), the JSON
summary, trajectories in extended XYZ and GSD, and freud's Box of a run's box."""

from __future__ import annotations

import csv
import json
from dataclasses import dataclass
from typing import Any, Dict, Iterator, List, Sequence, Tuple, Union

import numpy as np

from ._command import PathLike

#: A CSV file's columns by header name, each a numpy array (``id`` as int64, numbers as float64).
Table = Dict[str, np.ndarray]


def read_csv(path: PathLike) -> Table:
    """A CSV file carom wrote (``FINAL.csv``, ``compress``'s packing, an observable's ``KEY.csv``) as
    its columns: ``id`` as int64, every other numeric column as float64 (carom prints each double so that
    it parses back to the same bits, and so it does here), a column of text (a species name) as str.
    A file with a header only gives empty columns."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty, not a carom CSV file (no header line)")
    header, body = rows[0], rows[1:]
    table: Table = {}
    for c, name in enumerate(header):
        cells = [row[c] for row in body]
        if name == "id":
            table[name] = np.array(cells, dtype=np.int64)
            continue
        try:
            table[name] = np.array([float(v) for v in cells], dtype=np.float64)
        except ValueError:
            table[name] = np.array(cells, dtype=str)
    return table


def read_summary(path: PathLike) -> Dict[str, Any]:
    """``--summary SUMMARY.json`` as a dict (carom's ``null`` for a number that is not finite as None)."""
    with open(path, encoding="utf-8") as f:
        return json.load(f)


@dataclass(frozen=True)
class XyzFrame:
    """One frame of carom's extended XYZ trajectory: the sample's ``time``, the ``box`` (width, height),
    ``periodic``, and per disc in id order its species name ``type``, ``id``, ``position`` and
    ``velocity`` (N x 2: the doubles carom printed, to the bit) and ``radius``; any further per-disc
    column the frame's ``Properties`` name is in ``columns`` by its name."""

    time: float
    box: Tuple[float, float]
    periodic: bool
    type: np.ndarray
    id: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    radius: np.ndarray
    columns: Dict[str, np.ndarray]


def read_xyz(path: PathLike) -> List[XyzFrame]:
    """Every frame of ``--trajectory FRAMES.xyz`` (docs/commands.md: the count, a comment line with
    ``Lattice``, ``Properties``, ``Time`` and ``pbc``, then one line a disc)."""
    return list(iter_xyz(path))


def iter_xyz(path: PathLike) -> Iterator[XyzFrame]:
    """The frames of an extended XYZ trajectory one at a time, for files larger than memory."""
    with open(path, encoding="utf-8") as f:
        while True:
            count = f.readline()
            if not count.strip():
                return
            n = int(count)
            comment = _comment_fields(f.readline())
            lattice = [float(v) for v in comment["Lattice"].split()]
            properties = _properties(comment["Properties"])
            width = sum(c for _, _, c in properties)
            rows = [f.readline().split() for _ in range(n)]
            if any(len(r) != width for r in rows):
                raise ValueError(f"{path}: a frame with a line cut short (a killed run's file?)")
            cells = np.array(rows, dtype=str).reshape(n, width)
            columns: Dict[str, np.ndarray] = {}
            at = 0
            for name, kind, c in properties:
                block = cells[:, at:at + c]
                at += c
                typed = block.astype(np.float64) if kind == "R" else block.astype(np.int64) if kind == "I" else block
                columns[name] = typed[:, 0] if c == 1 else typed
            yield XyzFrame(time=float(comment["Time"]), box=(lattice[0], lattice[4]),
                           periodic=comment["pbc"].split()[0] == "T", type=columns.pop("type"),
                           id=columns.pop("id"), position=columns.pop("pos")[:, 0:2],
                           velocity=columns.pop("velo")[:, 0:2], radius=columns.pop("radius"), columns=columns)


def _properties(spec: str) -> List[Tuple[str, str, int]]:
    """``name:type:count`` triples of an extended XYZ ``Properties`` field (type S, I, R or L)."""
    parts = spec.split(":")
    return [(parts[k], parts[k + 1], int(parts[k + 2])) for k in range(0, len(parts), 3)]


def _comment_fields(line: str) -> Dict[str, str]:
    """KEY=VALUE and KEY="VALUE WITH SPACES" fields of an extended XYZ comment line."""
    fields: Dict[str, str] = {}
    for part in _split_quoted(line.strip()):
        key, _, value = part.partition("=")
        fields[key] = value.strip('"')
    return fields


def _split_quoted(text: str) -> List[str]:
    parts: List[str] = []
    current: List[str] = []
    quoted = False
    for ch in text:
        if ch == '"':
            quoted = not quoted
        if ch == " " and not quoted:
            if current:
                parts.append("".join(current))
            current = []
        else:
            current.append(ch)
    if current:
        parts.append("".join(current))
    return parts


def open_gsd(path: PathLike) -> Any:
    """``--trajectory FRAMES.gsd`` opened with gsd's own reader (``gsd.hoomd.open(path, "r")``, needs
    the ``gsd`` package): index it or iterate it for frames with ``configuration``, ``particles`` and
    ``log`` (``frame.log["carom/time"]``, ``["carom/Z"]``, ``["carom/collisions"]``). Close it, or use it
    in a ``with`` block."""
    import gsd.hoomd  # the gsd package: pip install gsd

    return gsd.hoomd.open(str(path), "r")


def read_gsd_log(path: PathLike) -> Table:
    """The per-frame values carom logs in a GSD trajectory, as arrays over the frames: ``step``, ``time``,
    ``Z`` (the interval since the previous frame; NaN in frame 0) and ``collisions`` (engines that tell
    them), read with ``gsd.hoomd.read_log``."""
    import gsd.hoomd

    log = gsd.hoomd.read_log(str(path), scalar_only=True)
    table: Table = {"step": np.asarray(log["configuration/step"])}
    for key, value in log.items():
        if key.startswith("log/carom/"):
            table[key[len("log/carom/"):]] = np.asarray(value)
    return table


def freud_box(source: Union[Any, Sequence[float]]) -> Any:
    """freud's 2D ``Box`` of a GSD frame (its ``configuration.box``), a :class:`carom.Scene`, an
    :class:`XyzFrame` or a (width, height) pair. freud's box is centred on the origin, as GSD positions
    are; shift carom's CSV and XYZ positions by half the box first. Needs the ``freud-analysis`` package."""
    import freud

    configuration = getattr(source, "configuration", None)
    if configuration is not None:
        width, height = configuration.box[0], configuration.box[1]
    elif hasattr(source, "width") and hasattr(source, "height"):
        width, height = source.width, source.height
    elif isinstance(source, XyzFrame):
        width, height = source.box
    else:
        width, height = source[0], source[1]
    return freud.box.Box.from_box([float(width), float(height)], dimensions=2)
