# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""cgal_rrht.estimate_normals(): accuracy, arrays in and out, parameters, bad input."""

import doctest

import numpy as np
import pytest

import open3d as o3d

import cgal_rrht
from conftest import DEPRECATED, angle_errors_deg, assert_documented, noisy_cube


def test_noisy_cube_is_sharper_than_open3d():
    """On a cube with 0.2% noise, RRHT keeps the edges that Open3D's PCA rounds off."""
    points, truth = noisy_cube(20000)
    rrht_above = np.mean(angle_errors_deg(cgal_rrht.estimate_normals(points), truth) > 10)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(30))
    open3d_above = np.mean(angle_errors_deg(np.asarray(pcd.normals), truth) > 10)
    print(f"share above 10 degrees: RRHT {rrht_above:.2%}, Open3D KNN 30 {open3d_above:.2%}")
    assert rrht_above < 0.3 * open3d_above
    assert rrht_above < 0.05


def test_refit_smooths_a_sphere_like_open3d_and_keeps_the_cube_sharp():
    """refit=True: on a noisy sphere, errors near those of Open3D's PCA; on a noisy cube, edges kept."""
    rng = np.random.default_rng(5)
    sphere = rng.normal(size=(20000, 3))
    sphere /= np.linalg.norm(sphere, axis=1, keepdims=True)
    truth = sphere.copy()
    sphere += rng.normal(scale=0.002 * np.sqrt(12.0), size=sphere.shape)  # 0.2% of the diagonal
    rms = {}
    for name, normals in (("rrht", cgal_rrht.estimate_normals(sphere, setting="paper_precise")),
                          ("refit", cgal_rrht.estimate_normals(sphere, setting="paper_precise", refit=True)),
                          ("default", cgal_rrht.estimate_normals(sphere))):
        rms[name] = np.sqrt(np.mean(angle_errors_deg(normals, truth) ** 2))
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(sphere))
    pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(80))
    rms["open3d"] = np.sqrt(np.mean(angle_errors_deg(np.asarray(pcd.normals), truth) ** 2))
    print("RMS (degrees):", rms)
    assert rms["refit"] < 0.7 * rms["rrht"]
    assert rms["refit"] < 1.2 * rms["open3d"]
    assert rms["default"] < 1.2 * rms["open3d"]  # least squares first
    points, cube_truth = noisy_cube(20000)
    plain = np.mean(angle_errors_deg(cgal_rrht.estimate_normals(points, setting="paper_precise"), cube_truth) > 10)
    refitted = np.mean(angle_errors_deg(cgal_rrht.estimate_normals(points, setting="paper_precise", refit=True),
                                        cube_truth) > 10)
    print(f"cube, share above 10 degrees: RRHT {plain:.2%}, with refit {refitted:.2%}")
    assert refitted <= plain + 0.001


def roc_auc(score, positive):
    """Area under the ROC curve of ``score`` as a predictor of ``positive`` (ties count one half)."""
    order = np.argsort(score, kind="stable")
    sorted_score = score[order]
    ranks = np.empty(len(score))
    # Average ranks (from 1) over runs of equal scores.
    _, first, counts = np.unique(sorted_score, return_index=True, return_counts=True)
    ranks[order] = np.repeat(first + (counts + 1) / 2.0, counts)
    n1 = positive.sum()
    n0 = len(positive) - n1
    return (ranks[positive].sum() - n1 * (n1 + 1) / 2.0) / (n1 * n0)


def test_confidence_predicts_the_errors_of_a_noisy_cube():
    """1 - confidence ranks the normals off by more than 10 degrees first (AUC), and is
    lower near the edges; asking for it changes no normal."""
    points, truth = noisy_cube(20000)
    normals, confidence = cgal_rrht.estimate_normals(points, return_confidence=True)
    assert confidence.shape == (len(points),) and confidence.dtype == np.float64
    assert np.all((confidence > 0) & (confidence <= 1))
    assert np.array_equal(normals, cgal_rrht.estimate_normals(points))
    wrong = angle_errors_deg(normals, truth) > 10
    auc = roc_auc(1 - confidence, wrong)
    # Distance to the nearest edge of the unit cube: the second smallest distance to a face plane.
    near_edge = np.sort(np.minimum(np.abs(points), np.abs(1 - points)), axis=1)[:, 1] < 0.01 * np.sqrt(3)
    print(f"AUC {auc:.3f}, median confidence {np.median(confidence[near_edge]):.3f} near edges, "
          f"{np.median(confidence[~near_edge]):.3f} elsewhere")
    assert auc >= 0.88
    assert np.median(confidence[near_edge]) < 0.6 * np.median(confidence[~near_edge])


