# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The plots of benchmark/report.py (matplotlib) and its renderings of the error
per point (the paper's Fig. 8 and 11)."""

import math
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from report_tables import REFERENCE, TAU, fmt_time  # noqa: E402

COLORS = {"Points": "tab:blue", "Cubes": "tab:orange", "Unif": "tab:green", "jet_K80": "black",
          "jet_K18": "dimgray", "pca_K80": "tab:purple", "vcm": "tab:brown", "pcl_K80": "tab:pink",
          "open3d_K30": "tab:olive", "open3d_hybrid": "tab:cyan"}
STYLES = {"m": "--", "b": ":", "c": "-"}


def style(name):
    """Color by sampling, line style by aggregation as in the paper's plots."""
    if name.startswith("RRHT_"):
        parts = name.split("_")
        if len(parts) < 3:  # RRHT_default
            return dict(color="tab:red", linestyle="-", marker="o")
        return dict(color=COLORS.get(parts[1], "tab:red"), linestyle=STYLES.get(parts[2], "-"), marker="o")
    return dict(color=COLORS.get(name, "tab:gray"), linestyle="-.", marker="s")


def best_threads(rows):
    return max(r["threads"] for r in rows)


def series(rows, x, y, threads=None):
    """{estimator: [(x, y)]} over successful rows with the given thread count
    (sequential estimators have only 1)."""
    lines = defaultdict(list)
    for r in rows:
        if r["status"] != "ok":
            continue
        if threads is not None and r["threads"] != threads:
            has_other = any(o["estimator"] == r["estimator"] and o["threads"] == threads for o in rows)
            if has_other:
                continue
        lines[r["estimator"]].append((x(r), y(r)))
    return {k: sorted(set(v)) for k, v in lines.items()}


def plot_lines(ax, lines, label_suffix=""):
    for name, points in lines.items():
        xs, ys = zip(*points)
        ax.plot(xs, ys, label=name + label_suffix, markersize=3, **style(name))


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return os.path.basename(path)


def plot_time_vs_points(rows, out, name, through, title):
    """Time against the number of points, log-log, with the n log n line
    through the largest cloud of the estimator `through`."""
    t = best_threads(rows)
    fig, ax = plt.subplots(figsize=(7, 5))
    plot_lines(ax, series(rows, lambda r: r["points"], lambda r: r["median_s"], t))
    points = series(rows, lambda r: r["points"], lambda r: r["median_s"], t).get(through)
    if points and len(points) > 1:
        n0, t0 = points[-1]
        xs = [p[0] for p in points]
        ax.plot(xs, [t0 * n * math.log(n) / (n0 * math.log(n0)) for n in xs], color="gray", linewidth=0.8,
                label="n log n through " + through)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("number of points")
    vcm = any(r["estimator"] == "vcm" for r in rows)
    ax.set_ylabel("time (s), %d threads%s" % (t, " (VCM: 1)" if vcm else ""))
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    return [save(fig, os.path.join(out, name + ".png"))]


def plot_time_vs_k(rows, out):
    """The defaults against k (speed): a plot and a table of the
    median times, with their ratio to k = 100."""
    times = {}
    for r in rows:
        if r["estimator"].startswith("RRHT_defaults_K") and r["status"] == "ok":
            times[int(r["estimator"][len("RRHT_defaults_K"):])] = r["median_s"]
    if not times:
        return [], ""
    ks = sorted(times)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(ks, [times[k] for k in ks], marker="o", markersize=3, label="RRHT, defaults (T_R = 691, n_rot = 5)")
    if 100 in times:
        ax.axhline(times[100], color="gray", linewidth=0.8, label="k = 100")
    ax.set_xscale("log")
    ax.set_xlabel("k (neighbors)")
    ax.set_ylabel("time (s), 2 threads")
    ax.set_title("Cube, 100k points, 0.2% noise: time against k")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    md = ["\n## Time against k\n", "| k | time (s) | ÷ k = 100 |", "|---|---|---|"]
    for k in ks:
        md.append("| %d | %s | %s |" % (k, fmt_time(times[k]), "%.2f" % (times[k] / times[100]) if 100 in times else ""))
    return [save(fig, os.path.join(out, "time_vs_k.png"))], "\n".join(md) + "\n"


def plot_fig7(rows, out):
    t = best_threads(rows)
    times = {}
    for r in rows:
        if r["status"] == "ok" and r["threads"] == t:
            times[(r["dataset"], r["noise_percent"], r["estimator"])] = r["median_s"]
    fig, ax = plt.subplots(figsize=(7, 5))
    lines = []
    for dataset, color in (("sphere", "tab:blue"), ("cube", "tab:orange"), ("cylinder", "tab:green")):
        for setting, dash in (("RRHT_Points_c", "-"), ("RRHT_Points_c_fast", "--")):
            xs, ys = [], []
            for noise in sorted({k[1] for k in times if k[0] == dataset}):
                on, off = times.get((dataset, noise, setting)), times.get((dataset, noise, setting + "_noCI"))
                if on and off:
                    xs.append(noise)
                    ys.append(on / off)
                    lines.append((dataset, setting, noise, on, off))
            if xs:
                ax.plot(xs, ys, dash, color=color, marker="o", markersize=3, label="%s, %s" % (dataset, setting))
    ax.axhline(1, color="gray", linewidth=0.8)
    ax.set_xlabel("noise (% of the bounding-box diagonal)")
    ax.set_ylabel("time with ÷ time without the confidence interval (%d threads)" % t)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    md = ["\n| dataset | setting | noise (%) | with CI (s) | without CI (s) | ratio |", "|---|---|---|---|---|---|"]
    for dataset, setting, noise, on, off in lines:
        md.append("| %s | %s | %g | %s | %s | %.2f |" % (dataset, setting, noise, fmt_time(on), fmt_time(off), on / off))
    return [save(fig, os.path.join(out, "fig7_confidence_interval.png"))], "\n".join(md) + "\n"


def plot_error_vs(rows, out, name, x, xlabel, title, keep=lambda r: True, split_by_dataset=False):
    datasets = sorted({r["dataset"] for r in rows}) if split_by_dataset else [None]
    fig, axes = plt.subplots(len(datasets), 2, figsize=(11, 4.5 * len(datasets)), squeeze=False)
    for i, dataset in enumerate(datasets):
        subset = [r for r in rows if keep(r) and (dataset is None or r["dataset"] == dataset)]
        t = best_threads(subset)
        for j, (measure, label) in enumerate((("rms_deg", "RMS (°)"), ("rms10_deg", "RMS_10 (°)"))):
            ax = axes[i][j]
            plot_lines(ax, series(subset, x, lambda r, m=measure: r[m], t))
            ax.set_xlabel(xlabel)
            ax.set_ylabel(label)
            ax.set_title(title + ("" if dataset is None else " — " + dataset), fontsize=9)
            ax.grid(True, alpha=0.3)
        axes[i][1].legend(fontsize=6)
    return [save(fig, os.path.join(out, name + ".png"))]


def plot_fig10(rows, out):
    t = best_threads(rows)
    ok = [r for r in rows if r["status"] == "ok" and r["threads"] == t]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, measure, label in ((axes[0], "rms_deg", "RMS (°)"), (axes[1], "rms10_deg", "RMS_10 (°)")):
        for fixed, vary, dash, text in (("rotations", "planes", "-", "n_rot = 5, T_R varies"),
                                        ("planes", "rotations", "--", "T_R = 700, n_rot varies")):
            value = 5 if fixed == "rotations" else 700
            line = sorted((r[vary], r["median_s"], r[measure]) for r in ok
                          if r["estimator"].startswith("RRHT") and r[fixed] == value)
            if line:
                ax.plot([p[1] for p in line], [p[2] for p in line], dash, marker="o", markersize=3, label=text)
        for r in ok:
            if r["estimator"].startswith("RRHT") and (r["planes"], r["rotations"]) in ((700, 5), (300, 2)):
                ax.annotate("T_R=%d, n_rot=%d" % (r["planes"], r["rotations"]), (r["median_s"], r[measure]),
                            fontsize=7, xytext=(5, 5), textcoords="offset points")
            if r["estimator"] == REFERENCE:
                ax.plot([r["median_s"]], [r[measure]], "ks", label=REFERENCE)
        ax.set_xlabel("time (s), %d threads" % t)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    return [save(fig, os.path.join(out, "fig10_precision_vs_time.png"))]


def error_color(e):
    """Blue to green from 0 to 10 degrees, red above (the paper's Fig. 8)."""
    if e > TAU:
        return (0.85, 0.1, 0.1)
    s = e / TAU
    return (0.0, s, 1.0 - s)


def load_errors(path):
    """x y z, truth, error (-1: no truth) and confidence (-1: none) per line; the points with a truth."""
    data = []
    with open(path) as f:
        for line in f:
            v = [float(x) for x in line.split()]
            if len(v) >= 7 and v[6] >= 0:
                data.append(v)
    return data


VIEWS = {"cube": (1.0, 0.7, 0.5), "cylinder": (1.0, 0.4, 0.6), "fandisk": (1.0, -0.6, 0.7),
         "corner": (1.0, 1.0, 1.0)}


def confidence_color(c, top):
    """Dark red (0) to yellow to white (``top``, the cloud's 90th percentile, and above)."""
    return plt.get_cmap("hot")(0.1 + 0.9 * min(1.0, c / top))


def render(ax, data, dataset, title, confidence=False):
    """Orthographic view; points whose surface faces away are culled, the
    rest drawn far to near. Colored by the error, or by the confidence."""
    d = VIEWS.get(dataset, (1.0, 0.7, 0.5))
    norm = math.sqrt(sum(c * c for c in d))
    d = [c / norm for c in d]
    up = (0.0, 0.0, 1.0)
    right = (up[1] * d[2] - up[2] * d[1], up[2] * d[0] - up[0] * d[2], up[0] * d[1] - up[1] * d[0])
    rn = math.sqrt(sum(c * c for c in right))
    right = [c / rn for c in right]
    up2 = (d[1] * right[2] - d[2] * right[1], d[2] * right[0] - d[0] * right[2], d[0] * right[1] - d[1] * right[0])
    n = len(data)
    centre = [sum(p[i] for p in data) / n for i in range(3)]

    def outward(p):
        t = p[3:6]
        # Synthetic shapes have unoriented truths: orient them away from the centre
        # (they are convex); meshes keep the orientation of their faces.
        if dataset in ("cube", "cylinder", "sphere"):
            if sum((p[i] - centre[i]) * t[i] for i in range(3)) < 0:
                t = [-c for c in t]
        return t

    orientation = 1.0
    if dataset not in ("cube", "cylinder", "sphere", "corner"):
        s = sum(sum((p[i] - centre[i]) * p[3 + i] for i in range(3)) for p in data)
        orientation = 1.0 if s >= 0 else -1.0
    visible = []
    for p in data:
        t = outward(p)
        if orientation * sum(t[i] * d[i] for i in range(3)) > 0 or dataset == "corner":
            visible.append((sum(p[i] * d[i] for i in range(3)), sum(p[i] * right[i] for i in range(3)),
                            sum(p[i] * up2[i] for i in range(3)), p[7] if confidence else p[6]))
    visible.sort()
    size = min(8.0, max(1.0, 25000.0 / max(1, len(visible))))  # dense enough to read as a surface
    if confidence:
        values = sorted(p[7] for p in data)
        top = max(1e-9, values[int(0.9 * (len(values) - 1))])
        colors = [confidence_color(v[3], top) for v in visible]
    else:
        colors = [error_color(v[3]) for v in visible]
    ax.scatter([v[1] for v in visible], [v[2] for v in visible], c=colors, s=size, linewidths=0)
    ax.set_aspect("equal")
    ax.axis("off")
    if confidence:
        ax.set_title("%s\nconfidence, dark = low" % title, fontsize=9)
        return
    bad = sum(1 for p in data if p[6] > TAU)
    ax.set_title("%s\n%.1f%% above 10°" % (title, 100.0 * bad / max(1, len(data))), fontsize=9)


def renderings(scratch, out):
    made = []
    for dataset in ("cube", "cylinder", "fandisk"):
        panels = [(name, os.path.join(scratch, "%s_%s.txt" % (dataset, name))) for name in ("RRHT_default", REFERENCE)]
        panels = [(n, p) for n, p in panels if os.path.exists(p)]
        if len(panels) < 2:
            continue
        fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 5))
        for ax, (name, path) in zip(axes, panels):
            render(ax, load_errors(path), dataset, name)
        fig.suptitle("%s: angle error, blue→green 0–10°, red above 10° (Fig. 8)" % dataset, fontsize=10)
        made.append(save(fig, os.path.join(out, "fig8_%s.png" % dataset)))
    names = ["RRHT_Points_c", "RRHT_Cubes_c", "RRHT_Unif_c", REFERENCE]
    panels = [(n, os.path.join(scratch, "corner_%s.txt" % n)) for n in names]
    panels = [(n, p) for n, p in panels if os.path.exists(p)]
    if panels:
        fig, axes = plt.subplots(1, len(panels), figsize=(4 * len(panels), 4.4), squeeze=False)
        for ax, (name, path) in zip(axes[0], panels):
            render(ax, load_errors(path), "corner", name)
        fig.suptitle("Corner, densities 1:5:10, 0.2% noise (Fig. 11)", fontsize=10)
        made.append(save(fig, os.path.join(out, "fig11_corner.png")))
    for dataset in ("cube", "cylinder", "fandisk", "corner"):
        path = os.path.join(scratch, "confidence_%s.txt" % dataset)
        if not os.path.exists(path):
            continue
        data = load_errors(path)
        fig, axes = plt.subplots(1, 2, figsize=(10, 5))
        render(axes[0], data, dataset, "RRHT_defaults_K100")
        render(axes[1], data, dataset, "RRHT_defaults_K100", confidence=True)
        fig.suptitle("%s, 0.2%% noise: angle error (blue→green 0–10°, red above) beside the confidence" % dataset,
                     fontsize=10)
        made.append(save(fig, os.path.join(out, "confidence_%s.png" % dataset)))
    return made
