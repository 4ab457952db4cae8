# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""cgal_rrht.orient_normals() and estimate_normals(orient=..., viewpoint=...):
outward on closed shapes, towards directions and viewpoints, the same normals
as rrht_normals --orient and for any number of threads, bad input."""

import subprocess

import numpy as np
import pytest

import cgal_rrht
from conftest import DATA, angle_errors_deg, assert_documented, noisy_cube

# The fast setting: the orientation, not the estimation, is under test.
FAST = dict(k=60, planes=300, rotations=2)


def outward_cube(n, seed=1):
    """A noisy unit cube (conftest) with its exact normals turned out of it."""
    points, truth = noisy_cube(n, seed=seed)
    return points, truth * np.sign(np.sum(truth * (points - 0.5), axis=1))[:, None]


def noisy_sphere(n, seed=5):
    """``n`` points on the unit sphere with 0.2% noise, and their exact outward normals."""
    rng = np.random.default_rng(seed)
    truth = rng.normal(size=(n, 3))
    truth /= np.linalg.norm(truth, axis=1, keepdims=True)
    return truth + rng.normal(scale=0.002 * np.sqrt(12.0), size=truth.shape), truth


def random_signs(normals, seed=0):
    """``normals`` with each row's sign drawn at random: an unoriented input whatever the estimator gave."""
    return normals * np.random.default_rng(seed).choice([-1.0, 1.0], size=(len(normals), 1))


def flipped_or_kept(oriented, normals):
    """Whether each row of ``oriented`` is exactly its row of ``normals``, or exactly its opposite."""
    return ((oriented == normals) | (oriented == -normals)).all(axis=1)


# --------------------------------------------------------------------------
# What the orientation gives.


def test_consistent_orientation_is_outward_on_closed_shapes(fandisk):
    """Out of a smooth sphere, of a noisy cube across its sharp edges, and of the fandisk CAD part."""
    sphere, sphere_truth = noisy_sphere(20000)
    cube, cube_truth = outward_cube(20000)
    for name, points, truth in (("sphere", sphere, sphere_truth), ("cube", cube, cube_truth)):
        normals = cgal_rrht.estimate_normals(points, orient="consistent", **FAST)
        outward = np.mean(np.sum(normals * truth, axis=1) > 0)
        print(f"{name}: {outward:.2%} outward")
        assert outward >= 0.99, name
    # The fandisk's exact normals are outward (the mesh's faces). Where RRHT's
    # normal is far off the exact one (a sharp edge's point given the other
    # face's normal), no sign of it is outward: the orientation is judged on
    # the others, and all are counted too.
    points, truth = fandisk
    normals = cgal_rrht.estimate_normals(points, orient="consistent")
    outward = np.sum(normals * truth, axis=1) > 0
    estimated = angle_errors_deg(normals, truth) < 30
    print(f"fandisk: {outward[estimated].mean():.2%} outward of the {estimated.mean():.1%} normals within 30 degrees; "
          f"{outward.mean():.2%} of all")
    assert estimated.mean() > 0.9
    assert outward[estimated].mean() >= 0.99
    assert outward.mean() >= 0.98


def test_consistent_orientation_ignores_the_signs_given():
    """Only the normals' lines matter: any signs in give the same orientation out."""
    points, truth = outward_cube(20000)
    normals = cgal_rrht.estimate_normals(points, **FAST)
    oriented = cgal_rrht.orient_normals(points, normals)
    assert flipped_or_kept(oriented, normals).all()
    for seed in (1, 2):
        assert np.array_equal(cgal_rrht.orient_normals(points, random_signs(normals, seed)), oriented)
    assert np.mean(np.sum(oriented * truth, axis=1) > 0) >= 0.99
    # Exact normals with random signs: all but a few points at the edges come out outward.
    exact = cgal_rrht.orient_normals(points, random_signs(truth))
    assert np.mean(np.sum(exact * truth, axis=1) > 0) >= 0.999


@pytest.mark.parametrize("direction, vector", [("up", (0.0, 0.0, 1.0)), ((0.3, -1.0, 2.0), (0.3, -1.0, 2.0)),
                                               (np.array([0.0, 0.0, -5.0]), (0.0, 0.0, -5.0))])
