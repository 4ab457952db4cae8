# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Open3D interoperability: RRHT normals for an ``open3d.geometry.PointCloud``, and their orientation."""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

import cgal_rrht

__all__ = ["estimate_normals", "orient_normals"]


def _neighborhood(search_param: Any) -> dict:
    """The ``k`` and ``radius`` of :func:`cgal_rrht.estimate_normals` that
    take the points that Open3D's ``search_param`` finds: Open3D counts the
    point itself among its ``knn`` or ``max_nn``, RRHT's ``k`` does not."""
    import open3d as o3d

    def neighbors(count: int) -> int:
        if count < 3:
            raise ValueError(f"search_param finds at most {count} points: a plane needs 3")
        return count - 1

    if isinstance(search_param, o3d.geometry.KDTreeSearchParamKNN):
        return {"k": neighbors(search_param.knn)}
    if isinstance(search_param, o3d.geometry.KDTreeSearchParamRadius):
        return {"k": 0, "radius": search_param.radius}  # the whole ball
    if isinstance(search_param, o3d.geometry.KDTreeSearchParamHybrid):
        return {"k": neighbors(search_param.max_nn), "radius": search_param.radius}  # the nearest in the ball
    raise TypeError("search_param must be an open3d.geometry.KDTreeSearchParamKNN, KDTreeSearchParamRadius or "
                    f"KDTreeSearchParamHybrid, not {type(search_param).__name__}")


def estimate_normals(pcd: Any, search_param: Any = None, **kwargs: Any) -> Any:
    """Fills ``pcd.normals`` of an ``open3d.geometry.PointCloud`` with RRHT normals.

    Like ``pcd.estimate_normals()``, but keeps sharp features. The
    neighborhoods are given as to Open3D, by ``search_param``: an
    ``open3d.geometry.KDTreeSearchParamKNN(knn)`` (the ``knn`` nearest
    points, the point itself included), ``KDTreeSearchParamRadius(radius)``
    (every point within ``radius``) or
    ``KDTreeSearchParamHybrid(radius, max_nn)`` (at most the ``max_nn``
    nearest within ``radius``), the same points as Open3D takes; or as to
    :func:`cgal_rrht.estimate_normals`, by ``k`` and ``radius``. Without
    either, the point and its 100 nearest neighbors (Open3D's default is
    30 points: RRHT votes better with more). The other keyword arguments are those of
    :func:`cgal_rrht.estimate_normals` (``sampling``, ``seed``...). The
    normals are unit and not oriented, unless ``orient`` or ``viewpoint``
    is given:

    - ``orient="consistent"`` replaces a call to
      ``pcd.orient_normals_consistent_tangent_plane(k)`` after the
      estimation: the normals are oriented consistently, out of closed
      surfaces, with 18 neighbors. Open3D propagates the sign along a
      spanning tree by the dot product of neighboring normals (Hoppe et al.
      1992), which is noise across the sharp edges that RRHT keeps, so that
      one wrong edge of the tree flips a whole face, and it leaves the
      choice of outside to chance; this orientation is sure across sharp
      edges and points out of the solid (see :func:`cgal_rrht.orient_normals`).
    - ``orient="up"`` or a direction (3 numbers) replaces
      ``pcd.orient_normals_to_align_with_direction(direction)``;
    - ``viewpoint=`` (one point, or one per point) replaces
      ``pcd.orient_normals_towards_camera_location(camera_location)``.

    Returns ``pcd``, or ``(pcd, confidence)`` with ``return_confidence=True``
    (the confidence of each normal, a NumPy array of shape (N,)).

    Raises
    ------
    TypeError
        If ``pcd`` is not an ``open3d.geometry.PointCloud``, if
        ``search_param`` is not one of Open3D's three search parameters, or
        if it is given with ``k`` or ``radius``.
    ValueError
        If ``search_param`` finds fewer than 3 points, or as
        :func:`cgal_rrht.estimate_normals`.

    Examples
    --------
    ::

        import open3d as o3d, cgal_rrht.open3d

        pcd = o3d.io.read_point_cloud("examples/data/fandisk_20k.ply")
        cgal_rrht.open3d.estimate_normals(pcd, search_param=o3d.geometry.KDTreeSearchParamKNN(50),
                                          orient="consistent")
        mesh, _ = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=8)
    """
    import open3d as o3d

    if not isinstance(pcd, o3d.geometry.PointCloud):
        raise TypeError(f"pcd must be an open3d.geometry.PointCloud, not {type(pcd).__name__}")
    if search_param is not None:
        given = [name for name in ("k", "radius") if name in kwargs]
        if given:
            raise TypeError(f"give the neighborhood either by search_param or by {' and '.join(given)}, not both")
        kwargs.update(_neighborhood(search_param))
    # Open3D's points are a contiguous float64 (N, 3) buffer, read in place.
    result = cgal_rrht.estimate_normals(np.asarray(pcd.points), **kwargs)
    normals, confidence = result if kwargs.get("return_confidence") else (result, None)
    pcd.normals = o3d.utility.Vector3dVector(normals)
    return pcd if confidence is None else (pcd, confidence)


def orient_normals(pcd: Any, *, direction: Any = None, viewpoint: Any = None, k: int = 18,
                   threads: Optional[int] = None) -> Any:
    """Orients the normals of an ``open3d.geometry.PointCloud`` in place, as :func:`cgal_rrht.orient_normals`.

    For normals already in ``pcd.normals`` (those of
    :func:`estimate_normals`, Open3D's, or a file's). With neither
    ``direction`` nor ``viewpoint``, it replaces
    ``pcd.orient_normals_consistent_tangent_plane(k)``: the normals are
    oriented consistently, out of closed surfaces, and surely across sharp
    edges, where Open3D's propagation by the dot product of neighboring
    normals can flip whole faces. ``direction`` (``"up"`` or 3 numbers)
    replaces ``pcd.orient_normals_to_align_with_direction()`` and
    ``viewpoint`` (one point, or an (N, 3) array of one per point)
    ``pcd.orient_normals_towards_camera_location()``, with the same signs,
    but for zero normals, which Open3D replaces by the direction (or the
    unit vector towards the camera) and this leaves as they are. The
    arguments are those of :func:`cgal_rrht.orient_normals`, whose
    documentation says what each does and which normals are left as they
    are. Returns ``pcd``.

    Raises
    ------
    TypeError
        If ``pcd`` is not an ``open3d.geometry.PointCloud``.
    ValueError
        If ``pcd`` has points but no normals, or as :func:`cgal_rrht.orient_normals`.
    """
    import open3d as o3d

    if not isinstance(pcd, o3d.geometry.PointCloud):
        raise TypeError(f"pcd must be an open3d.geometry.PointCloud, not {type(pcd).__name__}")
    if len(pcd.points) and not pcd.has_normals():
        raise ValueError("pcd has no normals: estimate them first, e.g. with cgal_rrht.open3d.estimate_normals(pcd)")
    oriented = cgal_rrht.orient_normals(np.asarray(pcd.points), np.asarray(pcd.normals).reshape(-1, 3),
                                        direction=direction, viewpoint=viewpoint, k=k, threads=threads)
    pcd.normals = o3d.utility.Vector3dVector(oriented)
    return pcd
