"""carom from Python: build scenes, run the carom command, read its outputs into numpy.

A thin layer over the ``carom`` command line (docs/commands.md): every physical result comes from
carom itself, run as a subprocess; bad input raises :class:`CaromError` carrying carom's one-line
``error:`` message and exit status. docs/python.md is the guide.
"""

from ._command import CaromError, find_command, run_carom
from .outputs import (Table, XyzFrame, freud_box, iter_xyz, open_gsd, read_csv, read_gsd_log, read_summary,
                      read_xyz)
from .runs import Run, compress, resume, simulate
from .scene import Block, Disc, Scene, Species, maxwell, uniform
from .sweep import Sweep, sweep

__all__ = [
    "Block", "CaromError", "Disc", "Run", "Scene", "Species", "Sweep", "Table", "XyzFrame", "compress",
    "find_command", "freud_box", "iter_xyz", "maxwell", "open_gsd", "read_csv", "read_gsd_log",
    "read_summary", "read_xyz", "resume", "run_carom", "simulate", "sweep", "uniform",
]