def test_direction(fandisk, direction, vector):
    points, truth = fandisk
    normals = random_signs(truth)
    oriented = cgal_rrht.orient_normals(points, normals, direction=direction)
    dots = oriented @ np.asarray(vector)
    assert (dots >= 0).all()
    assert flipped_or_kept(oriented, normals).all()
    # Flipped exactly where they pointed against the direction.
    assert np.array_equal(oriented, np.where((normals @ np.asarray(vector) < 0)[:, None], -normals, normals))
    assert np.array_equal(cgal_rrht.estimate_normals(points, k=30, orient=direction),
                          cgal_rrht.orient_normals(points, cgal_rrht.estimate_normals(points, k=30),
                                                   direction=direction))


def test_up_on_a_terrain():
    """Aerial LiDAR: a noisy terrain with steep slopes and roofs; every normal comes out with n_z >= 0."""
    rng = np.random.default_rng(8)
    xy = rng.random((30000, 2)) * 10
    z = np.sin(xy[:, 0]) * np.cos(0.7 * xy[:, 1]) + np.where((xy % 3 < 1).all(axis=1), 0.8, 0.0)
    points = np.column_stack([xy, z + rng.normal(scale=0.005, size=len(z))])
    oriented = cgal_rrht.estimate_normals(points, orient="up", **FAST)
    assert (oriented[:, 2] >= 0).all()
    assert np.allclose(np.linalg.norm(oriented, axis=1), 1.0)


def test_viewpoint_outside_and_inside(fandisk):
    points, truth = fandisk
    normals = random_signs(truth)
    for viewpoint in ((0.1, 0.2, 3.0), (-2.0, 1.0, 0.5), points.mean(axis=0)):
        oriented = cgal_rrht.orient_normals(points, normals, viewpoint=viewpoint)
        assert (np.sum(oriented * (np.asarray(viewpoint) - points), axis=1) >= 0).all()
        assert flipped_or_kept(oriented, normals).all()
    sphere, sphere_truth = noisy_sphere(5000)
    assert np.array_equal(cgal_rrht.orient_normals(sphere, random_signs(sphere_truth), viewpoint=[0, 0, 0]),
                          -sphere_truth)


def test_a_viewpoint_per_point():
    """Each normal faces its own sensor position; one position repeated is one viewpoint."""
    points, truth = outward_cube(10000)
    rng = np.random.default_rng(3)
    sensors = points + rng.normal(size=points.shape) * 2  # on either side of the surface
    normals = random_signs(truth)
    oriented = cgal_rrht.orient_normals(points, normals, viewpoint=sensors)
    dots = np.sum(oriented * (sensors - points), axis=1)
    assert (dots >= 0).all()
    assert 0.3 < np.mean(np.sum(oriented * truth, axis=1) > 0) < 0.7  # the sensors are on both sides
    assert flipped_or_kept(oriented, normals).all()
    scanner = np.array([0.5, 0.5, 4.0])
    assert np.array_equal(cgal_rrht.orient_normals(points, normals, viewpoint=np.tile(scanner, (len(points), 1))),
                          cgal_rrht.orient_normals(points, normals, viewpoint=scanner))
    assert np.array_equal(cgal_rrht.orient_normals(points, normals, viewpoint=sensors.astype(np.float32)),
                          cgal_rrht.orient_normals(points, normals, viewpoint=sensors.astype(np.float32)
                                                   .astype(np.float64)))
    # In estimate_normals, the rows of the points.
    estimated = cgal_rrht.estimate_normals(points, viewpoint=sensors, **FAST)
    assert np.array_equal(estimated, cgal_rrht.orient_normals(points, cgal_rrht.estimate_normals(points, **FAST),
                                                              viewpoint=sensors))


# --------------------------------------------------------------------------
# The same normals as the command-line tool and for any number of threads.

# rrht_normals --orient values, and the same for estimate_normals.
CLI_ORIENTATIONS = [
    ("--orient", dict(orient="consistent")),
    ("--orient=up", dict(orient="up")),
    ("--orient=0.3,-1,2", dict(orient=(0.3, -1.0, 2.0))),
    ("--orient=viewpoint:0.1,0.2,3", dict(viewpoint=(0.1, 0.2, 3.0))),
]


