#!/usr/bin/python3
# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Pictures of the Poisson surfaces of poisson_benchmark: for each shape and
noise of poisson.csv, the surfaces from the four sets of normals side by
side, shaded by their face normals, and a link to the picture under the
shape's table in poisson.md.

    poisson_pictures.py RESULTS_DIR SCRATCH_DIR

RESULTS_DIR holds poisson.csv and poisson.md, SCRATCH_DIR the surfaces
(SHAPE_noiseN_NORMALS.off). Needs Debian's python3-matplotlib and
python3-numpy.
"""

import argparse
import csv
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

NORMALS = [("rrht_orient", "RRHT + rrht_orient_normals"),
           ("rrht_exact_signs", "RRHT, the exact signs"),
           ("jet_mst", "jet fitting + mst_orient_normals"),
           ("exact", "exact normals")]
LIGHT = np.array([0.4, -0.5, 0.77])


def read_off(path):
    """The vertices and the triangles of an OFF file (polygons fan-split)."""
    with open(path) as f:
        words = f.read().split()
    if not words or words[0] != "OFF":
        raise ValueError("%s: not an OFF file" % path)
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = np.array(words[at:at + 3 * nv], dtype=float).reshape(nv, 3)
    at += 3 * nv
    triangles = []
    for _ in range(nf):
        n = int(words[at])
        face = [int(w) for w in words[at + 1:at + 1 + n]]
        at += 1 + n
        triangles += [(face[0], face[i], face[i + 1]) for i in range(1, n - 1)]
    return vertices, np.array(triangles, dtype=int).reshape(-1, 3)


def draw(ax, vertices, triangles, title):
    corners = vertices[triangles]
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    normals = normals / np.where(lengths > 0, lengths, 1)[:, None]
    # Two-sided shading: a face seen from behind (a flipped sheet) is darker
    # and tinted, so that inside-out parts show.
    light = normals @ (LIGHT / np.linalg.norm(LIGHT))
    front = np.clip(light, 0, 1)
    colors = np.where((light >= 0)[:, None],
                      np.outer(0.2 + 0.8 * front, [0.85, 0.87, 0.95]),
                      np.outer(0.25 + 0.5 * np.clip(-light, 0, 1), [0.9, 0.45, 0.35]))
    ax.add_collection3d(Poly3DCollection(corners, facecolors=np.clip(colors, 0, 1), edgecolors="none", linewidths=0,
                                         antialiased=False))
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_zlim(low[2], high[2])
    ax.set_box_aspect(np.maximum(high - low, 1e-9 * np.max(high - low)), zoom=1.3)
    ax.view_init(elev=25, azim=-60)
    ax.set_axis_off()
    ax.set_title(title, fontsize=9)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("scratch")
    args = parser.parse_args()
    with open(os.path.join(args.results, "poisson.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    cases = []
    for r in rows:
        if (r["shape"], r["noise_percent"]) not in cases:
            cases.append((r["shape"], r["noise_percent"]))
    md_path = os.path.join(args.results, "poisson.md")
    with open(md_path) as f:
        md = f.read()
    for shape, noise in cases:
        fig = plt.figure(figsize=(4 * len(NORMALS), 4.2))
        for i, (normals, label) in enumerate(NORMALS):
            ax = fig.add_subplot(1, len(NORMALS), i + 1, projection="3d")
            path = os.path.join(args.scratch, "%s_noise%s_%s.off" % (shape, noise, normals))
            if os.path.exists(path):
                vertices, triangles = read_off(path)
                draw(ax, vertices, triangles, label)
            else:
                ax.set_axis_off()
                ax.set_title("%s: no surface" % label, fontsize=9)
        name = "poisson_%s_noise%s.png" % (shape, noise)
        fig.tight_layout()
        fig.savefig(os.path.join(args.results, name), dpi=110)
        plt.close(fig)
        # Under the shape's heading, "## SHAPE, N points, noise X%".
        heading = re.compile(r"^## %s, \d+ points, noise %s%%\n" % (re.escape(shape), re.escape(noise)), re.M)
        match = heading.search(md)
        if match and name not in md:
            md = md[:match.end()] + "\n![%s](%s)\n" % (name, name) + md[match.end():]
        print("wrote %s" % name)
    with open(md_path, "w") as f:
        f.write(md)


if __name__ == "__main__":
    main()
