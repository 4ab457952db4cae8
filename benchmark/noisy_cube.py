#!/usr/bin/env python3
"""Writes a noisy cube for measurements of the command-line tool
rrht_normals: N points uniform on the faces of
[-1, 1]^3 (seed 1), with Gaussian noise of 0.2% of the diagonal, as .xyz.

    /usr/bin/python3 benchmark/noisy_cube.py cube100k.xyz [N]
"""
import sys

import numpy as np


def noisy_cube(n, seed=1, noise=0.002):
    rng = np.random.default_rng(seed)
    face = rng.integers(0, 6, n)
    uv = rng.uniform(-1, 1, (n, 2))
    axis, sign = face // 2, np.where(face % 2 == 0, -1.0, 1.0)
    points = np.empty((n, 3))
    for i in range(n):
        others = [j for j in range(3) if j != axis[i]]
        points[i, axis[i]] = sign[i]
        points[i, others] = uv[i]
    return points + rng.normal(0, noise * 2 * np.sqrt(3), points.shape)


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    np.savetxt(sys.argv[1], noisy_cube(int(sys.argv[2]) if len(sys.argv) == 3 else 100000), fmt="%.9g")
