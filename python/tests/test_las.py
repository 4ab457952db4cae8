# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""rrht_normals and cgal_rrht.tiles on LAS files: every record kept, the
normals added as extra bytes, the same normals as from the same points in
text and from the tiles of a survey, each point oriented towards the scanner
position in its extra bytes, and what cannot be read refused without touching
the output. The files are parsed and written here with ``struct`` and NumPy,
apart from the C++ reader and writer that the tools share."""

import struct
import subprocess
import sys

import numpy as np
import pytest

import cgal_rrht
from cgal_rrht import tiles
from conftest import ROOT, angle_errors_deg

# Dask's event loop on Debian 12's tornado.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

LAS = ROOT / "test" / "data" / "las"
FILES = ["simple.las", "extrabytes.las", "test1_4.las"]


class Parsed:
    """The header fields, point records and extra-bytes descriptors of a LAS file."""

    def __init__(self, data: bytes):
        self.minor = data[25]
        self.header_size, self.offset_to_points, self.vlrs = struct.unpack_from("<HII", data, 94)
        self.format = data[104]
        (self.record_length,) = struct.unpack_from("<H", data, 105)
        (self.size,) = struct.unpack_from("<I", data, 107)
        if self.minor >= 4:
            (self.size,) = struct.unpack_from("<Q", data, 247)
        self.scale = np.array(struct.unpack_from("<3d", data, 131))
        self.offset = np.array(struct.unpack_from("<3d", data, 155))
        begin = self.offset_to_points
        self.records = np.frombuffer(data, np.uint8, self.size * self.record_length, begin).reshape(
            self.size, self.record_length)
        self.descriptors = []  # (name, data type)
        at = self.header_size
        for _ in range(self.vlrs):
            user = data[at + 2 : at + 18].rstrip(b"\0")
            record_id, length = struct.unpack_from("<HH", data, at + 18)
            if user == b"LASF_Spec" and record_id == 4:
                for d in range(at + 54, at + 54 + length, 192):
                    self.descriptors.append((data[d + 4 : d + 36].rstrip(b"\0").decode(), data[d + 2]))
            at += 54 + length

    def xyz(self):
        """X * scale + offset: a product, then a sum, each rounded."""
        integers = np.ascontiguousarray(self.records[:, :12]).view("<i4").reshape(self.size, 3)
        return integers * self.scale + self.offset

    def doubles(self, offset, count):
        """`count` doubles from `offset` in each record."""
        return np.ascontiguousarray(self.records[:, offset : offset + 8 * count]).view("<f8").reshape(self.size, count)

    def normals(self, before):
        """The normals that our tools added after the records of ``before``."""
        return self.doubles(before.record_length, 3)


def cut(data: bytes, rows) -> bytes:
    """The LAS file ``data`` with only its records ``rows``, in this order: its
    header and records before the points kept, the counts and bounds set."""
    parsed = Parsed(data)
    head = bytearray(data[: parsed.offset_to_points])
    xyz = parsed.xyz()[rows]
    struct.pack_into("<I", head, 107, len(rows) if parsed.minor < 4 or parsed.format < 6 else 0)
    if parsed.minor >= 4:
        struct.pack_into("<Q", head, 247, len(rows))
    struct.pack_into("<6d", head, 179, *[f(xyz[:, axis]) for axis in range(3) for f in (np.max, np.min)])
    return bytes(head) + parsed.records[rows].tobytes()


def las_with_fields(xyz, fields, scale=0.001):
    """A LAS 1.2 file of point format 0 holding the points ``xyz`` (stored as
    integers at ``scale``) and the extra bytes ``fields``, a list of (name,
    data type (Table 25: 6 int32, 9 float, 10 double), scale or None,
    offset or None, the numbers stored)."""
    types = {6: "<i4", 9: "<f4", 10: "<f8"}
    n = len(xyz)
    length = 20 + sum(np.dtype(types[t]).itemsize for _, t, *_ in fields)
    records = np.zeros((n, length), np.uint8)
    records[:, :12] = np.ascontiguousarray(np.round(xyz / scale).astype("<i4")).view(np.uint8).reshape(n, 12)
    records[:, 14] = 0b001001  # the first of one return
    at = 20
    descriptors = b""
    for name, data_type, value_scale, value_offset, values in fields:
        size = np.dtype(types[data_type]).itemsize
        records[:, at : at + size] = np.asarray(values, types[data_type]).view(np.uint8).reshape(n, size)
        descriptor = bytearray(192)
        descriptor[2] = data_type
        descriptor[3] = (8 if value_scale is not None else 0) | (16 if value_offset is not None else 0)
        descriptor[4 : 4 + len(name)] = name.encode()
        struct.pack_into("<d", descriptor, 112, value_scale or 0.0)
        struct.pack_into("<d", descriptor, 136, value_offset or 0.0)
        descriptors += bytes(descriptor)
        at += size
    vlr = bytearray(54)
    vlr[2:11] = b"LASF_Spec"
    struct.pack_into("<HH", vlr, 18, 4, len(descriptors))
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24:26] = bytes([1, 2])
    struct.pack_into("<HIIBHI", header, 94, 227, 227 + 54 + len(descriptors), 1, 0, length, n)
    struct.pack_into("<I", header, 111, n)
    struct.pack_into("<3d", header, 131, scale, scale, scale)
    stored = np.round(xyz / scale) * scale
    struct.pack_into("<6d", header, 179, *[f(stored[:, axis]) for axis in range(3) for f in (np.max, np.min)])
    return bytes(header) + bytes(vlr) + descriptors + records.tobytes()


def run(cli, *arguments):
    return subprocess.run([cli, *map(str, arguments), "-q"], capture_output=True, text=True)


@pytest.mark.parametrize("name", FILES)
def test_every_record_kept_and_the_normals_added(cli, tmp_path, name):
    source = LAS / name
    output = tmp_path / "normals.las"
    assert run(cli, source, output, "--confidence").returncode == 0
    before, after = Parsed(source.read_bytes()), Parsed(output.read_bytes())
    assert (after.minor, after.format, after.size) == (4, before.format, before.size)
    assert after.record_length == before.record_length + 32
    assert np.array_equal(after.records[:, : before.record_length], before.records)
    assert after.descriptors[len(before.descriptors):] == [
        ("NormalX", 10), ("NormalY", 10), ("NormalZ", 10), ("NormalConfidence", 10)]
    normals = after.doubles(before.record_length, 3)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-12)
    confidence = after.doubles(before.record_length + 24, 1)
    assert np.all((confidence >= 0) & (confidence <= 1))


@pytest.mark.parametrize("name", ["simple.las", "test1_4.las"])
def test_the_same_normals_as_the_points_in_text(cli, tmp_path, name):
    """The normals from a LAS file equal, bit for bit, those of its points
    (scale x integer + offset) written as text with 17 digits."""
    source = LAS / name
    parsed = Parsed(source.read_bytes())
    text = tmp_path / "points.xyz"
    np.savetxt(text, parsed.xyz(), fmt="%.17g")
    assert run(cli, source, tmp_path / "normals.las").returncode == 0
    assert run(cli, text, tmp_path / "normals.xyz", "--precision", "17").returncode == 0
    from_text = np.loadtxt(tmp_path / "normals.xyz")
    assert np.array_equal(from_text[:, :3], parsed.xyz())
    from_las = Parsed((tmp_path / "normals.las").read_bytes()).doubles(parsed.record_length, 3)
    assert np.array_equal(from_las, from_text[:, 3:])


def test_orient_up(cli, tmp_path):
    output = tmp_path / "up.las"
    assert run(cli, LAS / "simple.las", output, "--orient=up").returncode == 0
    before = Parsed((LAS / "simple.las").read_bytes())
    normals = Parsed(output.read_bytes()).doubles(before.record_length, 3)
    assert np.all(normals[:, 2] >= 0)


def test_laz_refused_with_the_commands_that_decompress_it(cli, tmp_path):
    result = run(cli, LAS / "simple.laz", tmp_path / "normals.las")
    assert result.returncode == 1
    assert "LAZ" in result.stderr and "pdal translate" in result.stderr and "laszip" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_truncated_las_file_leaves_the_earlier_output(cli, tmp_path):
    output = tmp_path / "normals.las"
    assert run(cli, LAS / "simple.las", output).returncode == 0
    good = output.read_bytes()
    truncated = tmp_path / "truncated.las"
    truncated.write_bytes((LAS / "simple.las").read_bytes()[:20000])
    result = run(cli, truncated, output)
    assert result.returncode == 1
    assert "truncated" in result.stderr
    assert output.read_bytes() == good
    assert sorted(p.name for p in tmp_path.iterdir()) == ["normals.las", "truncated.las"]


def test_a_las_output_needs_a_las_input(cli, tmp_path):
    text = tmp_path / "points.xyz"
    np.savetxt(text, Parsed((LAS / "simple.las").read_bytes()).xyz())
    result = run(cli, text, tmp_path / "normals.las")
    assert result.returncode == 2
    assert "needs a .las input" in result.stderr


# --------------------------------------------------------------------------
# cgal_rrht.tiles on LAS surveys.


def survey_tiles(folder, data: bytes, count: int):
    """The records of ``data`` sorted into ``count`` strips along x: writes
    ``survey.las`` (all of them, strip after strip) and the folder
    ``tiles`` of one LAS file per strip, whose rows in name order are
    those of the survey."""
    parsed = Parsed(data)
    strip = np.minimum((count * np.argsort(np.argsort(parsed.xyz()[:, 0], kind="stable"))) // parsed.size, count - 1)
    order = np.argsort(strip, kind="stable")
    (folder / "survey.las").write_bytes(cut(data, order))
    (folder / "tiles").mkdir()
    for i in range(count):
        (folder / "tiles" / f"tile_{i}.las").write_bytes(cut(data, order[strip[order] == i]))
    return folder / "survey.las", folder / "tiles"


def test_tiles_of_a_survey_give_the_normals_of_rrht_normals(cli, cluster, tmp_path):
    """A folder of LAS tiles is one survey: each tile's file keeps its records
    and gets, bit for bit, the normals (and confidences) that rrht_normals
    gives the whole survey, the halos reaching across the files."""
    survey, folder = survey_tiles(tmp_path, (LAS / "simple.las").read_bytes(), 4)
    assert run(cli, survey, tmp_path / "whole.las", "--confidence", "--orient=up").returncode == 0
    whole = Parsed((tmp_path / "whole.las").read_bytes())
    summary = tiles.run(folder, tmp_path / "out", scheduler=cluster.scheduler_address, progress=False,
                        return_confidence=True, orient="up")
    assert summary["tiles"] == 4 and summary["points"] == whole.size and summary["halo"] > 0
    first = 0
    for i in range(4):
        tile = Parsed((folder / f"tile_{i}.las").read_bytes())
        out = Parsed((tmp_path / "out" / f"tile_{i}.las").read_bytes())
        assert np.array_equal(out.records, whole.records[first : first + tile.size])
        assert np.array_equal(out.records[:, : tile.record_length], tile.records)
        first += tile.size
    assert first == whole.size


def test_one_las_file_in_tiles_is_the_file_of_rrht_normals(cli, cli_env, tmp_path):
    """One LAS file cut into tiles on the way gives, byte for byte, the LAS
    file that rrht_normals writes."""
    assert run(cli, LAS / "test1_4.las", tmp_path / "cli.las", "--confidence", "--orient=0,1,1").returncode == 0
    done = subprocess.run([sys.executable, "-m", "cgal_rrht.tiles", str(LAS / "test1_4.las"),
                           str(tmp_path / "tiles.las"), "--confidence", "--orient=0,1,1", "--tile-size", "300",
                           "--workers", "2", "-q"], capture_output=True, text=True, env=cli_env)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "tiles.las").read_bytes() == (tmp_path / "cli.las").read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cli.las", "tiles.las"]


def terrestrial_scan(n=6000, seed=5):
    """Points of a ground, a wall at y = 5 and a pillar, each seen from the
    nearer of two scanners at (0, 0, 1.5) and (10, 0, 1.5), with their exact
    normals towards it; the scanner of each point as three fields: x a float,
    y an integer in centimetres minus 10 (read without its scale or offset,
    it would flip the wall's normals), z a double."""
    rng = np.random.default_rng(seed)
    points = np.column_stack([rng.uniform(-5, 15, n), rng.uniform(-5, 5, n), np.zeros(n)])
    truth = np.tile([0.0, 0.0, 1.0], (n, 1))
    wall = rng.random(n) < 0.3
    points[wall, 1], points[wall, 2] = 5.0, rng.uniform(0, 3, wall.sum())
    truth[wall] = [0.0, -1.0, 0.0]
    pillar = ~wall & (rng.random(n) < 0.2)  # the side x = 5 of a pillar, seen from the first scanner
    points[pillar] = np.column_stack([np.full(pillar.sum(), 5.0), rng.uniform(-1, 1, pillar.sum()),
                                      rng.uniform(0, 3, pillar.sum())])
    truth[pillar] = [-1.0, 0.0, 0.0]
    scanners = np.array([[0.0, 0.0, 1.5], [10.0, 0.0, 1.5]])
    seen_by = np.where(pillar, 0, np.argmin(np.abs(points[:, :1] - scanners[:, 0]), axis=1))
    fields = [("ScannerX", 9, None, None, scanners[seen_by, 0]),
              ("ScannerY", 6, 0.01, -10.0, np.round((scanners[seen_by, 1] + 10.0) / 0.01)),
              ("ScannerZ", 10, None, None, scanners[seen_by, 2])]
    return las_with_fields(points, fields), truth, scanners[seen_by]


def test_each_point_oriented_towards_its_scanner(cli, cluster, tmp_path):
    """--orient=viewpoint:NAME,NAME,NAME reads each point's scanner position
    from extra bytes of any type, scaled and offset: the normals face the
    scanners as the exact ones do, are those of estimate_normals() towards the
    same positions, and the tiles of the scan give them too."""
    data, truth, scanners = terrestrial_scan()
    (tmp_path / "scan.las").write_bytes(data)
    fields = ("ScannerX", "ScannerY", "ScannerZ")
    assert run(cli, tmp_path / "scan.las", tmp_path / "cli.las", f"--orient=viewpoint:{','.join(fields)}",
               "-k", "30").returncode == 0
    scan = Parsed(data)
    normals = Parsed((tmp_path / "cli.las").read_bytes()).normals(scan)
    errors = angle_errors_deg(normals, truth)  # as lines
    flipped = np.mean(np.sum(normals * truth, axis=1) < 0)  # against the side each scanner saw
    assert np.median(errors) < 3 and flipped < 0.005, (np.median(errors), flipped)
    expected = cgal_rrht.estimate_normals(scan.xyz(), k=30, viewpoint=scanners)
    assert np.array_equal(normals, expected)
    # The scan as one file, cut into tiles on the way and oriented once merged.
    tiles.run(tmp_path / "scan.las", tmp_path / "tiled.las", scheduler=cluster.scheduler_address, progress=False,
              tile_size=5.0, k=30, viewpoint=fields)
    assert (tmp_path / "tiled.las").read_bytes() == (tmp_path / "cli.las").read_bytes()

    survey, folder = survey_tiles(tmp_path, data, 3)
    assert run(cli, survey, tmp_path / "survey_normals.las", f"--orient=viewpoint:{','.join(fields)}",
               "-k", "30").returncode == 0
    whole = Parsed((tmp_path / "survey_normals.las").read_bytes())
    tiles.run(folder, tmp_path / "out", scheduler=cluster.scheduler_address, progress=False, k=30, viewpoint=fields)
    tiled = np.concatenate([Parsed((tmp_path / "out" / f"tile_{i}.las").read_bytes()).records for i in range(3)])
    assert np.array_equal(tiled, whole.records)

    result = run(cli, tmp_path / "scan.las", tmp_path / "bad.las", "--orient=viewpoint:ScannerX,ScannerY,Nope")
    assert result.returncode == 1 and "no field of one number named 'Nope'" in result.stderr
    with pytest.raises(tiles.TileError, match=r"tile_\d\.las: its extra bytes have no field of one number named 'Nope'"):
        tiles.run(folder, tmp_path / "bad", scheduler=cluster.scheduler_address, progress=False,
                  viewpoint=("ScannerX", "ScannerY", "Nope"))
    assert not (tmp_path / "bad.las").exists() and not (tmp_path / "bad").exists()


@pytest.mark.parametrize("damage", ["laz", "truncated"])
def test_tiles_refuse_what_cannot_be_read(cli_env, tmp_path, damage):
    """A LAZ tile, or a truncated LAS tile, stops the run before anything is
    written, with exit code 1 and what is wrong."""
    _, folder = survey_tiles(tmp_path, (LAS / "simple.las").read_bytes(), 2)
    if damage == "laz":
        (folder / "tile_2.laz").write_bytes((LAS / "simple.laz").read_bytes())
        words = ["tile_2.laz", "LAZ", "pdal translate", "laszip"]
    else:
        (folder / "tile_1.las").write_bytes((folder / "tile_1.las").read_bytes()[:5000])
        words = ["tile_1.las", "truncated"]
    done = subprocess.run([sys.executable, "-m", "cgal_rrht.tiles", str(folder), str(tmp_path / "out"),
                           "--workers", "1", "-q"], capture_output=True, text=True, env=cli_env)
    assert done.returncode == 1, done.stderr
    assert all(word in done.stderr for word in words), done.stderr
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())
