# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""rrht_normals on LAS files: every record kept, the normals added as extra
bytes, the same normals as from the same points in text, and what cannot be
read refused without touching the output. The files are parsed here with
``struct`` and NumPy, apart from the C++ reader that the tool uses."""

import struct
import subprocess

import numpy as np
import pytest

from conftest import ROOT

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
