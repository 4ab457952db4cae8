# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The same normals, bit for bit, as the command-line tool rrht_normals (which
calls CGAL::rrht_estimate_normals() on the same points)."""

import subprocess

import numpy as np
import pytest

import cgal_rrht
from conftest import DATA, DEPRECATED

# (Python keyword arguments, the same for rrht_normals)
SETTINGS = [
    ({}, []),
    (dict(setting="paper_fast", sampling="cubes"), ["--setting", "paper_fast", "--sampling", "cubes"]),
    (dict(setting="paper_fast", sampling="unif", aggregation="mean"),
     ["--setting", "paper_fast", "--sampling", "unif", "--aggregation", "mean"]),
    (dict(setting="paper_fast", rotations=3), ["--setting", "paper_fast", "--rotations", "3"]),
    (dict(setting="paper_precise", planes=300, rotations=2), ["--setting", "paper_precise", "--planes", "300",
                                                              "--rotations", "2"]),
    (dict(radius=0.05, k=0, seed=7), ["--radius", "0.05", "-k", "0", "--seed", "7"]),
    (dict(setting="paper_precise", radius=0.05, k=30, aggregation="best", slices=12),
     ["--setting", "paper_precise", "--radius", "0.05", "-k", "30", "--aggregation", "best", "--slices", "12"]),
    (dict(k=18, confidence_interval=False, cluster_angle=30.0, threads=1),
     ["-k", "18", "--no-confidence-interval", "--cluster-angle", "30", "--threads", "1"]),
    (dict(refit=True), ["--refit"]),
    (dict(setting="paper_fast", refit=True, radius=0.05, k=30),
     ["--setting", "paper_fast", "--refit", "--radius", "0.05", "-k", "30"]),
    # The deprecated switches, whose combinations no setting gives.
    pytest.param(dict(setting="paper_precise", adaptive=True), ["--setting", "paper_precise", "--adaptive"],
                 marks=DEPRECATED),
    pytest.param(dict(setting="paper_precise", adaptive=True, k=50, rotations=3, sampling="unif"),
                 ["--setting", "paper_precise", "--adaptive", "-k", "50", "--rotations", "3", "--sampling", "unif"],
                 marks=DEPRECATED),
    pytest.param(dict(setting="paper_precise", least_squares_first=True),
                 ["--setting", "paper_precise", "--least-squares-first"], marks=DEPRECATED),
    pytest.param(dict(setting="paper_precise", refit=True, adaptive=True, radius=0.05, k=30),
                 ["--setting", "paper_precise", "--refit", "--adaptive", "--radius", "0.05", "-k", "30"],
                 marks=DEPRECATED),
]


@pytest.mark.parametrize("parameters, flags", SETTINGS)
def test_same_normals_as_the_cli(cli, tmp_path, parameters, flags):
    source = DATA / "fandisk_20k.xyz"
    output = tmp_path / "normals.xyz"
    subprocess.run([cli, str(source), str(output), "--precision", "17", "-q", *flags], check=True,
                   stdout=subprocess.DEVNULL)
    written = np.loadtxt(output)  # 17 digits: each double read back exactly
    points = np.loadtxt(source)
    assert np.array_equal(written[:, :3], points)
    assert np.array_equal(cgal_rrht.estimate_normals(points, **parameters), written[:, 3:])


def test_deprecated_switches_warn(cli, tmp_path):
    """--adaptive and --least-squares-first, which --setting replaces, say so on stderr and still work."""
    source = DATA / "fandisk_20k.xyz"
    run = subprocess.run([cli, str(source), str(tmp_path / "normals.xyz"), "-q", "--setting", "paper_fast",
                          "--adaptive", "--least-squares-first"], check=True, capture_output=True, text=True)
    for flag in ("--adaptive", "--least-squares-first"):
        assert f"warning: {flag} is deprecated and will be removed: use --setting" in run.stderr
    assert "deprecated" not in subprocess.run([cli, str(source), str(tmp_path / "normals.xyz"), "-q"], check=True,
                                              capture_output=True, text=True).stderr


@pytest.mark.parametrize("extension", [".xyz", ".ply"])
def test_same_confidence_as_the_cli(cli, tmp_path, extension):
    """``--confidence``: a 7th column in .xyz, a double property ``confidence`` in a binary PLY."""
    source = DATA / "fandisk_20k.xyz"
    output = tmp_path / ("normals" + extension)
    subprocess.run([cli, str(source), str(output), "--precision", "17", "-q", "--confidence"], check=True,
                   stdout=subprocess.DEVNULL)
    if extension == ".xyz":
        written = np.loadtxt(output)
    else:
        data = output.read_bytes()
        end = data.index(b"end_header\n") + len(b"end_header\n")
        header = data[:end].decode().splitlines()
        assert "format binary_little_endian 1.0" in header
        assert [line.split()[-1] for line in header if line.startswith("property")] == [
            "x", "y", "z", "nx", "ny", "nz", "confidence"]
        assert all(line.startswith("property double") for line in header if line.startswith("property"))
        written = np.frombuffer(data[end:], dtype="<f8").reshape(-1, 7)
    points = np.loadtxt(source)
    normals, confidence = cgal_rrht.estimate_normals(points, return_confidence=True)
    assert written.shape == (len(points), 7)
    assert np.array_equal(written[:, :3], points)
    assert np.array_equal(written[:, 3:6], normals)
    assert np.array_equal(written[:, 6], confidence)
