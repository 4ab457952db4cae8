# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Open3D interoperability: RRHT normals for an ``open3d.geometry.PointCloud``."""

from __future__ import annotations

from typing import Any

import numpy as np

import cgal_rrht

__all__ = ["estimate_normals"]


def estimate_normals(pcd: Any, **kwargs: Any) -> Any:
    """Fills ``pcd.normals`` of an ``open3d.geometry.PointCloud`` with RRHT normals.

    Like ``pcd.estimate_normals()``, but keeps sharp features. The keyword
    arguments are those of :func:`cgal_rrht.estimate_normals` (``k``,
    ``radius``, ``sampling``, ``seed``...). The normals are unit and not
    oriented: ``pcd.orient_normals_consistent_tangent_plane(k)`` orients
    them. Returns ``pcd``, or ``(pcd, confidence)`` with
    ``return_confidence=True`` (the confidence of each normal, a NumPy
    array of shape (N,)).

    Raises
    ------
    TypeError
        If ``pcd`` is not an ``open3d.geometry.PointCloud``.
    """
    import open3d as o3d

    if not isinstance(pcd, o3d.geometry.PointCloud):
        raise TypeError(f"pcd must be an open3d.geometry.PointCloud, not {type(pcd).__name__}")
    # Open3D's points are a contiguous float64 (N, 3) buffer, read in place.
    result = cgal_rrht.estimate_normals(np.asarray(pcd.points), **kwargs)
    normals, confidence = result if kwargs.get("return_confidence") else (result, None)
    pcd.normals = o3d.utility.Vector3dVector(normals)
    return pcd if confidence is None else (pcd, confidence)
