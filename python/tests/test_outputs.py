"""The readers on small files written here: what carom's formats may hold beyond today's columns."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import carom

XYZ = """2
Lattice="4.0 0.0 0.0 0.0 3.0 0.0 0.0 0.0 1.0" Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1:psi6:R:1 Time=0.0 pbc="T T F"
small 0 0.1 0.2 0.0 1.5 -2.5 0.0 0.25 0.75
large 1 3.9 2.8 0.0 0.0 0.1 0.0 0.5 0.125
2
Lattice="4.0 0.0 0.0 0.0 3.0 0.0 0.0 0.0 1.0" Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1:psi6:R:1 Time=0.5 pbc="T T F"
small 0 0.85 2.95 0.0 1.5 -2.5 0.0 0.25 0.5
large 1 3.9 2.85 0.0 0.0 0.1 0.0 0.5 0.25
"""


def test_xyz_frames_with_a_further_column(tmp_path: Path) -> None:
    path = tmp_path / "frames.xyz"
    path.write_text(XYZ)
    frames = carom.read_xyz(path)
    assert [f.time for f in frames] == [0.0, 0.5]
    first = frames[0]
    assert first.box == (4.0, 3.0) and first.periodic
    assert first.type.tolist() == ["small", "large"] and first.id.tolist() == [0, 1]
    np.testing.assert_array_equal(first.position, [[0.1, 0.2], [3.9, 2.8]])
    np.testing.assert_array_equal(first.velocity, [[1.5, -2.5], [0.0, 0.1]])
    assert first.radius.tolist() == [0.25, 0.5]
    assert list(first.columns) == ["psi6"] and frames[1].columns["psi6"].tolist() == [0.5, 0.25]


def test_a_frame_cut_short_is_an_error(tmp_path: Path) -> None:
    path = tmp_path / "cut.xyz"
    path.write_text(XYZ[: XYZ.rindex("0.5 0.25")])
    with pytest.raises(ValueError, match="cut short"):
        carom.read_xyz(path)


def test_csv_columns_by_type(tmp_path: Path) -> None:
    path = tmp_path / "packing.csv"
    path.write_text("id,x,y,radius,species\n0,1.5,2.0,0.5,small\n1,0.1,0.30000000000000004,0.7,large\n")
    table = carom.read_csv(path)
    assert table["id"].dtype == np.int64 and table["id"].tolist() == [0, 1]
    assert table["y"].tolist() == [2.0, 0.30000000000000004]
    assert table["species"].tolist() == ["small", "large"]
    header_only = tmp_path / "empty.csv"
    header_only.write_text("t0,t1,Z\n")
    assert {k: v.size for k, v in carom.read_csv(header_only).items()} == {"t0": 0, "t1": 0, "Z": 0}


def test_freud_box_of_a_scene_and_of_a_pair() -> None:
    freud = pytest.importorskip("freud")
    scene = carom.Scene(width=6.0, height=2.5, species=[carom.Species("disc", 0.5, 1.0)])
    for source in (scene, (6.0, 2.5)):
        box = carom.freud_box(source)
        assert isinstance(box, freud.box.Box) and box.is2D and (box.Lx, box.Ly) == (6.0, 2.5)


def test_the_readme_shows_the_guide_s_example() -> None:
    """python/README.md (what pip shows) and docs/python.md carry the same example, block for block."""
    root = Path(__file__).resolve().parents[2]

    def python_blocks(path: Path) -> list:
        text = path.read_text(encoding="utf-8")
        return [b.split("```", 1)[0] for b in text.split("```python\n")[1:]]

    assert python_blocks(root / "python" / "README.md")[0] == python_blocks(root / "docs" / "python.md")[0]