def test_confidence_of_points_without_normal_is_zero():
    points, _ = noisy_cube(3000)
    points[10] = [np.nan, 0, 0]
    normals, confidence = cgal_rrht.estimate_normals(points, k=30, return_confidence=True)
    assert confidence[10] == 0 and np.array_equal(normals[10], np.zeros(3))
    line = np.outer(np.arange(50.0), [1.0, 2.0, 3.0])
    normals, confidence = cgal_rrht.estimate_normals(line, k=10, return_confidence=True)
    assert np.array_equal(confidence, np.zeros(50))
    normals, confidence = cgal_rrht.estimate_normals(np.zeros((0, 3)), return_confidence=True)
    assert normals.shape == (0, 3) and confidence.shape == (0,)


def test_fandisk_against_exact_normals(fandisk):
    points, truth = fandisk
    assert np.mean(angle_errors_deg(cgal_rrht.estimate_normals(points), truth) > 10) < 0.07
    assert np.mean(angle_errors_deg(cgal_rrht.estimate_normals(points, k=30), truth) > 10) < 0.045


def test_output_is_unit_float64_and_input_untouched(fandisk):
    points, _ = fandisk
    before = points.copy()
    normals = cgal_rrht.estimate_normals(points, k=30)
    assert normals.dtype == np.float64 and normals.shape == points.shape and normals.flags.c_contiguous
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-12)
    assert np.array_equal(points, before)


def test_float32_and_other_layouts_give_the_same_normals(fandisk):
    """float32 is widened exactly; Fortran order, strided views and lists are copied first."""
    points = fandisk[0].astype(np.float32)
    expected = cgal_rrht.estimate_normals(points.astype(np.float64), k=30)
    assert np.array_equal(cgal_rrht.estimate_normals(points, k=30), expected)
    wide = points.astype(np.float64)
    assert np.array_equal(cgal_rrht.estimate_normals(np.asfortranarray(wide), k=30), expected)
    padded = np.zeros((len(wide), 4))
    padded[:, :3] = wide
    assert np.array_equal(cgal_rrht.estimate_normals(padded[:, :3], k=30), expected)
    assert np.array_equal(cgal_rrht.estimate_normals(wide[:200].tolist(), k=30),
                          cgal_rrht.estimate_normals(wide[:200], k=30))


def test_same_seed_same_normals_whatever_the_threads(fandisk):
    points, _ = fandisk
    one = cgal_rrht.estimate_normals(points, threads=1, seed=3)
    assert np.array_equal(one, cgal_rrht.estimate_normals(points, threads=2, seed=3))
    assert np.array_equal(one, cgal_rrht.estimate_normals(points, seed=3))
    assert not np.array_equal(one, cgal_rrht.estimate_normals(points, threads=1, seed=4))


def test_settings_are_their_parameters(fandisk):
    """A setting gives the defaults of planes and rotations; a value given wins."""
    points = fandisk[0][:5000]
    default = cgal_rrht.estimate_normals(points, k=40)
    assert np.array_equal(default, cgal_rrht.estimate_normals(points, k=40, setting="default"))
    precise = cgal_rrht.estimate_normals(points, k=40, setting="paper_precise")
    assert not np.array_equal(precise, default)
    fast = cgal_rrht.estimate_normals(points, k=40, setting="paper_fast")
    assert np.array_equal(fast, cgal_rrht.estimate_normals(points, k=40, setting="paper_precise", planes=300,
                                                           rotations=2))
    assert not np.array_equal(fast, precise)
    assert np.array_equal(precise, cgal_rrht.estimate_normals(points, k=40, setting="paper_fast", planes=691,
                                                              rotations=5))
    with pytest.raises(ValueError, match="unknown setting 'paper'"):
        cgal_rrht.estimate_normals(points, setting="paper")


def test_deprecated_switches_still_work_with_a_warning(fandisk):
    """least_squares_first= and adaptive=, which setting= replaces, win over the setting for one release."""
    points = fandisk[0][:5000]
    with pytest.warns(DeprecationWarning, match="least_squares_first= is deprecated and will be removed: use setting="):
        precise = cgal_rrht.estimate_normals(points, k=40, least_squares_first=False, adaptive=False)
    assert np.array_equal(precise, cgal_rrht.estimate_normals(points, k=40, setting="paper_precise"))
    with pytest.warns(DeprecationWarning, match="adaptive= is deprecated"):
        default = cgal_rrht.estimate_normals(points, k=40, setting="paper_precise", least_squares_first=True,
                                             adaptive=True)
    assert np.array_equal(default, cgal_rrht.estimate_normals(points, k=40))


