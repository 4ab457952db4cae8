# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Scale of cgal_rrht.tiles on this machine: time, points per second and the
peak memory of every Dask worker against the number of points, and the
throughput of the tiled run against the in-memory run.

    python3 benchmark/tiles_scale.py OUT_FOLDER [--sizes 1e6 2e6 ...] [--compare 2e6]
                                                [--work DIR] [--planes N --rotations N]

The cloud is synthetic: noisy boxes of several heights side by side on a
noisy ground (a city block of CAD parts), 8000 points per unit of area, so
that the area grows with the number of points. It is written straight into
square tiles of 8 x 8 (about 512k points each, .npy), tile by tile, so that no
process ever holds the whole cloud. Each size runs on a fresh LocalCluster of
2 worker processes with 1 thread each; the peak memory of a worker is its
process's peak resident set (getrusage), read at the end of the run.
Writes OUT_FOLDER/tiles_scale.csv, tiles_scale.txt and tiles_scale.png.
"""

from __future__ import annotations

import argparse
import csv
import math
import resource
import shutil
import sys
import time
from pathlib import Path

import numpy as np

DENSITY = 8000.0  # points per unit of area
TILE = 8.0        # side of a tile, in units


def parts(n: int, lower: np.ndarray, side: float, seed: int) -> np.ndarray:
    """`n` noisy points in the square [lower, lower + side]^2: half on a ground, half on boxes, one per unit cell."""
    rng = np.random.default_rng(seed)
    points = np.column_stack([lower + rng.random((n, 2)) * side, np.zeros(n)])
    on_box = rng.random(n) < 0.5
    cell = np.floor(points[on_box, :2]).astype(np.int64)
    height = 0.3 + 0.1 * ((cell[:, 0] * 7 + cell[:, 1] * 3) % 5)
    local = rng.random((on_box.sum(), 3))
    face = rng.integers(0, 5, on_box.sum())
    axis = np.where(face < 4, face // 2, 2)
    local[np.arange(len(local)), axis] = np.where(face < 4, face % 2, 1.0)
    points[on_box] = np.column_stack([cell + 0.2 + 0.6 * local[:, :2], local[:, 2] * height])
    return points + rng.normal(0.0, 0.002, points.shape)


def write_tiles(n: int, folder: Path) -> int:
    """About `n` points over a square of area n / DENSITY, written tile by tile; returns the number written."""
    side = math.ceil(math.sqrt(n / DENSITY) / TILE) * TILE
    cells = int(side / TILE)
    # The square's side is a whole number of tiles: the density is kept, the
    # area (and n) rounded to whole tiles.
    per_tile = int(round(DENSITY * TILE * TILE * min(1.0, n / (DENSITY * side * side))))
    folder.mkdir(parents=True)
    count = 0
    for i in range(cells):
        for j in range(cells):
            if count >= n:
                return count
            m = min(per_tile, n - count)
            np.save(folder / f"tile_{i:04d}_{j:04d}.npy", parts(m, np.array([i, j]) * TILE, TILE, seed=i * 100003 + j))
            count += m
    return count


def peak_of_workers(client) -> list:
    return sorted(v * 1024 for v in client.run(lambda: resource.getrusage(resource.RUSAGE_SELF).ru_maxrss).values())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--sizes", type=float, nargs="*", default=[1e6, 2e6, 5e6, 1e7, 2e7, 5e7])
    parser.add_argument("--compare", type=float, default=2e6, help="the size of the in-memory comparison (0: none)")
    parser.add_argument("--work", default="/tmp/cgal_rrht_tiles_scale")
    parser.add_argument("--planes", type=int)
    parser.add_argument("--rotations", type=int, default=5)
    parser.add_argument("-k", type=int, default=100)
    args = parser.parse_args()

    import cgal_rrht
    from cgal_rrht import tiles
    from distributed import Client, LocalCluster

    out, work = Path(args.out), Path(args.work)
    out.mkdir(parents=True, exist_ok=True)
    options = dict(k=args.k, planes=args.planes, rotations=args.rotations)
    rows = []
    lines = [f"command: {' '.join(sys.argv)}", f"estimator: {options}", ""]

    if args.compare:
        shutil.rmtree(work, ignore_errors=True)
        n = write_tiles(int(args.compare), work / "tiles")
        started = time.perf_counter()
        cloud = np.concatenate([np.load(p) for p in tiles.list_tiles(work / "tiles")])
        normals = cgal_rrht.estimate_normals(cloud, threads=2, **options)
        np.save(work / "in_memory.npy", np.column_stack([cloud, normals]))
        in_memory = time.perf_counter() - started
        peak_in_memory = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                          silence_logs=50) as cluster, Client(cluster) as client:
            started = time.perf_counter()
            tiles.run(work / "tiles", work / "normals", scheduler=cluster.scheduler_address, progress=False, **options)
            tiled = time.perf_counter() - started
        same = all(np.array_equal(np.load(work / "normals" / p.name)[:, 3:6], normals[first : first + len(np.load(p, mmap_mode="r"))])
                   for p, first in zip(tiles.list_tiles(work / "tiles"),
                                       np.cumsum([0] + [len(np.load(p, mmap_mode="r")) for p in tiles.list_tiles(work / "tiles")])))
        lines += [f"{n} points, in memory (read the tiles, estimate with 2 threads, write one .npy): {in_memory:.1f} s, "
                  f"{n / in_memory:.0f} points/s, peak {peak_in_memory / 2**30:.2f} GiB",
                  f"{n} points, tiled (2 workers x 1 thread, the LocalCluster's start included): {tiled:.1f} s, "
                  f"{n / tiled:.0f} points/s: {in_memory / tiled:.3f} x the in-memory throughput; "
                  f"normals identical to the in-memory run: {same}", ""]
        print("\n".join(lines[-3:]), flush=True)
        del cloud, normals

    for size in args.sizes:
        shutil.rmtree(work, ignore_errors=True)
        n = write_tiles(int(size), work / "tiles")
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                          silence_logs=50) as cluster, Client(cluster) as client:
            started = time.perf_counter()
            summary = tiles.run(work / "tiles", work / "normals", scheduler=cluster.scheduler_address, progress=False,
                                **options)
            seconds = time.perf_counter() - started
            peaks = peak_of_workers(client)
        row = dict(points=n, tiles=summary["tiles"], seconds=round(seconds, 2), points_per_second=round(n / seconds),
                   halo=summary["halo"], estimated=summary["estimated"], rounds=summary["rounds"],
                   peak_worker_gib=round(max(peaks) / 2**30, 3))
        rows.append(row)
        print(row, flush=True)
    shutil.rmtree(work, ignore_errors=True)

    if rows:
        with open(out / "tiles_scale.csv", "w", newline="") as stream:
            writer = csv.DictWriter(stream, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
        lines.append("| points | tiles | seconds | points/s | halo points | points estimated | second rounds "
                     "| peak of a worker (GiB) |")
        lines.append("|---|---|---|---|---|---|---|---|")
        lines += [f"| {r['points']} | {r['tiles']} | {r['seconds']} | {r['points_per_second']} | {r['halo']} | "
                  f"{r['estimated']} | {r['rounds']} | {r['peak_worker_gib']} |" for r in rows]
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        x = np.array([r["points"] for r in rows]) / 1e6
        y = np.array([r["seconds"] for r in rows])
        slope = float(np.sum(x * y) / np.sum(x * x))
        figure, axis = plt.subplots(figsize=(6, 4))
        axis.plot(x, y, "o-", label="cgal_rrht.tiles, 2 workers")
        axis.plot(x, slope * x, "--", label=f"{slope:.1f} s per million points")
        axis.set_xlabel("points (millions)")
        axis.set_ylabel("wall time (s)")
        axis.set_title("Tiled normal estimation on 2 cores")
        axis.legend()
        figure.tight_layout()
        figure.savefig(out / "tiles_scale.png", dpi=100)
    (out / "tiles_scale.txt").write_text("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
