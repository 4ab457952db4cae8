# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""examples/python/open3d_pipeline.py runs on the bundled data and writes a
mesh and a picture."""

import re
import subprocess
import sys

import open3d as o3d

from conftest import ROOT

EXAMPLE = ROOT / "examples" / "python" / "open3d_pipeline.py"


def test_open3d_pipeline(tmp_path):
    run = subprocess.run([sys.executable, str(EXAMPLE), "--output", str(tmp_path)], capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    shares = dict(re.findall(r"^(cgal_rrht|Open3D): ([\d.]+)% of the points above 10 degrees", run.stdout, re.M))
    assert float(shares["cgal_rrht"]) < 0.5 * float(shares["Open3D"]), run.stdout
    mesh = o3d.io.read_triangle_mesh(str(tmp_path / "fandisk_poisson.ply"))
    assert len(mesh.triangles) > 10000
    # The Poisson surface spans the part (about 0.93 x 0.52 x 1.0).
    assert abs(mesh.get_axis_aligned_bounding_box().get_extent()[2] - 1.0) < 0.1
    assert (tmp_path / "fandisk_normal_errors.png").stat().st_size > 50000