@pytest.mark.parametrize(
    "parameters",
    [
        dict(setting="paper_fast", sampling="cubes"),
        dict(setting="paper_fast", sampling="unif", aggregation="mean"),
        dict(radius=0.05, k=0, seed=7),
        dict(setting="paper_precise", radius=0.05, k=30, aggregation="best", slices=12),
        dict(setting="paper_precise", confidence_interval=False, planes=200, presampling=2, cluster_angle=30.0),
        dict(setting="paper_precise"),
        dict(refit=True),
        dict(setting="paper_fast", refit=True),
        # The deprecated switches' combinations, which no setting gives.
        pytest.param(dict(setting="paper_precise", adaptive=True), marks=DEPRECATED),
        pytest.param(dict(setting="paper_precise", least_squares_first=True), marks=DEPRECATED),
        pytest.param(dict(adaptive=False), marks=DEPRECATED),
        pytest.param(dict(least_squares_first=False), marks=DEPRECATED),
    ],
)
def test_every_parameter_reaches_the_estimation(fandisk, parameters):
    """Each setting gives good normals, and other normals than the defaults."""
    points, truth = fandisk
    normals = cgal_rrht.estimate_normals(points, **parameters)
    assert np.mean(angle_errors_deg(normals, truth) > 10) < 0.1
    assert not np.array_equal(normals, cgal_rrht.estimate_normals(points))


def test_empty_and_degenerate_input():
    assert cgal_rrht.estimate_normals(np.zeros((0, 3))).shape == (0, 3)
    # Fewer than 3 distinct points, or collinear ones: no plane, zero normals.
    assert np.array_equal(cgal_rrht.estimate_normals(np.ones((5, 3))), np.zeros((5, 3)))
    line = np.outer(np.arange(50.0), [1.0, 2.0, 3.0])
    assert np.array_equal(cgal_rrht.estimate_normals(line, k=10), np.zeros((50, 3)))


def test_non_finite_points_get_zero_normals_and_no_nan():
    points, _ = noisy_cube(3000)
    points[10] = [np.nan, 0, 0]
    points[20] = [np.inf, 1, 1]
    normals = cgal_rrht.estimate_normals(points, k=30)
    assert np.all(np.isfinite(normals))
    assert np.array_equal(normals[[10, 20]], np.zeros((2, 3)))
    assert np.all(np.linalg.norm(np.delete(normals, [10, 20], axis=0), axis=1) > 0.999)


@pytest.mark.parametrize(
    "points, error, message",
    [
        (np.zeros((10, 2)), ValueError, r"shape \(N, 3\), not \(10, 2\)"),
        (np.zeros(30), ValueError, r"shape \(N, 3\)"),
        (np.zeros((2, 3, 3)), ValueError, r"shape \(N, 3\)"),
        (np.zeros((10, 3), dtype=np.int64), TypeError, "float64 or float32, not int64"),
        (np.zeros((10, 3), dtype=np.float16), TypeError, "float64 or float32, not float16"),
        (np.zeros((10, 3), dtype=complex), TypeError, "float64 or float32"),
        ([["a", "b", "c"]], ValueError, "could not convert"),
    ],
)
def test_bad_points(points, error, message):
    with pytest.raises(error, match=message):
        cgal_rrht.estimate_normals(points)


