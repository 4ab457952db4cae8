# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""cgal_rrht.tiles: tiles with halos on a Dask LocalCluster give the normals of the
whole cloud in memory, bit for bit; bad tiles give clear errors and write nothing."""

import os
import signal
import subprocess
import sys
import threading
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

import distributed

import cgal_rrht
from cgal_rrht import tiles
from cgal_rrht.point_files import PointFile, write_points

# Dask's event loop on Debian 12's tornado.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

# The fast setting, so that the 500k points take seconds.
OPTIONS = dict(k=30, planes=300, rotations=2)


def parts_side_by_side(n, seed=3):
    """`n` noisy points on boxes of several heights side by side on a ground, over [0, 8] x [0, 8]:
    sharp edges and corners on many tile borders."""
    rng = np.random.default_rng(seed)
    points = rng.random((n, 3)) * [8, 8, 0]
    on_box = rng.random(n) < 0.5
    cell = np.floor(points[on_box, :2]).astype(int)
    height = 0.3 + 0.1 * ((cell[:, 0] * 7 + cell[:, 1] * 3) % 5)
    local = rng.random((on_box.sum(), 3))
    face = rng.integers(0, 5, on_box.sum())  # 4 sides and the top
    axis = np.where(face < 4, face // 2, 2)
    local[np.arange(len(local)), axis] = np.where(face < 4, face % 2, 1.0)
    points[on_box] = np.column_stack([cell + 0.2 + 0.6 * local[:, :2], local[:, 2] * height])
    return points + rng.normal(0.0, 0.002, points.shape)


@pytest.fixture(scope="module")
def tiled(tmp_path_factory):
    """500k points cut into 64 tiles of 1 x 1 (binary PLY), and their normals in memory."""
    folder = tmp_path_factory.mktemp("tiles")
    points = parts_side_by_side(500_000)
    np.save(folder / "cloud.npy", points)
    written = tiles.split(folder / "cloud.npy", folder / "tiles", tile_size=1.0)
    assert len(written) >= 16
    return folder, points, cgal_rrht.estimate_normals(points, **OPTIONS)


def read_normals(folder, count):
    """The normals of a folder written by run(), by id (the ids files of split())."""
    normals = np.full((count, 3), np.nan)
    for tile in tiles.list_tiles(folder.parent / "tiles"):
        ids = np.load(tile.with_name(tile.stem + ".ids.npy"))
        out = PointFile(folder / tile.name)
        assert out.names == ("x", "y", "z", "nx", "ny", "nz")
        normals[ids] = out.table()[:, 3:]
    return normals


def test_tiles_give_the_normals_of_the_whole_cloud(tiled, cluster):
    folder, points, expected = tiled
    summary = tiles.run(folder / "tiles", folder / "normals", scheduler=cluster.scheduler_address,
                        progress=False, **OPTIONS)
    assert summary["points"] == len(points) and summary["tiles"] >= 16
    assert summary["halo"] > 0 and summary["estimated"] >= summary["points"]
    normals = read_normals(folder / "normals", len(points))
    assert np.array_equal(normals, expected), f"{(normals != expected).any(axis=1).sum()} normals differ"


def test_a_too_small_halo_is_widened_not_trusted(tiled, cluster):
    folder, points, expected = tiled
    summary = tiles.run(folder / "tiles", folder / "narrow", scheduler=cluster.scheduler_address, halo=0.01,
                        progress=False, **OPTIONS)
    assert summary["rounds"] > 0
    assert np.array_equal(read_normals(folder / "narrow", len(points)), expected)


def test_refit_and_confidence_need_wider_halos_and_get_them(cluster, tmp_path):
    points = parts_side_by_side(60_000, seed=4)
    expected, confidence = cgal_rrht.estimate_normals(points, refit=True, return_confidence=True, **OPTIONS)
    np.save(tmp_path / "cloud.npy", points)
    tiles.run(tmp_path / "cloud.npy", tmp_path / "out.npy", scheduler=cluster.scheduler_address, tile_size=2.0,
              progress=False, refit=True, return_confidence=True, **OPTIONS)
    out = np.load(tmp_path / "out.npy")
    assert np.array_equal(out[:, :3], points)
    assert np.array_equal(out[:, 3:6], expected)
    assert np.array_equal(out[:, 6], confidence)


def test_tiles_written_by_rrht_normals(cluster, tmp_path):
    """The binary PLY of the command-line tool (here the bundled fandisk, x y z nx ny nz in doubles) is a tile."""
    data = Path(__file__).resolve().parents[2] / "examples" / "data" / "fandisk_20k.ply"
    (tmp_path / "tiles").mkdir()
    (tmp_path / "tiles" / "fandisk.ply").write_bytes(data.read_bytes())
    tiles.run(tmp_path / "tiles", tmp_path / "out", scheduler=cluster.scheduler_address, progress=False, k=30)
    points = PointFile(tmp_path / "tiles" / "fandisk.ply").read()
    out = PointFile(tmp_path / "out" / "fandisk.ply").table()
    assert np.array_equal(out[:, :3], points)
    assert np.array_equal(out[:, 3:], cgal_rrht.estimate_normals(points, k=30))


def test_every_file_that_rrht_normals_reads(cluster, tmp_path):
    """One input file in ASCII PLY, OFF or .xyz, and a folder with an ASCII PLY tile, give the normals of the
    points in memory, bit for bit, without a warning."""
    points = parts_side_by_side(20_000)
    lines = [" ".join(repr(v) for v in p) + "\n" for p in points]  # repr: the doubles, exactly

    def ascii_ply(rows, kind="double"):
        return ("ply\nformat ascii 1.0\ncomment CGAL's data files are ASCII\n"
                f"element vertex {len(rows)}\nproperty {kind} x\nproperty {kind} y\nproperty {kind} z\n"
                "element face 0\nproperty list uchar int vertex_indices\nend_header\n" + "".join(rows))

    # CGAL reads a PLY file's float properties as single-precision numbers, and so must the tiles.
    singles = points.astype(np.float32)
    inputs = {"cloud.ply": (ascii_ply(lines), points),
              "cloud.off": ("OFF\n# a comment\n20000 0 0\n" + "".join(lines), points),
              "cloud.xyz": ("".join(lines), points),
              "floats.ply": (ascii_ply([" ".join(f"{v:.9g}" for v in p) + "\n" for p in singles], "float"),
                             singles.astype(np.float64))}
    expected = cgal_rrht.estimate_normals(points, **OPTIONS)
    with warnings.catch_warnings():
        warnings.simplefilter("error", UserWarning)
        for name, (content, read) in inputs.items():
            (tmp_path / name).write_text(content)
            tiles.run(tmp_path / name, tmp_path / f"{name}.npy", scheduler=cluster.scheduler_address, progress=False,
                      tile_size=4.0, **OPTIONS)
            out = np.load(tmp_path / f"{name}.npy")
            assert np.array_equal(out[:, :3], read), name
            normals = expected if read is points else cgal_rrht.estimate_normals(read, **OPTIONS)
            assert np.array_equal(out[:, 3:6], normals), name
        (tmp_path / "tiles").mkdir()
        (tmp_path / "tiles" / "a.ply").write_text(ascii_ply(lines[:10_000]))
        np.save(tmp_path / "tiles" / "b.npy", points[10_000:])
        tiles.run(tmp_path / "tiles", tmp_path / "out", scheduler=cluster.scheduler_address, progress=False, **OPTIONS)
    out = np.concatenate([PointFile(tmp_path / "out" / "a.ply").table(), PointFile(tmp_path / "out" / "b.npy").table()])
    assert np.array_equal(out[:, :3], points)
    assert np.array_equal(out[:, 3:], expected)


def test_tiles_oriented_up_as_the_whole_cloud(tiled, cluster):
    """orient="up": each normal is oriented on its own, so the tiles give what the whole cloud gives."""
    folder, points, expected = tiled
    tiles.run(folder / "tiles", folder / "up", scheduler=cluster.scheduler_address, progress=False, orient="up",
              **OPTIONS)
    normals = read_normals(folder / "up", len(points))
    assert (normals[:, 2] >= 0).all()
    oriented = cgal_rrht.orient_normals(points, expected, direction="up")
    assert not np.array_equal(oriented, expected)
    assert np.array_equal(normals, oriented), f"{(normals != oriented).any(axis=1).sum()} normals differ"


def test_tiles_oriented_towards_a_direction_with_confidence(cluster, tmp_path):
    points = parts_side_by_side(60_000, seed=5)
    direction = (1.0, 0.5, -0.2)
    expected, confidence = cgal_rrht.estimate_normals(points, return_confidence=True, **OPTIONS)
    np.save(tmp_path / "cloud.npy", points)
    tiles.run(tmp_path / "cloud.npy", tmp_path / "out.npy", scheduler=cluster.scheduler_address, tile_size=2.0,
              progress=False, return_confidence=True, orient=direction, **OPTIONS)
    out = np.load(tmp_path / "out.npy")
    assert np.array_equal(out[:, 3:6], cgal_rrht.orient_normals(points, expected, direction=direction))
    assert np.array_equal(out[:, 6], confidence)


@pytest.mark.parametrize(
    "arguments, message",
    [
        (dict(orient="consistent"), "a consistent orientation cannot be made tile by tile: each tile sees only its part"),
        (dict(viewpoint=np.zeros((1000, 3))), r"viewpoint must be one point, 3 numbers, or, for each point's scanner "
                                              r"position, the names of 3 extra-bytes fields of LAS tiles, not of shape "
                                              r"\(1000, 3\)"),
        (dict(viewpoint="ScannerX,ScannerY,ScannerZ"), r"the names of 3 extra-bytes fields of LAS tiles, not "
                                                       r"'ScannerX,ScannerY,ScannerZ'"),
        (dict(viewpoint=("ScannerX", "ScannerY", "ScannerZ")), "viewpoint names fields of the extra bytes of a LAS "
                                                               "input; give a point for this input"),
        (dict(orient=(0, 0, 0)), "direction must be finite and not null"),
        (dict(viewpoint=(0, np.nan, 0)), "viewpoint must be finite"),
        (dict(orient="up", viewpoint=(0, 0, 1)), "give orient or viewpoint, not both"),
        (dict(orient="sideways"), "unknown orient 'sideways'"),
    ],
)
def test_orientations_refused_up_front(tmp_path, arguments, message):
    """Before any scheduler is reached (there is none at this address) and anything is written."""
    np.save(tmp_path / "cloud.npy", parts_side_by_side(1000))
    with pytest.raises(ValueError, match=message):
        tiles.run(tmp_path / "cloud.npy", tmp_path / "out.npy", scheduler="tcp://127.0.0.1:9", progress=False,
                  **arguments, **OPTIONS)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cloud.npy"]


def test_command_line_orientation(cli_env, tmp_path):
    points = parts_side_by_side(20_000, seed=6)
    np.save(tmp_path / "cloud.npy", points)
    command = [sys.executable, "-m", "cgal_rrht.tiles", str(tmp_path / "cloud.npy")]
    estimator = ["-k", "30", "--planes", "300", "--rotations", "2"]
    done = subprocess.run(command + [str(tmp_path / "out.npy"), "--workers", "2", "-q", "--tile-size", "2",
                                     *estimator, "--orient=viewpoint:4,4,3"],
                          capture_output=True, text=True, env=cli_env)
    assert done.returncode == 0, done.stderr
    expected = cgal_rrht.estimate_normals(points, k=30, planes=300, rotations=2, viewpoint=(4.0, 4.0, 3.0))
    assert np.array_equal(np.load(tmp_path / "out.npy")[:, 3:6], expected)
    for flag, message in [
        ("--orient", "error: a consistent orientation cannot be made tile by tile"),
        ("--orient=mst", "error: a consistent orientation cannot be made tile by tile"),
        ("--orient=0,0,0", "direction must be finite and not null"),
        ("--orient=sideways", "argument --orient: must be up, X,Y,Z, viewpoint:X,Y,Z or viewpoint:NAME,NAME,NAME, not 'sideways'"),
        ("--orient=viewpoint:1,2", "argument --orient: must be up, X,Y,Z, viewpoint:X,Y,Z or viewpoint:NAME,NAME,NAME, not 'viewpoint:1,2'"),
    ]:
        done = subprocess.run(command + [str(tmp_path / "bad.npy"), "-q", "--scheduler", "tcp://127.0.0.1:9", flag],
                              capture_output=True, text=True, env=cli_env)
        assert done.returncode == 2, (flag, done.stderr)
        assert message in done.stderr, (flag, done.stderr)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cloud.npy", "out.npy"]


def test_a_worker_killed_mid_run_changes_nothing(tiled, cluster):
    folder, points, expected = tiled
    output = folder / "killed"
    client = distributed.Client(cluster)
    pids = list(client.run(os.getpid).values())
    failure = []

    def estimate():
        try:
            tiles.run(folder / "tiles", output, scheduler=cluster.scheduler_address, progress=False, **OPTIONS)
        except Exception as error:  # reported below
            failure.append(error)

    runner = threading.Thread(target=estimate)
    runner.start()
    count = len(tiles.list_tiles(folder / "tiles"))
    while not (output.is_dir() and any(output.glob("*.ply"))) and runner.is_alive():
        time.sleep(0.01)
    done = len(list(output.glob("*.ply")))
    os.kill(pids[0], signal.SIGKILL)
    runner.join()
    client.close()
    assert not failure, failure
    assert done < count, "the run ended before the worker was killed"
    assert np.array_equal(read_normals(output, len(points)), expected)
    assert not list(output.glob(".*partial*"))


def test_bad_tiles_are_named_and_nothing_is_written(cluster, tmp_path):
    good = tmp_path / "good"
    good.mkdir()
    points = parts_side_by_side(20_000)
    write_points(good / "a.ply", [("x", points[:10_000, 0]), ("y", points[:10_000, 1]), ("z", points[:10_000, 2])])
    np.save(good / "b.npy", points[10_000:])
    output = tmp_path / "out"
    tiles.run(good, output, scheduler=cluster.scheduler_address, progress=False, **OPTIONS)
    before = {p.name: p.read_bytes() for p in output.iterdir()}
    assert sorted(before) == ["a.ply", "b.npy"]

    def fails(folder, message):
        with pytest.raises(tiles.TileError, match=message):
            tiles.run(folder, output, scheduler=cluster.scheduler_address, progress=False, **OPTIONS)
        assert {p.name: p.read_bytes() for p in output.iterdir()} == before

    for name, make, message in [
        ("empty", lambda f: np.save(f / "c.npy", np.empty((0, 3))), r"c\.npy: it holds no point"),
        ("truncated", lambda f: (f / "c.ply").write_bytes((good / "a.ply").read_bytes()[:-100]), r"c\.ply.*truncated"),
        ("not a ply", lambda f: (f / "c.ply").write_text("hello\n"), r"c\.ply: not a PLY file"),
        ("truncated ascii ply", lambda f: (f / "c.ply").write_text(
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n0 0 0\n"), r"c\.ply: truncated: 2 vertices announced, 1 stored"),
        ("missing", lambda f: (f / "c.ply").symlink_to(tmp_path / "nowhere.ply"), r"c\.ply: no such file"),
        ("wrong shape", lambda f: np.save(f / "c.npy", np.zeros((5, 2))), r"c\.npy: not an array of points"),
    ]:
        folder = tmp_path / name
        folder.mkdir()
        for tile in good.iterdir():
            (folder / tile.name).write_bytes(tile.read_bytes())
        make(folder)
        fails(folder, message)
    with pytest.raises(tiles.TileError, match="nowhere: no such file or folder"):
        tiles.run(tmp_path / "nowhere", output, scheduler=cluster.scheduler_address, progress=False)

    # One input file, malformed past its first chunk: the output file of an
    # earlier run stays as it was, and no temporary folder is left.
    single = tmp_path / "single"
    single.mkdir()
    np.save(single / "good.npy", points)
    tiles.run(single / "good.npy", single / "out.npy", scheduler=cluster.scheduler_address, progress=False, **OPTIONS)
    kept = (single / "out.npy").read_bytes()
    with open(single / "bad.xyz", "w") as stream:
        np.savetxt(stream, points)
        stream.write("1 2 three\n")
    with pytest.raises(tiles.PointFileError, match=r"bad\.xyz: malformed, in the 1048576 rows from row 0: .* row 20000"):
        tiles.run(single / "bad.xyz", single / "out.npy", scheduler=cluster.scheduler_address, progress=False,
                  **OPTIONS)
    assert (single / "out.npy").read_bytes() == kept
    assert sorted(p.name for p in single.iterdir()) == ["bad.xyz", "good.npy", "out.npy"]


def test_command_line(cli_env, tmp_path):
    points = parts_side_by_side(30_000)
    np.save(tmp_path / "cloud.npy", points)
    command = [sys.executable, "-m", "cgal_rrht.tiles"]
    done = subprocess.run(command + ["split", str(tmp_path / "cloud.npy"), str(tmp_path / "tiles"), "--tile-size", "2"],
                          capture_output=True, text=True, env=cli_env)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout.split()[0]) >= 16, done.stdout  # 16, and slivers that the noise puts past the borders
    done = subprocess.run(command + [str(tmp_path / "tiles"), str(tmp_path / "out"), "--workers", "2", "-q",
                                     "-k", "30", "--setting", "paper_fast", "--planes", "500", "--seed", "4"],
                          capture_output=True, text=True, env=cli_env)
    assert done.returncode == 0, done.stderr
    assert done.stderr == "" and done.stdout == ""  # -q: a successful run says nothing
    expected = cgal_rrht.estimate_normals(points, k=30, setting="paper_fast", planes=500, seed=4)
    assert np.array_equal(read_normals(tmp_path / "out", len(points)), expected)
    (tmp_path / "tiles" / "tile_0_0.ply").write_text("broken\n")
    done = subprocess.run(command + [str(tmp_path / "tiles"), str(tmp_path / "out2"), "--workers", "1", "-q"],
                          capture_output=True, text=True, env=cli_env)
    assert done.returncode == 1
    assert "tile_0_0.ply: not a PLY file" in done.stderr
    # The switches that --setting replaces still parse, with a warning.
    done = subprocess.run(command + [str(tmp_path / "none"), str(tmp_path / "out3"), "--least-squares-first"],
                          capture_output=True, text=True, env=cli_env)
    assert "warning: --least-squares-first is deprecated and will be removed: use --setting" in done.stderr
    assert not (tmp_path / "out2").exists() or not any((tmp_path / "out2").iterdir())
