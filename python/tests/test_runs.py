"""simulate, compress and resume through the package: every output read back as carom wrote it, carom's
errors as exceptions, the child process never left behind."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import carom


def test_simulate_reads_the_final_state_to_the_bit(gas: carom.Scene, tmp_path: Path) -> None:
    run = carom.simulate(gas, folder=tmp_path)
    final = run.final()
    assert set(final) >= {"id", "x", "y", "vx", "vy"}
    assert final["id"].dtype == np.int64 and list(final["id"]) == list(range(200))
    # Each double as Python parses carom's text: the same bits.
    rows = (tmp_path / "final.csv").read_text().splitlines()[1:]
    assert [float(r.split(",")[1]) for r in rows] == final["x"].tolist()
    assert np.all((final["x"] >= 0) & (final["x"] < gas.width))
    summary = run.summary()
    assert summary["particles"] == 200 and summary["collisions"]["pair"] > 0
    z, z_error = run.pressure()
    assert z > 1 and z_error is not None and z_error > 0


def test_the_gsd_trajectory_logs_z_as_the_pressure_observable(gas: carom.Scene, tmp_path: Path) -> None:
    run = carom.simulate(gas, folder=tmp_path, every=0.5, trajectory="gsd", observe=["pressure", "gr"])
    pressure = run.observable("pressure")
    assert pressure["t0"].tolist() == [0.0, 0.5, 1.0, 1.5] and pressure["t1"].tolist() == [0.5, 1.0, 1.5, 2.0]
    log = run.gsd_log()
    assert log["step"].tolist() == [0, 1, 2, 3, 4]
    assert log["time"].tolist() == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert np.isnan(log["Z"][0])
    np.testing.assert_allclose(log["Z"][1:], pressure["Z"], rtol=1e-12)
    assert log["collisions"][-1] == sum(run.summary()["collisions"].values())
    assert len(run.observable("gr")["g"]) > 0

    final = run.final()
    with run.gsd() as frames:
        assert len(frames) == 5
        last = frames[-1]
        assert last.configuration.dimensions == 2 and last.particles.N == 200
        assert list(last.particles.types) == ["disc"]
        # float32 of carom's doubles, the box centred on the origin.
        centred = (final["x"] - gas.width / 2).astype(np.float32)
        centred[centred >= np.float32(0.5 * np.float32(gas.width))] -= np.float32(gas.width)
        np.testing.assert_array_equal(last.particles.position[:, 0], centred)
        freud = pytest.importorskip("freud")
        box = carom.freud_box(last)
        assert isinstance(box, freud.box.Box) and box.is2D and box.Lx == pytest.approx(gas.width, rel=1e-6)


def test_the_xyz_trajectory_ends_on_the_final_state(gas: carom.Scene, tmp_path: Path) -> None:
    run = carom.simulate(gas, folder=tmp_path, every=1.0, trajectory="xyz")
    frames = run.xyz()
    assert [f.time for f in frames] == [0.0, 1.0, 2.0]
    last, final = frames[-1], run.final()
    assert last.box == (gas.width, gas.height) and last.periodic
    assert last.type.tolist() == ["disc"] * 200 and last.id.tolist() == list(range(200))
    assert last.position[:, 0].tolist() == final["x"].tolist()
    assert last.velocity[:, 1].tolist() == final["vy"].tolist()
    assert last.radius.tolist() == [0.5] * 200


def test_resume_continues_to_the_bits_of_an_unbroken_run(gas: carom.Scene, tmp_path: Path) -> None:
    first = carom.simulate(gas, folder=tmp_path / "first", until=1.0, checkpoint=True)
    resumed = carom.resume(first.checkpoint, folder=tmp_path / "resumed", until=2.0)
    unbroken = carom.simulate(gas, folder=tmp_path / "unbroken", until=2.0)
    for column in ("x", "y", "vx", "vy"):
        assert resumed.final()[column].tolist() == unbroken.final()[column].tolist()


def test_a_resumed_trajectory_starts_at_the_checkpoint(gas: carom.Scene, tmp_path: Path) -> None:
    first = carom.simulate(gas, folder=tmp_path / "first", until=1.0, every=0.5, trajectory="gsd",
                           observe=["pressure"], checkpoint=True)
    resumed = carom.resume(first.checkpoint, folder=tmp_path / "resumed", until=2.0, trajectory="gsd", report=True)
    assert first.gsd_log()["time"].tolist() == [0.0, 0.5, 1.0]
    log = resumed.gsd_log()
    assert log["time"].tolist() == [1.5, 2.0] and log["step"].tolist() == [3, 4]
    # The file's first frame ends no interval of its own; the next is the observable's last interval.
    pressure = resumed.observable("pressure")
    assert pressure["t1"].tolist() == [0.5, 1.0, 1.5, 2.0]
    assert np.isnan(log["Z"][0]) and log["Z"][1] == pytest.approx(pressure["Z"][-1], rel=1e-12)


def test_compress_writes_the_packing(disc: carom.Species, tmp_path: Path) -> None:
    scene = carom.Scene.at_packing_fraction(disc, 0.5, 64, layout="triangular", jitter=0.3, seed=2,
                                            effects={"growth": 0.05}, until=200)
    run = carom.compress(scene, to_pressure=50, every=1, folder=tmp_path)
    packing = run.packing()
    assert list(packing["id"]) == list(range(64)) and np.all(packing["radius"] > 0.5)
    compression = run.summary()["compression"]
    assert compression["stop"] == "pressure" and compression["Z"] > 50
    assert compression["packingFraction"] > 0.5


def test_bad_input_raises_carom_s_line_and_status(gas: carom.Scene, tmp_path: Path) -> None:
    heard = []
    with pytest.raises(carom.CaromError) as refused:
        carom.simulate(gas, folder=tmp_path, engine="nope", progress=heard.append)
    assert refused.value.status == 2
    assert "nope" in refused.value.message
    assert "error: " + refused.value.message in heard
    assert "simulate" in refused.value.command
    assert not (tmp_path / "final.csv").exists()

    with pytest.raises(carom.CaromError) as refused:
        carom.simulate(gas, folder=tmp_path, every=-1.0, trajectory="gsd")
    assert refused.value.status == 2 and refused.value.message.startswith("--every")


def test_the_command_is_found_as_documented(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    jar = tmp_path / "carom.jar"
    jar.write_bytes(b"")
    monkeypatch.setenv("JAVA_HOME", str(tmp_path / "jdk"))
    assert carom.find_command(jar) == [str(tmp_path / "jdk" / "bin" / "java"), "--enable-native-access=ALL-UNNAMED",
                                       "-jar", str(jar)]
    monkeypatch.setenv("CAROM", str(jar))
    assert carom.find_command()[-1] == str(jar)
    with pytest.raises(FileNotFoundError):
        carom.find_command(tmp_path / "missing")
