#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python call's overhead over the C++ call, on the same cloud.

    /usr/bin/python3 benchmark/python_overhead.py [--points 1000000] [--rounds 5] [--threads 2]
        [--cli build/release/examples/rrht_normals] [--out benchmark/results/python]

The cloud is the noisy cube of benchmark/noisy_cube.py. The C++ call is
CGAL::rrht_estimate_normals() in rrht_normals, timed by the tool itself (the
call only, without reading or writing files); the Python call is
cgal_rrht.estimate_normals() on a NumPy array, timed around the call in a
fresh interpreter. Each round runs both once per setting, each in a process
of its own, and a ratio is the median of the ratios round by round (as the
targets experiment does), so that a drift of the machine's speed weighs on
both. The first round also checks that both give the same normals, bit for
bit. Both calls ask for the confidences in the last setting; what the
confidences cost is the C++ call's time with them over its time without, in
the same round. cgal_rrht must be importable by this interpreter (pip
install, or PYTHONPATH=build/release/python).
"""

import argparse
import json
import csv
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from noisy_cube import noisy_cube  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

# name, Python keyword arguments, rrht_normals flags
SETTINGS = [
    ("the default (k = 100)", {}, []),
    ("the default, T_R = 300, n_rot = 2", {"planes": 300, "rotations": 2}, ["--planes", "300", "--rotations", "2"]),
    ("the default with the confidences", {"return_confidence": True}, ["--confidence"]),
]
WITHOUT_CONFIDENCES, WITH_CONFIDENCES = SETTINGS[0][0], SETTINGS[2][0]
TARGET_OVERHEAD, TARGET_CONFIDENCE_COST = 1.05, 1.05

PYTHON_CALL = """
import sys, time, json
import numpy as np
import cgal_rrht
points = np.load(sys.argv[1])
start = time.perf_counter()
result = cgal_rrht.estimate_normals(points, threads=int(sys.argv[2]), **json.loads(sys.argv[3]))
print(time.perf_counter() - start)
if len(sys.argv) > 4:
    # the normals, then the confidences as a 4th column if asked for
    np.save(sys.argv[4], np.column_stack(result) if isinstance(result, tuple) else result)
"""


def time_cli(cli, xyz, threads, flags, output):
    run = subprocess.run([cli, xyz, output, "--threads", str(threads), "--precision", "17", "-q", *flags],
                         capture_output=True, text=True, check=True)
    return float(re.search(r"points, ([\d.]+) s", run.stdout).group(1))


def time_python(npy, threads, kwargs, output=None):
    command = [sys.executable, "-c", PYTHON_CALL, npy, str(threads), json.dumps(kwargs)] + ([output] if output else [])
    return float(subprocess.run(command, capture_output=True, text=True, check=True).stdout)


def ratio_cells(ratios, target):
    """The cells of a ratio: the median of the round-by-round ratios (min-max), and whether it meets the target."""
    ratio = statistics.median(ratios)
    return f"{ratio:.3f} ({min(ratios):.3f}-{max(ratios):.3f}) | {'yes' if ratio <= target else 'no'}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "examples" / "rrht_normals"))
    parser.add_argument("--out", type=Path, default=ROOT / "benchmark" / "results" / "python")
    args = parser.parse_args()

    import cgal_rrht  # fail early, with Python's message, if it is not installed

    # The commit the results are of: taken before they are written, which
    # would mark it dirty.
    commit = subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    with tempfile.TemporaryDirectory() as scratch:
        points = noisy_cube(args.points)
        xyz, npy = os.path.join(scratch, "cloud.xyz"), os.path.join(scratch, "cloud.npy")
        np.savetxt(xyz, points, fmt="%.17g")
        np.save(npy, points)
        rows = []
        # Round by round, every setting in turn: a round's settings run back
        # to back, so that the ratios between them pair neighboring runs.
        for round_ in range(args.rounds):
            for name, kwargs, flags in SETTINGS:
                check = round_ == 0
                cli_output = os.path.join(scratch, "cli.xyz")
                python_output = os.path.join(scratch, "python.npy") if check else None
                cpp = time_cli(args.cli, xyz, args.threads, flags, cli_output)
                python = time_python(npy, args.threads, kwargs, python_output)
                if check:
                    written = np.loadtxt(cli_output)
                    same = np.array_equal(written[:, :3], points) and np.array_equal(written[:, 3:],
                                                                                     np.load(python_output))
                    if not same:
                        sys.exit(f"different normals from rrht_normals and cgal_rrht ({name})")
                print(f"{name}, round {round_ + 1}: C++ {cpp:.3f} s, Python {python:.3f} s, ratio {python / cpp:.4f}",
                      flush=True)
                rows.append({"setting": name, "round": round_ + 1, "cpp_s": cpp, "python_s": python})

    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "python_overhead.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["setting", "round", "cpp_s", "python_s"])
        writer.writeheader()
        writer.writerows(rows)
    command = "/usr/bin/python3 benchmark/python_overhead.py" + "".join(
        f" --{k} {v}" for k, v in (("points", args.points), ("rounds", args.rounds), ("threads", args.threads)))
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")),
               platform.processor())
    lines = [
        "# The Python call against the C++ call",
        "",
        f"Command: `{command}` at commit {commit}, {datetime.now(timezone.utc):%Y-%m-%d %H:%M} UTC, "
        f"on {cpu} ({os.cpu_count()} cores), Python {platform.python_version()}, NumPy {np.__version__}.",
        "",
        f"{args.points} points of the noisy cube (`benchmark/noisy_cube.py`), {args.threads} threads, "
        f"{args.rounds} rounds. C++: `CGAL::rrht_estimate_normals()` in `rrht_normals`, as the tool times it; "
        "Python: `cgal_rrht.estimate_normals()` on a float64 array, timed around the call. "
        "Both gave the same normals (and confidences), bit for bit (checked in the first round). A ratio is "
        f"the median of the round-by-round ratios (min-max in brackets); the target is at most {TARGET_OVERHEAD}.",
        "",
        "| setting | C++ median (s) | Python median (s) | Python / C++ | target met |",
        "|---|---|---|---|---|",
    ]
    for name, _, _ in SETTINGS:
        mine = [r for r in rows if r["setting"] == name]
        ratios = [r["python_s"] / r["cpp_s"] for r in mine]
        lines.append(f"| {name} | {statistics.median(r['cpp_s'] for r in mine):.3f} | "
                     f"{statistics.median(r['python_s'] for r in mine):.3f} | {ratio_cells(ratios, TARGET_OVERHEAD)} |")
    # What the confidences cost: the same language, the same round.
    without = {r["round"]: r for r in rows if r["setting"] == WITHOUT_CONFIDENCES}
    costs = {language: [r[key] / without[r["round"]][key] for r in rows if r["setting"] == WITH_CONFIDENCES]
             for language, key in (("C++", "cpp_s"), ("Python", "python_s"))}
    lines += ["", f"What the confidences cost: each call's time with them over its time without, in the same round "
              f"(target: at most {TARGET_CONFIDENCE_COST}).", "", "| call | with ÷ without | target met |", "|---|---|---|"]
    for language, ratios in costs.items():
        lines.append(f"| {language} | {ratio_cells(ratios, TARGET_CONFIDENCE_COST)} |")
    (args.out / "README.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
