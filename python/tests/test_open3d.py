# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""cgal_rrht.open3d.estimate_normals() and orient_normals() on an Open3D point cloud."""

import numpy as np
import open3d as o3d
import pytest

import cgal_rrht
import cgal_rrht.open3d
from conftest import angle_errors_deg, noisy_cube


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


def test_search_param_as_in_open3d(fandisk):
    """Open3D's search parameters give the normals of the same neighborhoods, fewer wrong ones than Open3D's."""
    points, truth = fandisk
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    spacing = np.mean(pcd.compute_nearest_neighbor_distance())
    # Open3D counts the point itself among knn and max_nn.
    cases = [(o3d.geometry.KDTreeSearchParamKNN(50), {"k": 49}),
             (o3d.geometry.KDTreeSearchParamRadius(6 * spacing), {"k": 0, "radius": 6 * spacing}),
             (o3d.geometry.KDTreeSearchParamHybrid(radius=6 * spacing, max_nn=30), {"k": 29, "radius": 6 * spacing})]
    for search_param, neighborhood in cases:
        cgal_rrht.open3d.estimate_normals(pcd, search_param=search_param)
        normals = np.asarray(pcd.normals).copy()
        assert np.array_equal(normals, cgal_rrht.estimate_normals(points, **neighborhood)), search_param
        theirs = o3d.geometry.PointCloud(pcd.points)
        theirs.estimate_normals(search_param)
        rrht_wrong = np.mean(angle_errors_deg(normals, truth) > 10)
        open3d_wrong = np.mean(angle_errors_deg(np.asarray(theirs.normals), truth) > 10)
        assert rrht_wrong < 0.5 * open3d_wrong, (search_param, rrht_wrong, open3d_wrong)
    with pytest.raises(TypeError, match="either by search_param or by k"):
        cgal_rrht.open3d.estimate_normals(pcd, search_param=o3d.geometry.KDTreeSearchParamKNN(50), k=50)
    with pytest.raises(TypeError, match="KDTreeSearchParamKNN"):
        cgal_rrht.open3d.estimate_normals(pcd, search_param=50)
    with pytest.raises(ValueError, match="a plane needs 3"):
        cgal_rrht.open3d.estimate_normals(pcd, search_param=o3d.geometry.KDTreeSearchParamKNN(2))


def test_empty_point_cloud_and_bad_arguments():
    pcd = o3d.geometry.PointCloud()
    cgal_rrht.open3d.estimate_normals(pcd)
    assert len(pcd.normals) == 0
    with pytest.raises(TypeError, match="open3d.geometry.PointCloud"):
        cgal_rrht.open3d.estimate_normals(np.zeros((10, 3)))
    with pytest.raises(ValueError, match="unknown sampling"):
        cgal_rrht.open3d.estimate_normals(o3d.geometry.PointCloud(), sampling="grid")


def test_orient_consistent_in_place_of_orient_normals_consistent_tangent_plane():
    """estimate_normals(pcd, orient="consistent"): the normals of cgal_rrht.estimate_normals, out of a noisy cube."""
    points, truth = noisy_cube(20000)
    truth *= np.sign(np.sum(truth * (points - 0.5), axis=1))[:, None]  # outward
    fast = dict(k=60, planes=300, rotations=2)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    assert cgal_rrht.open3d.estimate_normals(pcd, orient="consistent", **fast) is pcd
    normals = np.asarray(pcd.normals)
    assert np.array_equal(normals, cgal_rrht.estimate_normals(points, orient="consistent", **fast))
    ours = np.mean(np.sum(normals * truth, axis=1) > 0)
    theirs = o3d.geometry.PointCloud(pcd)
    theirs.orient_normals_consistent_tangent_plane(18)
    share = np.mean(np.sum(np.asarray(theirs.normals) * truth, axis=1) > 0)
    print(f"outward: cgal_rrht {ours:.2%}, Open3D's orient_normals_consistent_tangent_plane(18) {share:.2%} "
          "(its sign chosen by chance)")
    assert ours >= 0.99


def test_orient_normals_of_a_point_cloud(fandisk):
    """In place of Open3D's three orientations: the same signs towards a direction and a camera."""
    points, truth = fandisk
    unoriented = cgal_rrht.estimate_normals(points, k=30)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    pcd.normals = o3d.utility.Vector3dVector(unoriented)
    assert cgal_rrht.open3d.orient_normals(pcd) is pcd
    assert np.array_equal(np.asarray(pcd.normals), cgal_rrht.orient_normals(points, unoriented))
    assert np.array_equal(np.asarray(cgal_rrht.open3d.orient_normals(pcd, k=8).normals),
                          cgal_rrht.orient_normals(points, unoriented, k=8))
    for ours, theirs in [
        (dict(direction=(0.3, -1.0, 2.0)), lambda cloud: cloud.orient_normals_to_align_with_direction([0.3, -1.0, 2.0])),
        (dict(direction="up"), lambda cloud: cloud.orient_normals_to_align_with_direction([0.0, 0.0, 1.0])),
        (dict(viewpoint=(0.1, 0.2, 3.0)), lambda cloud: cloud.orient_normals_towards_camera_location([0.1, 0.2, 3.0])),
    ]:
        pcd.normals = o3d.utility.Vector3dVector(unoriented)
        cgal_rrht.open3d.orient_normals(pcd, **ours)
        reference = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
        reference.normals = o3d.utility.Vector3dVector(unoriented)
        theirs(reference)
        assert np.array_equal(np.asarray(pcd.normals), np.asarray(reference.normals)), ours
    assert np.array_equal(np.asarray(pcd.points), points)


def test_orient_normals_bad_point_clouds():
    empty = o3d.geometry.PointCloud()
    assert len(cgal_rrht.open3d.orient_normals(empty).normals) == 0
    with pytest.raises(ValueError, match="pcd has no normals: estimate them first"):
        cgal_rrht.open3d.orient_normals(o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.zeros((5, 3)))))
    with pytest.raises(TypeError, match="open3d.geometry.PointCloud"):
        cgal_rrht.open3d.orient_normals(np.zeros((10, 3)))
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.eye(3)))
    pcd.normals = o3d.utility.Vector3dVector(np.eye(3))
    with pytest.raises(ValueError, match="give direction or viewpoint, not both"):
        cgal_rrht.open3d.orient_normals(pcd, direction="up", viewpoint=(0, 0, 1))
    with pytest.raises(ValueError, match="give orient or viewpoint, not both"):
        cgal_rrht.open3d.estimate_normals(pcd, orient="up", viewpoint=(0, 0, 1))
