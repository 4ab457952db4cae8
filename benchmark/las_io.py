#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""rrht_normals on a LAS survey against the same points as binary PLY, and a
picture of the survey's normals.

    .venv/bin/python benchmark/las_io.py [--las ../shared/data/las/autzen_trim.las] [--copies 10]
        [--rounds 5] [--threads 2] [--cli build/release/examples/rrht_normals] [--out benchmark/results/las]

The survey, and a larger one made of ``--copies`` copies of it side by side
in x (its records, their X shifted), are written as LAS and as binary
little-endian PLY with double x, y, z: the coordinates that the LAS file
gives, so the same points. Each round runs ``rrht_normals --orient=up`` on
each file, in a process of its own: LAS in and out (the records kept, the
normals as extra bytes), PLY in and out (CGAL's reader and writer: x y z nx
ny nz). The time of reading and writing is the process's wall time less
the estimation and orientation time that the tool prints for the same run
(the process's start is in it for both formats); a ratio LAS / PLY is the
median of the ratios round by round, so that a drift of the machine's
speed weighs on both. The first round checks that both give the same
normals, bit for bit. The picture is of the survey's normals from LAS,
coloured by normal. cgal_rrht must be importable by this interpreter (the
README's virtual environment, or PYTHONPATH=BUILD/python of a build with
-DCGAL_RRHT_BUILD_PYTHON=ON): it reads the files.
"""

import argparse
import os
import platform
import re
import statistics
import struct
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

from cgal_rrht.point_files import PointFile, write_points

ROOT = Path(__file__).resolve().parents[1]
TARGET = 1.0  # reading and writing LAS costs no more than PLY


def copies_side_by_side(source: Path, copies: int, output: Path) -> None:
    """``copies`` copies of the LAS file ``source`` side by side in x: its
    header and records before the points, the records repeated with X
    shifted by the survey's width, the counts and bounds set."""
    data = source.read_bytes()
    minor, start, length = data[25], struct.unpack_from("<I", data, 96)[0], struct.unpack_from("<H", data, 105)[0]
    count = struct.unpack_from("<Q", data, 247)[0] if minor >= 4 else struct.unpack_from("<I", data, 107)[0]
    records = np.frombuffer(data, np.uint8, count * length, start).reshape(count, length)
    x = np.ascontiguousarray(records[:, :4]).view("<i4").ravel()
    width = int(x.max() - x.min()) + 1
    parts = []
    for copy in range(copies):
        part = records.copy()
        part[:, :4] = (x + copy * width).astype("<i4").view(np.uint8).reshape(count, 4)
        parts.append(part)
    head = bytearray(data[:start])
    if minor >= 4:
        struct.pack_into("<Q", head, 247, count * copies)
        head[255:375] = (np.frombuffer(data, "<u8", 15, 255) * copies).astype("<u8").tobytes()
    if data[104] < 6:
        struct.pack_into("<I", head, 107, count * copies)
        head[111:131] = (np.frombuffer(data, "<u4", 5, 111) * copies).astype("<u4").tobytes()
    max_x = struct.unpack_from("<d", data, 179)[0]
    struct.pack_into("<d", head, 179, max_x + (copies - 1) * width * struct.unpack_from("<d", data, 131)[0])
    output.write_bytes(bytes(head) + b"".join(part.tobytes() for part in parts))


def run(cli, source, output, threads):
    """The wall time of rrht_normals on ``source`` and the estimation's time it prints."""
    start = time.perf_counter()
    done = subprocess.run([str(cli), str(source), str(output), "--orient=up", "--threads", str(threads), "-q"],
                          capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    estimation = float(re.search(r"points, ([0-9.e+-]+) s,", done.stdout).group(1))
    return wall, estimation


def las_normals(path: Path) -> np.ndarray:
    points = PointFile(path)
    return np.stack([points.field(name) for name in ("NormalX", "NormalY", "NormalZ")], axis=1)


def picture(las: Path, png: Path, title: str) -> None:
    """The survey's points from above and from the side, each in the colour
    of its normal: (n + 1) / 2 as red, green, blue."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    points, normals = PointFile(las).read(), las_normals(las)
    colours = np.clip((normals + 1) / 2, 0, 1)
    xyz = points - points.min(axis=0)
    figure = plt.figure(figsize=(14, 5.6))
    top = figure.add_subplot(1, 2, 1)
    order = np.argsort(xyz[:, 2])  # the highest points drawn last, as seen from above
    top.scatter(xyz[order, 0], xyz[order, 1], c=colours[order], s=0.6, linewidths=0)
    top.set_aspect("equal")
    top.set_title("from above")
    top.set_xlabel("x (ft)")
    top.set_ylabel("y (ft)")
    side = figure.add_subplot(1, 2, 2, projection="3d")
    side.scatter(xyz[:, 0], xyz[:, 1], xyz[:, 2], c=colours, s=0.4, linewidths=0, depthshade=False)
    side.view_init(elev=28, azim=-62)
    side.set_box_aspect(np.ptp(xyz, axis=0) * [1, 1, 2], zoom=1.5)
    side.set_title("from the south-east, heights doubled")
    side.set_axis_off()
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(png, dpi=110)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--las", type=Path, default=ROOT.parent / "shared" / "data" / "las" / "autzen_trim.las")
    parser.add_argument("--copies", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--cli", type=Path, default=ROOT / "build" / "release" / "examples" / "rrht_normals")
    parser.add_argument("--out", type=Path, default=ROOT / "benchmark" / "results" / "las")
    args = parser.parse_args()
    if not args.las.is_file():
        sys.exit(f"{args.las}: not found (the survey of ../shared/data/las, or --las FILE)")
    commit = subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"], capture_output=True,
                            text=True).stdout.strip()
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory(prefix="las_io.") as scratch:
        scratch = Path(scratch)
        surveys = [("the survey", args.las)]
        if args.copies > 1:
            copies_side_by_side(args.las, args.copies, scratch / "copies.las")
            surveys.append((f"{args.copies} copies side by side", scratch / "copies.las"))
        for name, las in surveys:
            points = PointFile(las).read()
            ply = scratch / "points.ply"
            write_points(ply, [("x", points[:, 0]), ("y", points[:, 1]), ("z", points[:, 2])])
            ratios, times = [], {"las": [], "ply": []}
            for round_ in range(args.rounds):
                las_wall, las_estimation = run(args.cli, las, scratch / "out.las", args.threads)
                ply_wall, ply_estimation = run(args.cli, ply, scratch / "out.ply", args.threads)
                times["las"].append((las_wall, las_estimation))
                times["ply"].append((ply_wall, ply_estimation))
                ratios.append((las_wall - las_estimation) / (ply_wall - ply_estimation))
                if round_ == 0:
                    from_ply = PointFile(scratch / "out.ply").table()
                    if not np.array_equal(las_normals(scratch / "out.las"), from_ply[:, 3:6]):
                        sys.exit(f"{name}: the normals from LAS and from PLY differ")
            sizes = (las.stat().st_size, ply.stat().st_size, (scratch / "out.las").stat().st_size,
                     (scratch / "out.ply").stat().st_size)
            rows.append((name, len(points), times, ratios, sizes))
            if las == args.las:
                os.replace(scratch / "out.las", scratch / "survey_normals.las")
            print(name, len(points), "LAS / PLY reading and writing:", statistics.median(ratios), flush=True)
        picture(scratch / "survey_normals.las", args.out / "autzen_normals.png",
                f"{args.las.name}: {len(PointFile(args.las))} points, normals of "
                f"'rrht_normals {args.las.name} out.las --orient=up', coloured by normal")

    command = " ".join(([f"PYTHONPATH={os.environ['PYTHONPATH']}"] if os.environ.get("PYTHONPATH") else []) +
                       [sys.executable, "benchmark/las_io.py"] + sys.argv[1:])
    median = statistics.median
    lines = [
        "# LAS against binary PLY in `rrht_normals`",
        "",
        f"Command: `{command}` at commit {commit}, {datetime.now(timezone.utc):%Y-%m-%d %H:%M} UTC, on "
        f"{platform.processor() or platform.machine()} ({os.cpu_count()} cores), with `{args.las.name}` of "
        "`../shared/data/las` (PDAL's test data).",
        "",
        f"`rrht_normals FILE OUT --orient=up --threads {args.threads}` on the same points as LAS (in and out: the "
        "records kept, the normals as extra bytes) and as binary PLY of doubles (CGAL's reader and writer: x y z "
        "nx ny nz); both gave the same normals, bit for bit (checked in the first round). Reading and writing: "
        "the process's wall time less the estimation and orientation time that the tool prints (the process's "
        f"start is in both). Medians of {args.rounds} rounds; the ratio is the median of the ratios round by "
        f"round (min-max in brackets); the target is at most {TARGET:.2f}.",
        "",
        "| survey | points | LAS in, out (MB) | PLY in, out (MB) | LAS: wall, estimation (s) | PLY: wall, "
        "estimation (s) | reading and writing, LAS / PLY | target met |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for name, count, times, ratios, sizes in rows:
        las_wall, las_estimation = (median(t[i] for t in times["las"]) for i in (0, 1))
        ply_wall, ply_estimation = (median(t[i] for t in times["ply"]) for i in (0, 1))
        lines.append(
            f"| {name} | {count} | {sizes[0] / 1e6:.1f}, {sizes[2] / 1e6:.1f} | {sizes[1] / 1e6:.1f}, "
            f"{sizes[3] / 1e6:.1f} | {las_wall:.3f}, {las_estimation:.3f} | {ply_wall:.3f}, {ply_estimation:.3f} | "
            f"{median(ratios):.3f} ({min(ratios):.3f}-{max(ratios):.3f}) | "
            f"{'yes' if median(ratios) <= TARGET else 'no'} |")
    lines += ["", "![The normals of the survey, coloured by normal](autzen_normals.png)", ""]
    (args.out / "README.md").write_text("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
