# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""cgal_rrht.open3d.estimate_normals() on an Open3D point cloud."""

import numpy as np
import pytest

import cgal_rrht
import cgal_rrht.open3d
from conftest import angle_errors_deg

o3d = pytest.importorskip("open3d")


def test_fills_the_normals_of_a_point_cloud(fandisk):
    points, truth = fandisk
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    assert not pcd.has_normals()
    assert cgal_rrht.open3d.estimate_normals(pcd, k=50, seed=2) is pcd
    assert pcd.has_normals() and len(pcd.normals) == len(points)
    normals = np.asarray(pcd.normals)
    assert np.array_equal(normals, cgal_rrht.estimate_normals(points, k=50, seed=2))
    assert np.array_equal(np.asarray(pcd.points), points)
    assert np.mean(angle_errors_deg(normals, truth) > 10) < 0.05


def test_returns_the_confidence_on_request(fandisk):
    points, _ = fandisk
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    result, confidence = cgal_rrht.open3d.estimate_normals(pcd, k=50, return_confidence=True)
    expected_normals, expected_confidence = cgal_rrht.estimate_normals(points, k=50, return_confidence=True)
    assert result is pcd
    assert np.array_equal(np.asarray(pcd.normals), expected_normals)
    assert np.array_equal(confidence, expected_confidence)


def test_replaces_existing_normals_and_orients_with_open3d(fandisk):
    points, truth = fandisk
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(30))
    cgal_rrht.open3d.estimate_normals(pcd)
    pcd.orient_normals_consistent_tangent_plane(10)
    oriented = np.asarray(pcd.normals)
    assert np.array_equal(np.abs(oriented), np.abs(cgal_rrht.estimate_normals(points)))


def test_empty_point_cloud_and_bad_arguments():
    pcd = o3d.geometry.PointCloud()
    cgal_rrht.open3d.estimate_normals(pcd)
    assert len(pcd.normals) == 0
    with pytest.raises(TypeError, match="open3d.geometry.PointCloud"):
        cgal_rrht.open3d.estimate_normals(np.zeros((10, 3)))
    with pytest.raises(ValueError, match="unknown sampling"):
        cgal_rrht.open3d.estimate_normals(o3d.geometry.PointCloud(), sampling="grid")
