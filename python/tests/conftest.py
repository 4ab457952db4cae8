# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared clouds with exact normals, and the command-line tool to compare with."""

import inspect
import os
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "examples" / "data"
#: Marks a test of the switches that ``setting=`` replaces, which warn for one release.
DEPRECATED = pytest.mark.filterwarnings("ignore:.* is deprecated and will be removed:DeprecationWarning")


def angle_errors_deg(normals, truth):
    """Unoriented angle between each normal and its truth, in degrees (90 for a zero normal)."""
    cosines = np.abs(np.sum(normals * truth, axis=1)) / np.maximum(
        np.linalg.norm(normals, axis=1) * np.linalg.norm(truth, axis=1), 1e-300
    )
    return np.degrees(np.arccos(np.clip(cosines, 0.0, 1.0)))


def assert_documented(function, positional):
    """Every parameter of ``function`` has its numpydoc entry with its default
    (quoted either way), the first are ``positional`` and the others keyword-only."""
    doc = function.__doc__
    signature = inspect.signature(function)
    for name, parameter in signature.parameters.items():
        assert f"\n    {name} : " in doc, name
        if parameter.default is not inspect.Parameter.empty and parameter.default is not None:
            default = f"default {parameter.default!r}"
            assert default in doc or default.replace("'", '"') in doc, name
    parameters = list(signature.parameters.values())
    assert [p.name for p in parameters[:len(positional)]] == list(positional)
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in parameters[len(positional):])
    return doc


def noisy_cube(n, noise=0.002, seed=1):
    """`n` points drawn uniformly on the unit cube's faces, with Gaussian noise of
    `noise` times the diagonal, and the normal of each point's face."""
    rng = np.random.default_rng(seed)
    face = rng.integers(0, 6, n)
    axis, side = face // 2, (face % 2).astype(float)
    points = rng.random((n, 3))
    points[np.arange(n), axis] = side
    truth = np.zeros((n, 3))
    truth[np.arange(n), axis] = 1.0
    points += rng.normal(0.0, noise * np.sqrt(3.0), (n, 3))
    return points, truth


@pytest.fixture(scope="session")
def fandisk():
    """The bundled 20k points on the fandisk CAD part and their exact normals."""
    data = np.loadtxt(DATA / "fandisk_20k_truth.xyz")
    return np.ascontiguousarray(data[:, :3]), np.ascontiguousarray(data[:, 3:])


@pytest.fixture(scope="session")
def cli():
    """The rrht_normals of a build: $CGAL_RRHT_CLI, else build/release's."""
    path = os.environ.get("CGAL_RRHT_CLI") or str(ROOT / "build" / "release" / "examples" / "rrht_normals")
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        pytest.skip(f"rrht_normals not found at {path} (build the examples, or set CGAL_RRHT_CLI)")
    return path


@pytest.fixture(scope="module")
def cluster():
    """A Dask LocalCluster of two worker processes, for cgal_rrht.tiles."""
    import distributed

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=50) as local:
        yield local


@pytest.fixture
def cli_env():
    """The environment of a child Python that imports the same cgal_rrht."""
    import cgal_rrht

    env = dict(os.environ)
    package = os.path.dirname(os.path.dirname(cgal_rrht.__file__))
    env["PYTHONPATH"] = package + os.pathsep + env.get("PYTHONPATH", "")
    return env
