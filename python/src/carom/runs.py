"""``carom simulate``, ``compress`` and ``resume`` from Python: each call is one carom process writing
into one folder, and a :class:`Run` that reads what it wrote."""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

from ._command import PathLike, Progress, run_carom
from .outputs import Table, XyzFrame, open_gsd, read_csv, read_gsd_log, read_summary, read_xyz
from .scene import Scene, scene_file


@dataclass(frozen=True)
class Run:
    """What one carom command wrote, in ``folder`` (fixed names, each present only if asked for):
    ``scene.json`` (a Scene given as values), ``final.csv``, ``summary.json``, ``packing.csv``
    (``compress``), ``frames.gsd`` or ``frames.xyz``, ``report/`` (observables) and ``run.ckpt``. The
    readers read the files when called; ``stdout`` and ``stderr`` are what carom printed."""

    folder: Path
    stdout: str

    def path(self, name: str) -> Path:
        """An output file's path in the run's folder (raises ``FileNotFoundError`` if it was not written)."""
        p = self.folder / name
        if not p.exists():
            raise FileNotFoundError(f"{p}: this run did not write {name}")
        return p

    def final(self) -> Table:
        """The final state, ``final.csv``: columns ``id``, ``x``, ``y``, ``vx``, ``vy`` (and any carom adds)."""
        return read_csv(self.path("final.csv"))

    def summary(self) -> Dict[str, Any]:
        """The run's summary, ``summary.json`` (keys as docs/commands.md lists them)."""
        return read_summary(self.path("summary.json"))

    def pressure(self) -> Tuple[float, Optional[float]]:
        """The run's reduced pressure Z = PA/(NkT) and its error bar (None with too few blocks)."""
        p = self.summary()["pressure"]
        return p["Z"], p["Zerror"]

    def packing(self) -> Table:
        """``compress``'s packing, ``packing.csv``: ``id``, ``x``, ``y``, ``radius``."""
        return read_csv(self.path("packing.csv"))

    def observable(self, key: str) -> Table:
        """An observable's table, ``report/KEY.csv`` (``pressure``: ``t0``, ``t1``, ``Z``; ``gr``: ``r``, ``g``; ...)."""
        return read_csv(self.path(f"report/{key}.csv"))

    def gsd(self) -> Any:
        """The GSD trajectory opened with ``gsd.hoomd`` (:func:`carom.open_gsd`)."""
        return open_gsd(self.path("frames.gsd"))

    def gsd_log(self) -> Table:
        """The GSD trajectory's per-frame ``step``, ``time``, ``Z`` and ``collisions`` (:func:`carom.read_gsd_log`)."""
        return read_gsd_log(self.path("frames.gsd"))

    def xyz(self) -> List[XyzFrame]:
        """Every frame of the extended XYZ trajectory (:func:`carom.read_xyz`)."""
        return read_xyz(self.path("frames.xyz"))

    @property
    def checkpoint(self) -> Path:
        """The checkpoint file, for :func:`resume`."""
        return self.path("run.ckpt")


def _folder(folder: Optional[PathLike]) -> Path:
    if folder is None:
        return Path(tempfile.mkdtemp(prefix="carom-run-"))
    path = Path(folder)
    path.mkdir(parents=True, exist_ok=True)
    return path


def _sampling(folder: Path, every: Optional[float], trajectory: Optional[str], observe: Sequence[str]) -> List[PathLike]:
    args: List[PathLike] = []
    if every is not None:
        args += ["--every", repr(float(every))]
    if trajectory is not None:
        if trajectory not in ("gsd", "xyz"):
            raise ValueError(f"trajectory: 'gsd' or 'xyz', not {trajectory!r}")
        args += ["--trajectory", str(folder / f"frames.{trajectory}")]
    if observe:
        args += ["--observe", ",".join(observe), "--report", str(folder / "report")]
    return args


def _engine(engine: Optional[str], threads: Optional[int], options: Optional[Mapping[str, Any]]) -> List[PathLike]:
    args: List[PathLike] = []
    if engine is not None:
        args += ["--engine", engine]
    if threads is not None:
        args += ["--threads", str(threads)]
    for name, value in (options or {}).items():
        args += ["--option", f"{name}={value}"]
    return args