@pytest.mark.parametrize("flag, orientation", CLI_ORIENTATIONS)
def test_same_normals_as_the_cli(cli, tmp_path, flag, orientation):
    source = DATA / "fandisk_20k.xyz"
    output = tmp_path / "normals.xyz"
    subprocess.run([cli, str(source), str(output), "--precision", "17", "-q", "-k", "30", flag], check=True,
                   stdout=subprocess.DEVNULL)
    written = np.loadtxt(output)
    points = np.loadtxt(source)
    assert np.array_equal(written[:, :3], points)  # every point has a normal: none moved to the end
    normals = cgal_rrht.estimate_normals(points, k=30, **orientation)
    assert np.array_equal(normals, written[:, 3:])
    unoriented = cgal_rrht.estimate_normals(points, k=30)
    direction = orientation.get("orient")
    separate = cgal_rrht.orient_normals(points, unoriented, viewpoint=orientation.get("viewpoint"),
                                        direction=None if direction == "consistent" else direction)
    assert np.array_equal(separate, normals)


def test_same_orientation_whatever_the_threads(fandisk):
    points, _ = fandisk
    normals = cgal_rrht.estimate_normals(points, k=30)
    one = cgal_rrht.orient_normals(points, normals, threads=1)
    assert not np.array_equal(one, normals)  # something was flipped
    assert np.array_equal(one, cgal_rrht.orient_normals(points, normals, threads=2))
    assert np.array_equal(one, cgal_rrht.orient_normals(points, normals))
    assert np.array_equal(cgal_rrht.estimate_normals(points, k=30, orient="consistent", threads=1),
                          cgal_rrht.estimate_normals(points, k=30, orient="consistent", threads=2))
    assert not np.array_equal(one, cgal_rrht.orient_normals(points, normals, k=8))  # k reaches the orientation


def test_estimate_normals_is_unchanged_without_orient(fandisk):
    points, _ = fandisk
    plain, confidence, support = cgal_rrht.estimate_normals(points, k=30, return_confidence=True,
                                                            return_support=True)
    again = cgal_rrht.estimate_normals(points, k=30, orient=None, viewpoint=None, return_confidence=True,
                                       return_support=True)
    assert all(np.array_equal(a, b) for a, b in zip(again, (plain, confidence, support)))
    assert np.array_equal(cgal_rrht.estimate_normals(points, k=30), plain)
    # Orienting changes the signs only, and nothing else returned.
    oriented, oriented_confidence, oriented_support = cgal_rrht.estimate_normals(
        points, k=30, orient="consistent", return_confidence=True, return_support=True)
    assert flipped_or_kept(oriented, plain).all() and not np.array_equal(oriented, plain)
    assert np.array_equal(oriented_confidence, confidence) and np.array_equal(oriented_support, support)


# --------------------------------------------------------------------------
# Arrays in and out, and bad input.


def test_a_new_array_in_the_order_of_the_input(fandisk):
    points, truth = fandisk
    normals = random_signs(truth) * 3.0  # not unit: the lengths are kept
    before = normals.copy()
    oriented = cgal_rrht.orient_normals(points, normals)
    assert oriented is not normals and not np.shares_memory(oriented, normals)
    assert np.array_equal(normals, before)
    assert oriented.dtype == np.float64 and oriented.shape == points.shape and oriented.flags.c_contiguous
    assert flipped_or_kept(oriented, normals).all()
    # In another order, the same rows.
    order = np.random.default_rng(4).permutation(len(points))
    shuffled = cgal_rrht.orient_normals(points[order], normals[order], direction="up")
    assert np.array_equal(shuffled, cgal_rrht.orient_normals(points, normals, direction="up")[order])
    # float32, other layouts and lists: converted first.
    assert np.array_equal(cgal_rrht.orient_normals(points.astype(np.float32), normals.astype(np.float32)),
                          cgal_rrht.orient_normals(points.astype(np.float32).astype(np.float64),
                                                   normals.astype(np.float32).astype(np.float64)))
    assert np.array_equal(cgal_rrht.orient_normals(np.asfortranarray(points), normals[::1].copy(order="F")), oriented)
    assert np.array_equal(cgal_rrht.orient_normals(points[:100].tolist(), normals[:100].tolist(), direction="up"),
                          cgal_rrht.orient_normals(points[:100], normals[:100], direction="up"))


