# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Malformed files, as a user's broken files would be: flipped bytes, truncations, NaN and
infinite values, damaged headers. Every reader of the package (rrht_normals, and the
point files of cgal_rrht.tiles) ends each with a clear error or a correct result, never
a crash, and a failed rrht_normals leaves the earlier output as it was."""

import subprocess
from pathlib import Path

import numpy as np

from cgal_rrht.point_files import PointFile, PointFileError, write_points
from conftest import DATA, ROOT

POINTS = 300  # small files: a few hundred cases in seconds


def sources(tmp_path):
    """The same points as every format both readers take: name -> bytes."""
    lines = (DATA / "fandisk_20k.xyz").read_text().splitlines()[:POINTS]
    text = "".join(line + "\n" for line in lines)
    points = np.loadtxt(lines)
    write_points(tmp_path / "binary.ply", [("x", points[:, 0]), ("y", points[:, 1]), ("z", points[:, 2])])
    header = (f"ply\nformat ascii 1.0\ncomment a comment\nelement vertex {POINTS}\nproperty float x\n"
              "property float y\nproperty float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n")
    # A real LAS file (LAS 1.2, format 3) cut to its first POINTS records.
    las = bytearray((ROOT / "test" / "data" / "las" / "simple.las").read_bytes()[: 227 + POINTS * 34])
    las[107:111] = POINTS.to_bytes(4, "little")
    return {
        "cloud.las": bytes(las),
        "cloud.xyz": text.encode(),
        "ascii.ply": (header + text).encode(),
        "binary.ply": (tmp_path / "binary.ply").read_bytes(),
        "cloud.off": f"OFF\n{POINTS} 0 0\n{text}".encode(),
    }


def mutate(data: bytes, rng: np.random.Generator) -> bytes:
    """One seeded damage of a file's bytes."""
    kind = rng.integers(0, 6)
    if kind == 0:  # flipped bytes, anywhere
        out = bytearray(data)
        for position in rng.integers(0, len(out), rng.integers(1, 6)):
            out[position] ^= 1 << int(rng.integers(0, 8))
        return bytes(out)
    if kind == 1:  # truncated
        return data[: rng.integers(0, len(data))]
    if kind == 2:  # a number replaced by nan, inf, -inf or garbage, in a text body
        words = data.split(b" ")
        position = rng.integers(0, len(words))
        words[position] = [b"nan", b"inf", b"-inf", b"1e999", b"x", b""][rng.integers(0, 6)]
        return b" ".join(words)
    lines = data.split(b"\n")
    head = min(len(lines), 12)  # the header lines, and the first rows
    position = int(rng.integers(0, head))
    if kind == 3:  # a header line deleted or repeated
        return b"\n".join(lines[:position] + lines[position + 1:] if rng.integers(0, 2) else
                          lines[:position] + [lines[position]] + lines[position:])
    if kind == 4:  # a header word damaged
        words = lines[position].split(b" ")
        word = int(rng.integers(0, len(words)))
        words[word] = words[word][:-1] if rng.integers(0, 2) else words[word] + b"1"
        lines[position] = b" ".join(words)
        return b"\n".join(lines)
    other = int(rng.integers(0, head))  # two header lines swapped
    lines[position], lines[other] = lines[other], lines[position]
    return b"\n".join(lines)


def cases(tmp_path, count, seed):
    rng = np.random.default_rng(seed)
    files = sources(tmp_path)
    names = sorted(files)
    for case in range(count):
        name = names[case % len(names)]
        path = tmp_path / f"case{case}_{name}"
        path.write_bytes(mutate(files[name], rng))
        yield path


def test_rrht_normals_never_crashes_on_malformed_files(cli, tmp_path):
    output = tmp_path / "normals.xyz"
    earlier = b"1 2 3 0 0 1\n"
    # The pipeline example reads a user's file through the same check of PLY headers.
    pipeline = Path(cli).with_name("rrht_pipeline_example")
    assert pipeline.is_file(), f"{pipeline} is built with rrht_normals"
    succeeded = failed = damaged_headers = 0
    for path in cases(tmp_path, 240, seed=5):
        output.write_bytes(earlier)
        done = subprocess.run([cli, str(path), str(output), "-k", "8", "--threads", "1", "-q"], capture_output=True)
        assert done.returncode in (0, 1), (path.name, done.returncode, done.stderr[-300:])
        if done.returncode == 1:
            failed += 1
            assert b"rrht_normals: " in done.stderr, (path.name, done.stderr[-300:])  # after CGAL's own message
            assert output.read_bytes() == earlier, path.name
            damage = done.stderr.partition(b"(malformed file: ")[2]
            if damage:  # the header check's refusal: the pipeline example refuses the file too
                damaged_headers += 1
                piped = subprocess.run([str(pipeline), str(path), str(tmp_path / "mesh.off")], capture_output=True)
                assert piped.returncode == 1 and damage.rstrip(b")\n") in piped.stderr, (path.name, piped.stderr)
                assert not (tmp_path / "mesh.off").exists(), path.name
            continue
        succeeded += 1
        rows = np.loadtxt(output, ndmin=2)
        assert rows.shape[1] == 6 and 0 < len(rows) <= POINTS + 1, path.name
        normals = rows[:, 3:]
        assert np.all(np.isfinite(normals)), path.name
        lengths = np.linalg.norm(normals, axis=1)
        assert np.all((np.abs(lengths - 1) < 1e-6) | (lengths == 0)), path.name
    # Both outcomes are reached: the damage is neither always fatal nor always harmless.
    assert succeeded > 20 and failed > 20 and damaged_headers > 5, (succeeded, failed, damaged_headers)


def test_tiles_point_files_never_crash_on_malformed_files(tmp_path):
    inputs = list(cases(tmp_path, 240, seed=6))
    rng = np.random.default_rng(7)
    for case in range(60):  # .npy files too: a damaged header or body
        array = rng.random((POINTS, 3))
        np.save(tmp_path / "good.npy", array)
        path = tmp_path / f"case_npy{case}.npy"
        path.write_bytes(mutate((tmp_path / "good.npy").read_bytes(), rng))
        inputs.append(path)
    read = refused = 0
    for path in inputs:
        try:
            points = PointFile(path)
            count = len(points)
            whole = points.read()
            chunks = [chunk for _, chunk in points.chunks(64)]
        except PointFileError as error:
            refused += 1
            assert path.name in str(error), (path.name, error)
            continue
        read += 1
        assert whole.shape == (count, 3) and whole.dtype == np.float64, path.name
        assert np.array_equal(np.concatenate(chunks) if chunks else np.empty((0, 3)), whole, equal_nan=True), path.name
    assert read > 20 and refused > 20, (read, refused)