def simulate(scene: Union[Scene, PathLike], *, folder: Optional[PathLike] = None, until: Optional[float] = None,
             engine: Optional[str] = None, threads: Optional[int] = None,
             options: Optional[Mapping[str, Any]] = None, every: Optional[float] = None,
             trajectory: Optional[str] = None, observe: Sequence[str] = (), checkpoint: bool = False,
             checkpoint_every: Optional[float] = None, allow_long: bool = False,
             arguments: Sequence[str] = (), carom: Optional[PathLike] = None,
             progress: Progress = False) -> Run:
    """``carom simulate`` of ``scene`` (a :class:`Scene` or a scene file's path) into ``folder`` (a new
    temporary folder if None, left for you to read and remove): always ``final.csv`` and
    ``summary.json``; with ``every``, ``trajectory`` (``"gsd"`` or ``"xyz"``) writes ``frames.gsd`` or
    ``frames.xyz`` and ``observe`` (keys such as ``"gr"``, ``"msd"``, ``"psi6"``, ``"pressure"``) the
    ``report/`` folder; ``checkpoint`` writes ``run.ckpt`` for :func:`resume`. ``engine``, ``threads``,
    ``options`` (tunables), ``until`` and ``allow_long`` are the command line's options; ``arguments``
    are added as they are. carom checks everything before it runs: bad input raises
    :class:`carom.CaromError` with its ``error:`` line. ``progress``: see :func:`carom.run_carom`."""
    out = _folder(folder)
    args: List[PathLike] = ["simulate", scene_file(scene, out)]
    if until is not None:
        args += ["--until", repr(float(until))]
    args += _engine(engine, threads, options)
    args += ["--out", out / "final.csv", "--summary", out / "summary.json"]
    args += _sampling(out, every, trajectory, observe)
    if checkpoint:
        args += ["--checkpoint", out / "run.ckpt"]
        if checkpoint_every is not None:
            args += ["--checkpoint-every", repr(float(checkpoint_every))]
    if allow_long:
        args.append("--allow-long")
    args += list(arguments)
    return Run(out, run_carom(args, carom=carom, progress=progress))


def compress(scene: Union[Scene, PathLike], to_pressure: float, *, folder: Optional[PathLike] = None,
             every: Optional[float] = None, arguments: Sequence[str] = (), carom: Optional[PathLike] = None,
             progress: Progress = False) -> Run:
    """``carom compress``: grows the discs of ``scene`` (which names ``effects={"growth": G}``) until the
    reduced pressure exceeds ``to_pressure`` or the scene's end time; writes ``packing.csv`` and
    ``summary.json`` (its ``compression`` part says where and why it stopped) into ``folder``."""
    out = _folder(folder)
    args: List[PathLike] = ["compress", scene_file(scene, out), "--to-pressure", repr(float(to_pressure)),
                       "--out", out / "packing.csv", "--summary", out / "summary.json"]
    if every is not None:
        args += ["--every", repr(float(every))]
    args += list(arguments)
    return Run(out, run_carom(args, carom=carom, progress=progress))


def resume(checkpoint: PathLike, *, folder: Optional[PathLike] = None, until: Optional[float] = None,
           trajectory: Optional[str] = None, report: bool = False, save: bool = False,
           allow_long: bool = False, arguments: Sequence[str] = (), carom: Optional[PathLike] = None,
           progress: Progress = False) -> Run:
    """``carom resume`` of a checkpoint (``Run.checkpoint``) to its end time or ``until``, into ``folder``:
    ``final.csv`` and ``summary.json``, the bits of a run that never stopped; ``trajectory`` (the
    checkpoint's run sampled) writes the frames from the checkpoint on, ``report`` (it observed) the
    observables over the whole run, ``save`` a new ``run.ckpt`` in ``folder``."""
    out = _folder(folder)
    args: List[PathLike] = ["resume", Path(checkpoint)]
    if until is not None:
        args += ["--until", repr(float(until))]
    args += ["--out", out / "final.csv", "--summary", out / "summary.json"]
    if trajectory is not None:
        args += _sampling(out, None, trajectory, ())
    if report:
        args += ["--report", out / "report"]
    if save:
        args += ["--checkpoint", out / "run.ckpt"]
    if allow_long:
        args.append("--allow-long")
    args += list(arguments)
    return Run(out, run_carom(args, carom=carom, progress=progress))