@pytest.mark.parametrize("mode", [dict(), dict(direction="up"), dict(viewpoint=(0.5, 0.5, 4.0)), "per point"])
def test_rows_that_cannot_be_oriented_are_returned_unchanged(mode):
    """Zero normals, NaN or infinite points and normals (and NaN sensor positions): as given, at their row;
    the other rows are oriented as without them."""
    points, truth = outward_cube(8000)
    normals = random_signs(truth)
    sensors = points + truth * 2
    if mode == "per point":
        mode = dict(viewpoint=sensors)
    bad = np.array([3, 10, 20, 30, 40, 7000])
    points[10] = [np.nan, 0.5, 0.5]
    points[20] = [0.5, np.inf, 0.5]
    normals[3] = 0.0
    normals[30] = [np.nan, 1.0, 0.0]
    normals[40] = [0.0, -np.inf, 0.0]
    if "viewpoint" in mode and np.ndim(mode["viewpoint"]) == 2:
        sensors[7000] = [np.nan, 0, 0]
    else:
        normals[7000] = [0.0, 0.0, np.nan]
    oriented = cgal_rrht.orient_normals(points, normals, **mode)
    assert np.array_equal(oriented[bad], normals[bad], equal_nan=True)
    good = np.setdiff1d(np.arange(len(points)), bad)
    good_mode = dict(mode, viewpoint=sensors[good]) if "viewpoint" in mode and np.ndim(mode["viewpoint"]) == 2 else mode
    assert np.array_equal(oriented[good], cgal_rrht.orient_normals(points[good], normals[good], **good_mode))
    if not mode:  # consistent: outward
        assert np.mean(np.sum(oriented[good] * truth[good], axis=1) > 0) >= 0.99


def test_estimated_zero_normals_stay_zero():
    """estimate_normals gives the zero vector to a non-finite point; no orientation changes it."""
    points, _ = outward_cube(5000)
    points[10] = [np.nan, 0, 0]
    for orientation in (dict(orient="consistent"), dict(orient="up"), dict(viewpoint=(0, 0, 5))):
        normals = cgal_rrht.estimate_normals(points, **orientation, **FAST)
        assert np.array_equal(normals[10], np.zeros(3))
        assert np.all(np.isfinite(normals))


def test_fewer_points_than_neighbors():
    """Every point is then every other's neighbor: a small patch comes out on one side."""
    rng = np.random.default_rng(2)
    points = np.column_stack([rng.random((6, 2)), np.zeros(6)])
    normals = random_signs(np.tile([0.0, 0.0, 1.0], (6, 1)), seed=5)
    assert len(np.unique(normals[:, 2])) == 2
    oriented = cgal_rrht.orient_normals(points, normals, k=18)
    assert len(np.unique(oriented[:, 2])) == 1
    for count in (1, 2):
        assert flipped_or_kept(cgal_rrht.orient_normals(points[:count], normals[:count]), normals[:count]).all()


def test_a_point_at_the_viewpoint_keeps_its_normal(fandisk):
    """A point equal to its viewpoint has no side to face: its normal is returned as given."""
    points, truth = fandisk
    normals = random_signs(truth)
    at = 123
    oriented = cgal_rrht.orient_normals(points, normals, viewpoint=points[at])
    others = np.arange(len(points)) != at
    assert np.array_equal(oriented[at], normals[at])
    assert (np.sum(oriented[others] * (points[at] - points[others]), axis=1) >= 0).all()
    for sign in (1, -1):
        assert np.array_equal(cgal_rrht.orient_normals(points, sign * normals, viewpoint=points),
                              sign * normals)  # each point its own viewpoint: nothing flips


def test_empty_input():
    empty = np.zeros((0, 3))
    for mode in (dict(), dict(direction="up"), dict(viewpoint=(1, 2, 3)), dict(viewpoint=empty)):
        assert cgal_rrht.orient_normals(empty, empty, **mode).shape == (0, 3)
    for orientation in (dict(orient="consistent"), dict(orient="up"), dict(viewpoint=(1, 2, 3))):
        assert cgal_rrht.estimate_normals(empty, **orientation).shape == (0, 3)


