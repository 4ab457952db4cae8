#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""RRHT normals in an Open3D pipeline, on the bundled fandisk CAD part.

    python3 examples/python/open3d_pipeline.py [--output FOLDER]

1. reads examples/data/fandisk_20k.ply with Open3D (20k points, and the exact
   normal of the face each lies on, kept as the truth);
2. estimates the normals with cgal_rrht, and, for comparison, with Open3D's
   own estimate_normals (30 nearest neighbors, its usual setting);
3. orients RRHT's normals consistently with cgal_rrht.open3d.orient_normals
   (in place of Open3D's orient_normals_consistent_tangent_plane, whose
   propagation flips faces across the sharp edges that RRHT keeps);
4. reconstructs a surface with Open3D's Poisson reconstruction and writes it
   to FOLDER/fandisk_poisson.ply;
5. writes FOLDER/fandisk_normal_errors.png: the angle error of each point,
   RRHT beside Open3D.
"""

import argparse
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt
import numpy as np
import open3d as o3d

import cgal_rrht.open3d

DATA = Path(__file__).resolve().parents[1] / "data" / "fandisk_20k.ply"


def angle_errors_deg(normals, truth):
    """Unoriented angle between each normal and its truth, in degrees."""
    cosines = np.abs(np.sum(normals * truth, axis=1)) / np.linalg.norm(normals, axis=1) / np.linalg.norm(truth, axis=1)
    return np.degrees(np.arccos(np.clip(cosines, 0.0, 1.0)))


def plot_errors(points, errors, path):
    """The points seen from one side, colored by their angle error, one panel per estimator."""
    figure = plt.figure(figsize=(13, 6))
    for i, (name, error) in enumerate(errors.items()):
        axes = figure.add_subplot(1, len(errors), i + 1, projection="3d")
        shown = axes.scatter(*points.T, c=np.minimum(error, 30), cmap="inferno_r", vmin=0, vmax=30, s=1.5,
                             linewidths=0)
        axes.view_init(elev=25, azim=-60)
        axes.set_box_aspect(np.ptp(points, axis=0), zoom=1.4)
        axes.set_axis_off()
        axes.set_title(f"{name}\n{np.mean(error > 10):.1%} above 10°, RMS {np.sqrt(np.mean(error**2)):.1f}°")
    figure.subplots_adjust(left=0, right=0.9, bottom=0, top=0.92, wspace=0)
    figure.colorbar(shown, ax=figure.axes, shrink=0.6, label="angle error (degrees, 30 and above in black)")
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", type=Path, default=Path("."), help="the folder of the mesh and the picture")
    output = parser.parse_args().output
    output.mkdir(parents=True, exist_ok=True)

    cloud = o3d.io.read_point_cloud(str(DATA))
    truth = np.asarray(cloud.normals).copy()
    points = np.asarray(cloud.points)
    print(f"read {len(points)} points with their exact normals from {DATA.name}")

    start = time.perf_counter()
    cgal_rrht.open3d.estimate_normals(cloud, k=50)
    print(f"cgal_rrht normals (k = 50): {time.perf_counter() - start:.2f} s")
    rrht_errors = angle_errors_deg(np.asarray(cloud.normals), truth)

    peer = o3d.geometry.PointCloud(cloud.points)
    start = time.perf_counter()
    peer.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(30))
    print(f"Open3D normals (KNN 30): {time.perf_counter() - start:.2f} s")
    open3d_errors = angle_errors_deg(np.asarray(peer.normals), truth)

    picture = output / "fandisk_normal_errors.png"
    plot_errors(points, {"cgal_rrht (RRHT)": rrht_errors, "Open3D estimate_normals": open3d_errors}, picture)
    for name, errors in (("cgal_rrht", rrht_errors), ("Open3D", open3d_errors)):
        print(f"{name}: {np.mean(errors > 10):.1%} of the points above 10 degrees, "
              f"RMS {np.sqrt(np.mean(errors**2)):.1f} degrees")
    print(f"wrote {picture}")

    cgal_rrht.open3d.orient_normals(cloud)
    mesh, _ = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(cloud, depth=8)
    path = output / "fandisk_poisson.ply"
    if not o3d.io.write_triangle_mesh(str(path), mesh):
        raise SystemExit(f"cannot write {path}")
    print(f"wrote {path}: Poisson surface of the oriented RRHT normals, "
          f"{len(mesh.vertices)} vertices, {len(mesh.triangles)} triangles")


if __name__ == "__main__":
    main()
