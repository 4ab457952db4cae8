# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Normal estimation that keeps sharp features, on NumPy arrays.

``cgal_rrht.estimate_normals(points)`` runs ``CGAL::rrht_estimate_normals()``,
the Robust Randomized Hough Transform of A. Boulch and R. Marlet, "Fast and
Robust Normal Estimation for Point Clouds with Sharp Features", Computer
Graphics Forum 31(5), 2012. ``cgal_rrht.orient_normals(points, normals)``
runs ``CGAL::rrht_orient_normals()``: towards a direction, towards viewpoints,
or consistently, out of closed surfaces. ``cgal_rrht.open3d`` does both on an
Open3D point cloud.
"""

from __future__ import annotations

import warnings
from typing import Any, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _core

__all__ = ["estimate_normals", "orient_normals", "SETTINGS", "SAMPLINGS", "AGGREGATIONS"]
__version__ = "0.1.0"

#: The values of ``setting``: least squares first with the adaptive Hough transform
#: (the default), and the paper's precise and fast settings (Section 6), as the C++
#: library names them.
SETTINGS: Tuple[str, ...] = _core.SETTINGS
#: The values of ``sampling``: RRHT_Points, RRHT_Cubes, RRHT_Unif (paper, Section 5),
#: as the C++ library names them.
SAMPLINGS: Tuple[str, ...] = _core.SAMPLINGS
#: The values of ``aggregation``: RRHT_m, RRHT_b, RRHT_c (paper, Section 4), as the C++
#: library names them.
AGGREGATIONS: Tuple[str, ...] = _core.AGGREGATIONS
# The neighbors of estimate_normals(orient="consistent"): those of rrht_normals --orient.
_CONSISTENT_K = 18


@overload
def estimate_normals(
    points: npt.ArrayLike,
    k: int = ...,
    *,
    setting: str = ...,
    radius: Optional[float] = ...,
    planes: Optional[int] = ...,
    rotations: Optional[int] = ...,
    slices: int = ...,
    confidence_interval: bool = ...,
    sampling: str = ...,
    presampling: int = ...,
    aggregation: str = ...,
    cluster_angle: float = ...,
    seed: int = ...,
    least_squares_first: Optional[bool] = ...,
    adaptive: Optional[bool] = ...,
    refit: bool = ...,
    ids: Optional[npt.ArrayLike] = ...,
    halo: Optional[npt.ArrayLike] = ...,
    halo_ids: Optional[npt.ArrayLike] = ...,
    threads: Optional[int] = ...,
    progress: bool = ...,
    orient: Union[None, str, npt.ArrayLike] = ...,
    viewpoint: Optional[npt.ArrayLike] = ...,
    return_confidence: Literal[False] = ...,
    return_support: Literal[False] = ...,
    neighbors: Optional[npt.ArrayLike] = ...,
    neighbor_ids: Optional[npt.ArrayLike] = ...,
) -> npt.NDArray[np.float64]: ...


@overload
def estimate_normals(
    points: npt.ArrayLike,
    k: int = ...,
    *,
    setting: str = ...,
    radius: Optional[float] = ...,
    planes: Optional[int] = ...,
    rotations: Optional[int] = ...,
    slices: int = ...,
    confidence_interval: bool = ...,
    sampling: str = ...,
    presampling: int = ...,
    aggregation: str = ...,
    cluster_angle: float = ...,
    seed: int = ...,
    least_squares_first: Optional[bool] = ...,
    adaptive: Optional[bool] = ...,
    refit: bool = ...,
    ids: Optional[npt.ArrayLike] = ...,
    halo: Optional[npt.ArrayLike] = ...,
    halo_ids: Optional[npt.ArrayLike] = ...,
    threads: Optional[int] = ...,
    progress: bool = ...,
    orient: Union[None, str, npt.ArrayLike] = ...,
    viewpoint: Optional[npt.ArrayLike] = ...,
    return_confidence: bool = ...,
    return_support: bool = ...,
    neighbors: Optional[npt.ArrayLike] = ...,
    neighbor_ids: Optional[npt.ArrayLike] = ...,
) -> Union[npt.NDArray[np.float64], Tuple[npt.NDArray[np.float64], ...]]: ...


def estimate_normals(
    points: npt.ArrayLike,
    k: int = 100,
    *,
    setting: str = "default",
    radius: Optional[float] = None,
    planes: Optional[int] = None,
    rotations: Optional[int] = None,
    slices: int = 15,
    confidence_interval: bool = True,
    sampling: str = "points",
    presampling: int = 4,
    aggregation: str = "cluster",
    cluster_angle: float = 45.0,
    seed: int = 0,
    least_squares_first: Optional[bool] = None,
    adaptive: Optional[bool] = None,
    refit: bool = False,
    ids: Optional[npt.ArrayLike] = None,
    halo: Optional[npt.ArrayLike] = None,
    halo_ids: Optional[npt.ArrayLike] = None,
    threads: Optional[int] = None,
    progress: bool = False,
    orient: Union[None, str, npt.ArrayLike] = None,
    viewpoint: Optional[npt.ArrayLike] = None,
    return_confidence: bool = False,
    return_support: bool = False,
    neighbors: Optional[npt.ArrayLike] = None,
    neighbor_ids: Optional[npt.ArrayLike] = None,
) -> Union[npt.NDArray[np.float64], Tuple[npt.NDArray[np.float64], ...]]:
    """Estimates the normals of a point cloud, keeping sharp features.

    For each point, planes through random triples of its neighbors vote in a
    Hough accumulator of directions; the normal is the mean normal of the
    most voted bin, so that near an edge the plane of the point's own side
    wins. This is done in ``rotations`` randomly rotated accumulators, whose
    normals are combined by ``aggregation``. By default, the Hough transform
    runs only where it is needed: where the neighborhood of a point is one
    smooth sheet within the noise, or one side of a thin part, the normal is
    that of a quadric fitted by least squares, as jet fitting's; elsewhere,
    as along sharp features, it is the Hough transform's, run cheaply first
    and again where its confidence is low. ``setting="paper_precise"`` and
    ``"paper_fast"`` run the paper's settings instead. The defaults are those
    of ``CGAL::rrht_estimate_normals()``; the paper's names are in brackets.

    Parameters
    ----------
    points : array_like, shape (N, 3), float64 or float32
        The points. A C-contiguous float64 array is read in place, without a
        copy; other arrays are converted to one first. Points with a NaN or
        infinite coordinate get a zero normal and are nobody's neighbor.
    k : int, default 100
        The number of neighbors [K]: a point's neighborhood is the point and
        its ``k`` nearest neighbors. With ``radius``, the cap on the number
        of neighbors taken from the ball (0: no cap).
    setting : {"default", "paper_precise", "paper_fast"}, default "default"
        The estimation (the named parameter ``setting`` of the C++
        function): ``"default"``, least squares where the neighborhood is
        one smooth sheet and the adaptive Hough transform elsewhere, which
        runs the fast setting first and ``planes`` and ``rotations`` where
        its confidence is low; ``"paper_precise"``, the Hough transform at
        every point with the Hoeffding bound of planes and 5 rotations;
        ``"paper_fast"``, with 300 planes and 2 rotations. ``planes`` and
        ``rotations``, where given, win over the setting's.
    radius : float, optional
        The radius of a spherical neighborhood [r]; default: none (``k``
        nearest neighbors). A ball with more than ``k`` other points keeps
        its ``k`` nearest (unless ``k`` is 0); one with fewer than 3 points
        is replaced by the ``k`` (at least 3) nearest neighbors.
    planes : int, optional
        The largest number of triples drawn per accumulator [T_R], from 1 to
        100 000 000; default: the Hoeffding bound of eq. 7 for the
        accumulator's number of bins (691 with 15 slices), 300 with
        ``setting="paper_fast"``.
    rotations : int, optional
        The number of randomly rotated accumulators [n_rot], 1 to 100 000;
        default: 5, 2 with ``setting="paper_fast"``.
    slices : int, default 15
        The number of slices of the sphere in the accumulator [n_phi], 1 to
        1000.
    confidence_interval : bool, default True
        Stop drawing triples as soon as the 95% confidence intervals of the
        two most voted bins are disjoint (eq. 10).
    sampling : {"points", "cubes", "unif"}, default "points"
        How triples are drawn: uniformly among the neighbors [RRHT_Points],
        or spatially uniformly in the neighborhood ball [RRHT_Cubes,
        RRHT_Unif], which resists density variations at some cost in time.
        With the default setting, only "unif" changes anything.
    presampling : int, default 4
        The discretization of the ball for "cubes" (c^3 cubes) and "unif"
        (balls of radius r/c) [c], 1 to 32.
    aggregation : {"mean", "best", "cluster"}, default "cluster"
        How the normals of the rotated accumulators are combined [RRHT_m,
        RRHT_b, RRHT_c].
    cluster_angle : float, default 45.0
        The angle in degrees within which normals form a cluster
        [a_cluster], 0 to 180.
    seed : int, default 0
        The seed of the random draws, 0 to 2**32 - 1. Each point draws from
        its own stream, derived from the seed and its id (by default its
        row): the same input and seed give the same normals, bit for bit, as
        ``rrht_normals`` and ``CGAL::rrht_estimate_normals()``, whatever the
        number of threads.
    refit : bool, default False
        Refit each normal by least squares (beyond the paper): a quadric
        height field over its plane, fitted to the neighbors within 2.5
        noise deviations of it, replaces the RRHT normal where at most 5%
        of the neighbors lie outside that band, as on smooth surfaces, and
        two parallel planes where the neighborhood is the two sides of a
        thin part, but not near sharp features. The noise deviation is
        estimated from the point's neighbors. With any setting; costs a
        second pass.
    threads : int, optional
        The number of threads for this call, 1 to 1024; default: all cores.
    progress : bool, default False
        Show a progress bar (tqdm) on stderr.
    orient : {"consistent", "up"} or array_like of 3 numbers, optional
        Orient the normals once estimated, as :func:`orient_normals` does
        (beyond the paper); default: not oriented, the normals being then
        the same as without this parameter, bit for bit. ``"consistent"``:
        consistently from the points alone, out of closed surfaces, with 18
        neighbors, as ``rrht_normals --orient`` (call
        :func:`orient_normals` for another number); not with ``halo``,
        since a part of a cloud cannot be oriented consistently with the
        rest on its own. ``"up"`` or a direction (3 numbers, finite, not
        null): each normal is flipped where it points against the direction.
    viewpoint : array_like, shape (3,) or (N, 3), optional
        Orient the normals towards this viewpoint (a scanner's position), or
        each towards its own row (the position of the sensor that saw the
        point), as :func:`orient_normals` does; not with ``orient``.
    return_confidence : bool, default False
        Also return the confidence of each normal (beyond the paper; the
        named parameter ``confidence_map`` of the C++ function). With the
        default setting it takes extra time: the Hough transform then also
        votes where the quadric is kept.

    Returns
    -------
    normals : numpy.ndarray, shape (N, 3), float64
        Unit normals, not oriented unless ``orient`` or ``viewpoint`` is
        given (:func:`orient_normals` orients them afterwards); the zero
        vector where no plane can be formed (fewer than 3 distinct or only
        collinear neighbors, a non-finite point), which no orientation
        changes.
    confidence : numpy.ndarray, shape (N,), float64
        Only with ``return_confidence``: from 0 to 1, the share of all the
        planes drawn at the point, over the rotated accumulators, that voted
        for a most voted bin within ``cluster_angle`` of the returned normal;
        with the default setting, where the normal is kept
        without a vote, the share of 50 of its triples whose planes lie
        within twice a bin's solid angle of it. It drops near sharp features and where the normal is wrong, so a low
        value flags a normal to distrust; noise lowers it evenly over a
        cloud, so compare values within a cloud. 0 where the normal is zero.
    support : numpy.ndarray, shape (N,), float64
        Only with ``return_support``: the radius of the ball that holds
        every point the normal depends on. With the default setting, whose
        tests read the neighborhoods of the point's
        neighbors and of theirs, the largest distance to one of those
        points plus the radius of its neighborhood; with the paper's settings,
        the distance to the ``k``-th neighbor (or ``radius``), and with
        ``refit``, the largest distance to a neighbor plus that neighbor's
        own. 0 for a non-finite point. The arrays come
        in this order, as those of ``numpy.unique``: normals, then
        confidence and support if asked for.

    Other Parameters
    ----------------
    These are for parts of a cloud, as ``cgal_rrht.tiles`` processes it.
    ids : array_like of int, shape (N,), optional
        A stable id for each point, 0 to 2**64 - 1, distinct (the named
        parameter ``point_id_map`` of the C++ function); default: the row.
        It keys the point's random stream and orders its neighbors at the
        same distance. With the rows of a whole cloud as ids, a part of it
        gives each point whose support (``return_support``) it holds the
        same normal, bit for bit, as the whole cloud:
        ``cgal_rrht.tiles`` is built on it.
    halo : array_like, shape (M, 3), optional
        Points that are only neighbors of ``points`` (the named parameter
        ``neighbor_only_map`` of the C++ function), as the halo of a tile:
        they get no normal and cost no estimation (with ``refit``, only its
        first pass). The arrays returned have a row per point of
        ``points`` only.
    halo_ids : array_like of int, shape (M,), optional
        The ids of ``halo``, needed with ``ids``; without ``ids``, the
        rows that follow those of ``points``, N to N + M - 1.
    return_support : bool, default False
        Also return the support radius of each normal: the radius of the
        ball around the point that holds every point its normal depends on
        (the named parameter ``support_radius_map`` of the C++ function).
    least_squares_first : bool, optional
        Deprecated, replaced by ``setting``, kept for one release with a
        ``DeprecationWarning``: the least squares of the default setting,
        on or off whatever the setting.
    adaptive : bool, optional
        Deprecated as ``least_squares_first``: the adaptive Hough transform
        of the default setting, on or off whatever the setting.
    neighbors : array_like, optional
        The deprecated name of ``halo`` (``--neighbors`` is ``k`` on the
        command line), kept for one release with a ``DeprecationWarning``.
    neighbor_ids : array_like of int, optional
        The deprecated name of ``halo_ids``, kept as ``neighbors``.

    Raises
    ------
    TypeError
        If ``points`` or ``halo`` is an array of another dtype than
        float64 or float32, or ``ids`` or ``halo_ids`` is not an array of
        integers.
    ValueError
        If ``points`` is not of shape (N, 3) (``halo`` (M, 3)), ``ids``
        not of shape (N,) (``halo_ids`` (M,)) or negative, if only one
        of ``ids`` and ``halo_ids`` is given with ``halo``, if a
        parameter is out of its
        range (with the message of ``CGAL::rrht_estimate_normals()``), if
        ``setting``, ``sampling`` or ``aggregation`` is an unknown name, or if ``orient``
        or ``viewpoint`` is wrong (as in :func:`orient_normals`), both are
        given, or ``orient`` is ``"consistent"`` with ``halo``. All
        of this is checked before the estimation starts.
    KeyboardInterrupt
        On Ctrl-C, which stops the estimation within a fraction of a second
        (seen after the kd-tree of the cloud is built, which takes about a
        quarter of a second per million points).

    Notes
    -----
    The GIL is released during the estimation: other Python threads run
    meanwhile.

    Examples
    --------
    >>> import numpy as np, cgal_rrht
    >>> points = np.random.default_rng(0).random((1000, 3)) * [1, 1, 0]
    >>> normals = cgal_rrht.estimate_normals(points, k=30)
    >>> bool(np.allclose(np.abs(normals[:, 2]), 1))
    True
    >>> normals, confidence = cgal_rrht.estimate_normals(points, k=30, return_confidence=True)
    >>> bool(((confidence > 0) & (confidence <= 1)).all())
    True
    """
    halo, halo_ids = _renamed(("neighbors", neighbors), ("halo", halo)), \
        _renamed(("neighbor_ids", neighbor_ids), ("halo_ids", halo_ids))
    array = _points(points, "points", "N")
    extra = None if halo is None else _points(halo, "halo", "M")
    fast = _name(setting, SETTINGS, "setting") == "paper_fast"
    arguments = dict(
        k=k,
        radius=None if radius is None else float(radius),
        planes=planes if planes is not None else 300 if fast else None,
        rotations=rotations if rotations is not None else 2 if fast else 5,
        slices=slices,
        confidence_interval=bool(confidence_interval),
        sampling=str(sampling),
        presampling=presampling,
        aggregation=str(aggregation),
        cluster_angle=float(cluster_angle),
        seed=seed,
        least_squares_first=_from_setting(_deprecated("least_squares_first", least_squares_first), setting),
        adaptive=_from_setting(_deprecated("adaptive", adaptive), setting),
        refit=bool(refit),
        threads=threads,
        return_confidence=bool(return_confidence),
        return_support=bool(return_support),
    )
    id_array = None if ids is None else _ids(ids, len(array), "ids")
    if extra is not None and (ids is None) != (halo_ids is None):
        raise ValueError("give both ids and halo_ids, or neither")
    if extra is None and halo_ids is not None:
        raise ValueError("halo_ids without halo")
    if extra is not None and id_array is not None:
        id_array = np.concatenate([id_array, _ids(halo_ids, len(extra), "halo_ids")])
    # Checked now, not after a long estimation.
    orientation = _estimation_orientation(orient, viewpoint, len(array), arguments["threads"], extra is not None)
    if not progress:
        results = _core.estimate_normals(array, extra, id_array, progress=None, **arguments)
    else:
        try:
            from tqdm.auto import tqdm
        except ImportError as error:
            raise ImportError("progress=True needs tqdm (pip install tqdm; Debian: python3-tqdm)") from error

        with tqdm(total=len(array), unit="pt", desc="cgal_rrht", unit_scale=True) as bar:

            def advance(done: float) -> None:
                bar.update(int(done * len(array)) - bar.n)

            results = _core.estimate_normals(array, extra, id_array, progress=advance, **arguments)
            advance(1.0)
    if orientation is not None:
        _core.orient_normals(array, results[0], **orientation)  # the fresh output, in place
    return _results(results)


def orient_normals(
    points: npt.ArrayLike,
    normals: npt.ArrayLike,
    *,
    direction: Union[None, str, npt.ArrayLike] = None,
    viewpoint: Optional[npt.ArrayLike] = None,
    k: int = 18,
    threads: Optional[int] = None,
) -> npt.NDArray[np.float64]:
    """Orients normals towards a direction or viewpoints, or consistently from the points alone.

    Runs ``CGAL::rrht_orient_normals()`` (beyond the paper). Each normal
    keeps its line and gets a sign:

    - with ``direction``, it is flipped where it points against that
      direction (aerial surveys: ``"up"``);
    - with ``viewpoint``, where it points away from the viewpoint, or from
      the point's own sensor position (terrestrial scans);
    - with neither, the normals are oriented consistently from the points
      alone, out of the solid where the surface is closed.

    The consistent orientation joins the points into consistently oriented
    clusters on the graph of their ``k`` nearest neighbors, trusting the
    agreement of two normals on one smooth sheet and, across a sharp edge,
    the reflection criterion of Xie et al. (2003), which keeps it right
    across the edges that RRHT keeps sharp. Each cluster is then turned so
    that the flux of the position through it is positive (outward on a
    closed surface), and flipped where it lies inside an odd number of
    others (the walls of a cavity point into it). Separate objects are each
    oriented so; an open surface ends up oriented to one side, which one
    being the cloud's choice. The user manual (section "Orienting and
    reconstructing") says more, and what it cannot do.

    Parameters
    ----------
    points : array_like, shape (N, 3), float64 or float32
        The points. A C-contiguous float64 array is read in place.
    normals : array_like, shape (N, 3), float64 or float32
        Their normals, such as those of :func:`estimate_normals`; not
        changed. Their length does not matter.
    direction : "up" or array_like of 3 numbers, optional
        The direction the normals should point to, finite and not null;
        ``"up"`` is (0, 0, 1), as PDAL's ``always_up``.
    viewpoint : array_like, shape (3,) or (N, 3), optional
        The position the normals should point to, such as a scanner's: each
        normal ``n`` at a point ``p`` with ``n . (viewpoint - p) < 0`` is
        flipped, as by Open3D's ``orient_normals_towards_camera_location``
        and PCL's ``flipNormalTowardsViewpoint``. An (N, 3) array gives each
        point its own viewpoint, the position of the sensor that saw it (a
        row with a NaN or infinite coordinate leaves its normal as it is).
        Not with ``direction``.
    k : int, default 18
        The number of neighbors of the consistent orientation, at least 2;
        not used with ``direction`` or ``viewpoint``.
    threads : int, optional
        The number of threads for this call, 1 to 1024; default: all cores.

    Returns
    -------
    oriented : numpy.ndarray, shape (N, 3), float64
        A new array, in the order of the input: row i is ``normals[i]`` or
        ``-normals[i]``. Rows that cannot be oriented are ``normals[i]``
        unchanged: a point with a NaN or infinite coordinate, a zero normal
        or one with a NaN or infinite coordinate (``estimate_normals`` gives
        the zero vector where it finds no plane), a non-finite row of
        per-point viewpoints. A normal perpendicular to ``direction`` keeps
        its sign, and so does the normal of a point equal to its viewpoint.
        The consistent orientation orients the other points among
        themselves.

    Raises
    ------
    TypeError
        If ``points``, ``normals`` or an (N, 3) ``viewpoint`` is an array of
        another dtype than float64 or float32, or ``k`` or ``threads`` is not
        an integer.
    ValueError
        If ``points`` is not of shape (N, 3), ``normals`` not of its shape,
        ``viewpoint`` neither (3,) nor (N, 3), ``direction`` neither "up"
        nor 3 numbers, if both ``direction`` and ``viewpoint`` are given, if
        ``direction`` is null or not finite, a (3,) ``viewpoint`` not finite,
        or ``k`` below 2 without them (with the message of
        ``CGAL::rrht_orient_normals()``), or ``threads`` out of range.

    Notes
    -----
    The result depends only on the arguments: it is the same, bit for bit,
    for any ``threads``, and as ``CGAL::rrht_orient_normals()`` and
    ``rrht_normals --orient`` (``k`` = 18) give on the same points and
    normals. ``estimate_normals(points, orient=...)`` estimates and orients
    in one call. The GIL is released while it runs; a Ctrl-C is seen when it
    ends. Towards a direction or viewpoints, each point is oriented on its
    own, so a cloud can be oriented by parts (``cgal_rrht.tiles``); a
    consistent orientation needs the whole cloud.

    Examples
    --------
    >>> import numpy as np, cgal_rrht
    >>> points = np.random.default_rng(0).normal(size=(2000, 3))
    >>> points /= np.linalg.norm(points, axis=1, keepdims=True)  # a unit sphere
    >>> normals = cgal_rrht.estimate_normals(points, k=30)
    >>> outward = cgal_rrht.orient_normals(points, normals)
    >>> bool((np.sum(outward * points, axis=1) > 0).all())
    True
    >>> up = cgal_rrht.orient_normals(points, normals, direction="up")
    >>> bool((up[:, 2] >= 0).all())
    True
    >>> inward = cgal_rrht.orient_normals(points, normals, viewpoint=[0, 0, 0])
    >>> bool(np.array_equal(inward, -outward))
    True
    """
    array = _points(points, "points", "N")
    oriented = _points(normals, "normals", "N")
    if oriented.shape != array.shape:
        raise ValueError(f"normals must have the shape of points, {array.shape}, not {oriented.shape}")
    if np.may_share_memory(oriented, normals):
        oriented = oriented.copy()
    orientation = _orientation(direction, viewpoint, len(array))
    _core.orient_normals(array, oriented, k=k, threads=threads, **orientation)
    return oriented


def _orientation(direction: object, viewpoint: object, count: int, name: str = "direction",
                 valid: str = "'up' or three numbers") -> Dict[str, Any]:
    """The arguments ``direction``, ``viewpoint`` and ``viewpoints`` of ``_core.orient_normals()``.

    ``direction`` ("up" or 3 numbers, called ``name``, whose ``valid``
    values the messages list) and ``viewpoint`` (3 numbers, or an array
    (count, 3)) are checked for their form; whether
    their values are finite and not null, and that only one is given, the
    C++ side checks, with its message.
    """
    arguments: Dict[str, Any] = dict(direction=None, viewpoint=None, viewpoints=None)
    if direction is not None:
        if isinstance(direction, str):
            if direction != "up":
                raise ValueError(f"unknown {name} {direction!r}: use {valid}")
            arguments["direction"] = (0.0, 0.0, 1.0)
        else:
            vector = np.asarray(direction, dtype=np.float64)
            if vector.shape != (3,):
                raise ValueError(f"{name} must be {valid}, not an array of shape {vector.shape}")
            arguments["direction"] = tuple(float(x) for x in vector)
    if viewpoint is not None:
        shape = np.shape(viewpoint)
        if shape == (3,):
            arguments["viewpoint"] = tuple(float(x) for x in np.asarray(viewpoint, dtype=np.float64))
        elif shape == (count, 3):
            arguments["viewpoints"] = _points(viewpoint, "viewpoint", "N")
        else:
            raise ValueError(f"viewpoint must be one point, of shape (3,), or one per point, of shape ({count}, 3), "
                             f"not {shape}")
    return arguments


def _renamed(old: Tuple[str, Any], new: Tuple[str, Any]) -> Any:
    """The value of the keyword ``new``, or of its deprecated name ``old``, with a DeprecationWarning."""
    if old[1] is None:
        return new[1]
    if new[1] is not None:
        raise TypeError(f"give {new[0]}= only: {old[0]}= is its deprecated name")
    warnings.warn(f"{old[0]}= is deprecated: it is now {new[0]}= ({old[0]} is k on the command line)",
                  DeprecationWarning, stacklevel=3)
    return old[1]


def _deprecated(name: str, value: Optional[bool]) -> Optional[bool]:
    """``value``, with a DeprecationWarning if given: ``setting`` replaces the switch ``name``."""
    if value is not None:
        warnings.warn(f"{name}= is deprecated and will be removed: use setting=", DeprecationWarning, stacklevel=3)
    return value


def _estimation_orientation(orient: object, viewpoint: object, count: int, threads: Optional[int],
                            with_halo: bool) -> Optional[Dict[str, Any]]:
    """The arguments of ``_core.orient_normals()`` for ``estimate_normals(orient=..., viewpoint=...)``, or None.

    Checked in full: ``_core.orient_normals()`` is called on no point, so
    that it checks the values as it will on the normals.
    """
    if orient is None and viewpoint is None:
        return None
    if orient is not None and viewpoint is not None:
        raise ValueError("give orient or viewpoint, not both: viewpoint alone orients the normals towards it")
    if isinstance(orient, str) and orient == "consistent":
        if with_halo:
            raise ValueError("orient='consistent' cannot be used with a halo: a part of a cloud would be oriented "
                             "consistently on its own, not with the rest; orient towards a direction or a viewpoint, "
                             "or orient the whole cloud")
        orientation: Dict[str, Any] = dict(direction=None, viewpoint=None, viewpoints=None)
    else:
        orientation = _orientation(orient, viewpoint, count, "orient", "'consistent', 'up' or three numbers")
    orientation.update(k=_CONSISTENT_K, threads=threads)
    empty = np.empty((0, 3))
    _core.orient_normals(empty, np.empty((0, 3)),
                         **dict(orientation, viewpoints=None if orientation["viewpoints"] is None else empty))
    return orientation


def _results(results: tuple) -> Union[npt.NDArray[np.float64], Tuple[npt.NDArray[np.float64], ...]]:
    """The normals alone, or in a tuple with the confidences and supports asked for."""
    asked = tuple(array for array in results if array is not None)
    return asked[0] if len(asked) == 1 else asked


def _points(points: npt.ArrayLike, name: str, rows: str) -> npt.NDArray[np.float64]:
    """``points`` as a C-contiguous float64 array (rows, 3), without a copy when it is one."""
    if isinstance(points, np.ndarray):
        if points.dtype not in (np.float64, np.float32):
            raise TypeError(
                f"{name} must be float64 or float32, not {points.dtype}: convert them with {name}.astype(np.float64)"
            )
        array = np.ascontiguousarray(points, dtype=np.float64)
    else:
        array = np.asarray(points, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"{name} must have the shape ({rows}, 3), not {array.shape}")
    return array


def _ids(ids: npt.ArrayLike, count: int, name: str) -> npt.NDArray[np.uint64]:
    """``ids`` as a C-contiguous uint64 array of ``count`` ids, or a TypeError or ValueError."""
    array = np.asarray(ids)
    if array.dtype.kind not in "ui":
        raise TypeError(f"{name} must be integers, not {array.dtype}")
    if array.shape != (count,):
        raise ValueError(f"{name} must have the shape ({count},), one per point, not {array.shape}")
    if array.dtype.kind == "i" and count and array.min() < 0:
        raise ValueError(f"{name} must be non-negative")
    return np.ascontiguousarray(array, dtype=np.uint64)


def _from_setting(flag: Optional[bool], setting: object) -> bool:
    """``least_squares_first`` or ``adaptive``: as given, or, if None, on in the default setting only."""
    return setting == "default" if flag is None else bool(flag)


def _name(value: object, valid: tuple, name: str) -> str:
    """``value`` if it is one of the ``valid`` names, or a ValueError listing them."""
    if value not in valid:
        raise ValueError(f"unknown {name} {value!r}: use one of {', '.join(map(repr, valid))}")
    return str(value)