@pytest.mark.parametrize(
    "parameters, error, message",
    [
        (dict(k=0), ValueError, "k must be at least 1 when no neighbor_radius is given"),
        (dict(k=-1), ValueError, "k must be from 0 to 4294967295, got -1"),
        (dict(k=2**40), ValueError, "k must be from 0 to"),
        (dict(k=2**70), ValueError, "k must be from 0 to 4294967295, got 1180591620717411303424"),
        (dict(k=10.5), TypeError, "k must be an integer, not float"),
        (dict(k=True), TypeError, "k must be an integer, not bool"),
        (dict(radius=-1.0), ValueError, "neighbor_radius must be finite and non-negative"),
        (dict(radius=float("nan")), ValueError, "neighbor_radius must be finite and non-negative"),
        (dict(radius=float("inf")), ValueError, "neighbor_radius must be finite and non-negative"),
        (dict(setting="fast"), ValueError, "unknown setting 'fast': use one of 'default', 'paper_precise', "
                                           "'paper_fast'"),
        (dict(planes=0), ValueError, r"number_of_planes \(T_R\) must be from 1 to 100000000"),
        (dict(rotations=0), ValueError, r"number_of_rotations \(n_rot\) must be from 1 to 100000"),
        (dict(rotations=-3), ValueError, r"number_of_rotations \(n_rot\) must be from 1 to 100000"),
        (dict(slices=1001), ValueError, r"accumulator_slices \(n_phi\) must be from 1 to 1000"),
        (dict(presampling=33), ValueError, r"presampling_factor \(c\) must be from 1 to 32"),
        (dict(cluster_angle=181.0), ValueError, "cluster_angle must be from 0 to 180 degrees"),
        (dict(cluster_angle=float("nan")), ValueError, "cluster_angle must be from 0 to 180 degrees"),
        (dict(seed=-1), ValueError, "seed must be from 0 to 4294967295"),
        (dict(seed=2**32), ValueError, "seed must be from 0 to 4294967295"),
        (dict(threads=0), ValueError, "threads must be from 1 to 1024, got 0"),
        (dict(threads=5000), ValueError, "threads must be from 1 to 1024, got 5000"),
        (dict(sampling="Cubes"), ValueError, "unknown sampling 'Cubes': use one of 'points', 'cubes', 'unif'"),
        (dict(aggregation="median"), ValueError, "unknown aggregation 'median': use one of 'mean', 'best', 'cluster'"),
        (dict(sampling=5), ValueError, "unknown sampling '5'"),
        (dict(planes=2.5), TypeError, "planes must be an integer, not float"),
        (dict(rotations=np.float64(2)), TypeError, "rotations must be an integer, not float64"),
        (dict(threads="2"), TypeError, "threads must be an integer, not str"),
        (dict(planes=2**70), ValueError, "planes must be from -9223372036854775808 to 9223372036854775807"),
    ],
)
def test_bad_parameters(parameters, error, message):
    """Checked before anything runs, also on an empty cloud, with the C++ message where C++ checks."""
    for points in (np.zeros((0, 3)), noisy_cube(100)[0]):
        with pytest.raises(error, match=message):
            cgal_rrht.estimate_normals(points, **parameters)


def test_numpy_integers_are_integers(fandisk):
    points = fandisk[0][:2000]
    assert np.array_equal(cgal_rrht.estimate_normals(points, k=np.int32(20), seed=np.uint64(5)),
                          cgal_rrht.estimate_normals(points, k=20, seed=5))


def test_progress_bar(fandisk, capsys):
    points = fandisk[0]
    normals = cgal_rrht.estimate_normals(points, k=30, progress=True)
    assert np.array_equal(normals, cgal_rrht.estimate_normals(points, k=30))
    assert "20.0k/20.0k" in capsys.readouterr().err


def test_documentation():
    """help() lists every parameter with its default and the paper's name."""
    doc = assert_documented(cgal_rrht.estimate_normals, ["points", "k"])
    for paper_name in ("[K]", "[r]", "[T_R]", "[n_rot]", "[n_phi]", "eq. 10", "[RRHT_Points]", "[c]", "[RRHT_m",
                       "[a_cluster]"):
        assert paper_name in doc


def test_docstring_example():
    assert doctest.testmod(cgal_rrht, raise_on_error=True).attempted > 0


# Least squares first (the default) depends on the neighbors' neighbors: wider supports.
@pytest.mark.parametrize("setting, share", [("default", 0.6), ("paper_precise", 0.8)])
def test_ids_make_a_part_of_the_cloud_give_the_normals_of_the_whole(fandisk, setting, share):
    points = fandisk[0]
    whole, confidence, support = cgal_rrht.estimate_normals(points, k=30, setting=setting, return_confidence=True,
                                                            return_support=True)
    assert np.array_equal(whole, cgal_rrht.estimate_normals(points, k=30, setting=setting,
                                                            ids=np.arange(len(points))))
    cut = np.median(points[:, 0])
    part = np.flatnonzero(points[:, 0] < cut)[::-1]  # in another order
    normals, part_confidence, part_support = cgal_rrht.estimate_normals(
        points[part], k=30, setting=setting, ids=part, return_confidence=True, return_support=True)
    inside = cut - points[part, 0] > part_support * (1 + 1e-9)
    assert inside.mean() > share
    assert np.array_equal(normals[inside], whole[part[inside]])
    assert np.array_equal(part_confidence[inside], confidence[part[inside]])
    assert np.array_equal(part_support[inside], support[part[inside]])
    # Without the ids, the rows of the part key other random streams: other
    # normals wherever the Hough transform's normal is taken (by default, not
    # where the quadric or a neighbor's plane is kept).
    differ = (cgal_rrht.estimate_normals(points[part], k=30, setting=setting)[inside] != whole[part[inside]]).any(axis=1)
    assert differ.mean() > (0.5 if setting == "paper_precise" else 0.02)