@pytest.mark.parametrize(
    "arguments, error, message",
    [
        (dict(direction="up", viewpoint=(0, 0, 1)), ValueError, "give direction or viewpoint, not both"),
        (dict(direction=(0, 0, 1), viewpoint=np.zeros((50, 3))), ValueError, "give direction or viewpoint, not both"),
        (dict(direction=(0, 0, 0)), ValueError, r"CGAL::rrht_orient_normals\(\): direction must be finite and not null"),
        (dict(direction=(np.nan, 0, 1)), ValueError, "direction must be finite and not null"),
        (dict(direction=(np.inf, 0, 1)), ValueError, "direction must be finite and not null"),
        (dict(viewpoint=(0, np.nan, 0)), ValueError, r"CGAL::rrht_orient_normals\(\): viewpoint must be finite"),
        (dict(k=1), ValueError, r"CGAL::rrht_orient_normals\(\): k must be at least 2"),
        (dict(k=0), ValueError, "k must be at least 2"),
        (dict(k=-1), ValueError, "k must be from 0 to 4294967295, got -1"),
        (dict(k=2.5), TypeError, "k must be an integer, not float"),
        (dict(threads=0), ValueError, "threads must be from 1 to 1024, got 0"),
        (dict(direction="down"), ValueError, "unknown direction 'down': use 'up' or three numbers"),
        (dict(direction=(0, 1)), ValueError, r"direction must be 'up' or three numbers, not an array of shape \(2,\)"),
        (dict(viewpoint=np.zeros((49, 3))), ValueError,
         r"viewpoint must be one point, of shape \(3,\), or one per point, of shape \(50, 3\), not \(49, 3\)"),
        (dict(viewpoint=np.zeros((50, 2))), ValueError, r"of shape \(50, 3\), not \(50, 2\)"),
        (dict(viewpoint=np.zeros((50, 3), dtype=int)), TypeError, "viewpoint must be float64 or float32, not int64"),
        (dict(normals=np.zeros((49, 3))), ValueError, r"normals must have the shape of points, \(50, 3\), not \(49, 3\)"),
        (dict(normals=np.zeros((50, 3), dtype=np.int32)), TypeError, "normals must be float64 or float32, not int32"),
        (dict(points=np.zeros((50, 2))), ValueError, r"points must have the shape \(N, 3\), not \(50, 2\)"),
    ],
)
def test_bad_arguments(arguments, error, message):
    """Clear errors, before anything is oriented; the input is not changed."""
    points, truth = outward_cube(50)
    call = dict(points=points, normals=truth.copy())
    call.update(arguments)
    before = call["normals"].copy()
    with pytest.raises(error, match=message):
        cgal_rrht.orient_normals(call.pop("points"), call.pop("normals"), **call)
    assert np.array_equal(before, arguments.get("normals", truth))


def test_k_is_not_used_towards_a_direction_or_a_viewpoint():
    points, truth = outward_cube(50)
    assert np.array_equal(cgal_rrht.orient_normals(points, truth, direction="up", k=1),
                          cgal_rrht.orient_normals(points, truth, direction="up"))


@pytest.mark.parametrize(
    "arguments, message",
    [
        (dict(orient="up", viewpoint=(0, 0, 5)), "give orient or viewpoint, not both"),
        (dict(orient="consistent", halo=np.zeros((4, 3))), "orient='consistent' cannot be used with a halo"),
        (dict(orient="outward"), "unknown orient 'outward': use 'consistent', 'up' or three numbers"),
        (dict(orient=(1, 2)), r"orient must be 'consistent', 'up' or three numbers, not an array of shape \(2,\)"),
        (dict(orient=(0, 0, 0)), "direction must be finite and not null"),
        (dict(viewpoint=(np.nan, 0, 0)), "viewpoint must be finite"),
        (dict(viewpoint=np.zeros((7, 3))), r"or one per point, of shape \(\d+, 3\), not \(7, 3\)"),
    ],
)
def test_bad_orientation_of_estimate_normals(arguments, message):
    """Refused before the estimation starts, on an empty cloud too."""
    for points in (np.zeros((0, 3)), noisy_cube(100)[0]):
        with pytest.raises(ValueError, match=message):
            cgal_rrht.estimate_normals(points, k=10, **arguments)


def test_documentation():
    assert_documented(cgal_rrht.orient_normals, ["points", "normals"])