def test_support_is_the_distance_to_the_kth_neighbor(fandisk):
    points = fandisk[0][:3000]
    normals, support = cgal_rrht.estimate_normals(points, k=20, setting="paper_precise", return_support=True)
    assert normals.shape == (3000, 3) and support.shape == (3000,)
    distances = np.sort(np.linalg.norm(points[:50, None, :] - points[None, :, :], axis=2), axis=1)
    assert np.allclose(support[:50], distances[:, 20], rtol=1e-12)
    _, refit_support = cgal_rrht.estimate_normals(points, k=20, setting="paper_precise", refit=True,
                                                  return_support=True)
    assert (refit_support >= support).all() and (refit_support <= 3 * support).all()
    # Least squares first (the default) reads the neighborhoods of the neighbors' neighbors.
    _, default_support = cgal_rrht.estimate_normals(points, k=20, return_support=True)
    assert (default_support >= 2 * support).all() and (default_support <= 5 * support).all()
    assert np.isinf(cgal_rrht.estimate_normals(points[:10], k=20, return_support=True)[1]).all()


@pytest.mark.parametrize(
    "ids, error, message",
    [
        (np.arange(5.0), TypeError, "ids must be integers, not float64"),
        (np.arange(4), ValueError, r"ids must have the shape \(5,\), one per point, not \(4,\)"),
        (np.arange(10).reshape(5, 2), ValueError, r"ids must have the shape \(5,\)"),
        (np.array([0, 1, -2, 3, 4]), ValueError, "ids must be non-negative"),
    ],
)
def test_bad_ids(ids, error, message):
    with pytest.raises(error, match=message):
        cgal_rrht.estimate_normals(noisy_cube(5)[0], k=3, ids=ids)


@pytest.mark.parametrize("refit", [False, True])
def test_a_halo_is_only_neighbors(fandisk, refit):
    points = fandisk[0]
    whole, support = cgal_rrht.estimate_normals(points, k=30, refit=refit, return_support=True)
    normals, own_support = cgal_rrht.estimate_normals(points[:5000], k=30, refit=refit, halo=points[5000:],
                                                      return_support=True)
    assert normals.shape == (5000, 3) and own_support.shape == (5000,)
    assert np.array_equal(normals, whole[:5000]) and np.array_equal(own_support, support[:5000])
    rows = np.arange(len(points))[::-1]  # the same with ids, the points in another order
    assert np.array_equal(
        cgal_rrht.estimate_normals(points[rows][:7000], k=30, refit=refit, ids=rows[:7000],
                                   halo=points[rows][7000:], halo_ids=rows[7000:]),
        whole[rows[:7000]])
    if not refit:  # the deprecated names still work, with a warning
        with pytest.warns(DeprecationWarning, match=r"neighbors= is deprecated: it is now halo="):
            assert np.array_equal(cgal_rrht.estimate_normals(points[:5000], k=30, neighbors=points[5000:]),
                                  whole[:5000])
        with pytest.warns(DeprecationWarning, match=r"neighbor_ids= is deprecated: it is now halo_ids="):
            cgal_rrht.estimate_normals(points[:10], k=30, ids=np.arange(10), halo=points[10:20],
                                       neighbor_ids=np.arange(10, 20))


@pytest.mark.parametrize(
    "arguments, error, message",
    [
        (dict(halo=np.zeros((4, 2))), ValueError, r"halo must have the shape \(M, 3\), not \(4, 2\)"),
        (dict(halo=np.zeros((4, 3), dtype=int)), TypeError, "halo must be float64 or float32, not int64"),
        (dict(halo=np.zeros((4, 3)), ids=np.arange(5)), ValueError, "give both ids and halo_ids, or neither"),
        (dict(halo_ids=np.arange(4)), ValueError, "halo_ids without halo"),
        (dict(halo=np.zeros((4, 3)), ids=np.arange(5), halo_ids=np.arange(3)), ValueError,
         r"halo_ids must have the shape \(4,\), one per point, not \(3,\)"),
        (dict(halo=np.zeros((4, 3)), neighbors=np.zeros((4, 3))), TypeError,
         "give halo= only: neighbors= is its deprecated name"),
    ],
)
def test_bad_halo(arguments, error, message):
    with pytest.raises(error, match=message):
        cgal_rrht.estimate_normals(noisy_cube(5)[0], k=3, **arguments)
