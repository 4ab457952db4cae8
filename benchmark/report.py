#!/usr/bin/python3
# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Turns the CSV files of rrht_benchmark into Markdown tables, plots and
renderings of the error (the paper's Fig. 8 and 11).

    report.py RESULTS_DIR [--scratch DIR] [--before EARLIER_RESULTS_DIR]...

RESULTS_DIR holds the CSV files and machine.txt (written by
scripts/benchmark.sh); DIR holds the per-point error files. Needs Debian's
python3-matplotlib.
"""

import argparse
import csv
import math
import os
import re
from collections import OrderedDict, defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REFERENCE = "jet_K80"  # the paper's and CGAL's usual competitor
TAU = 10.0


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("points", "outliers", "planes", "rotations", "threads", "runs", "null_normals"):
            r[key] = int(r[key])
        for key in ("noise_percent", "outliers_percent", "median_s", "min_s", "max_s", "peak_mib", "rms_deg",
                    "rms10_deg", "above10_percent"):
            r[key] = float(r[key])
    return rows


def has_truth(row):
    # The orientation's rows are timed on normals it did not estimate: their errors are not its own.
    return row["experiment"] not in ("real_scans", "orientation")


def group_key(r):
    return (r["dataset"], r["points"], r["outliers"], r["noise_percent"], r["outliers_percent"])


def describe(key):
    dataset, points, outliers, noise, outliers_percent = key
    text = "%s, %d points, %g%% noise" % (dataset, points, noise)
    if outliers:
        text += ", +%g%% outliers (%d)" % (outliers_percent, outliers)
    return text


def fmt_time(s):
    return "%.3f" % s if s < 10 else "%.1f" % s


def table(rows, with_errors=True):
    """One Markdown table per dataset group: estimators as rows, times per
    thread count, ratios to jet_K80 of the same run, errors, memory."""
    groups = OrderedDict()
    for r in rows:
        groups.setdefault(group_key(r), []).append(r)
    out = []
    for key, members in groups.items():
        threads = sorted({r["threads"] for r in members})
        top = threads[-1]
        by_estimator = OrderedDict()
        for r in members:
            by_estimator.setdefault(r["estimator"], {})[r["threads"]] = r
        reference = by_estimator.get(REFERENCE, {})
        header = ["estimator"] + ["time %dt (s)" % t for t in threads]
        header += ["time ÷ jet_K80 (%dt)" % top]
        if with_errors:
            header += ["RMS (°)", "RMS_10 (°)", "RMS_10 ÷ jet_K80", "> 10° (%)"]
        header += ["peak memory (MiB)", "null normals"]
        out.append("\n**%s**\n" % describe(key))
        out.append("| " + " | ".join(header) + " |")
        out.append("|" + "---|" * len(header))
        for name, per_thread in by_estimator.items():
            any_row = next(iter(per_thread.values()))
            cells = [("**%s**" % name) if name.startswith("RRHT") else name]
            for t in threads:
                r = per_thread.get(t)
                cells.append("—" if r is None else (fmt_time(r["median_s"]) if r["status"] == "ok" else r["status"]))
            mine = per_thread.get(top) or any_row
            ref = reference.get(mine["threads"])
            ok = mine["status"] == "ok" and ref is not None and ref["status"] == "ok" and ref["median_s"] > 0
            cells.append("%.2f×" % (mine["median_s"] / ref["median_s"]) if ok else "—")
            scored = [r for r in per_thread.values() if r["status"] == "ok"]
            if with_errors and scored:
                r = scored[0]
                cells += ["%.2f" % r["rms_deg"], "%.2f" % r["rms10_deg"]]
                cells.append("%.2f" % (r["rms10_deg"] / ref["rms10_deg"])
                             if ref is not None and ref["status"] == "ok" and ref["rms10_deg"] > 0 else "—")
                cells.append("%.2f" % r["above10_percent"])
            elif with_errors:
                cells += ["—"] * 4
            cells += ["%.1f" % max(r["peak_mib"] for r in scored) if scored else "—",
                      str(scored[0]["null_normals"]) if scored else "—"]
            out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


TITLES = {
    "headline": "Headline: RRHT against jet fitting, PCA, VCM (and PCL, Open3D) on shapes with sharp edges",
    "fig6_time_vs_points": "Fig. 6: time against the number of points (sphere, 0.2% noise, no confidence interval)",
    "fig7_confidence_interval": "Fig. 7: effect of the confidence-interval stop (eq. 10) against noise",
    "fig9_noise": "Fig. 9: error against noise on the closed cylinder",
    "fig10_precision_vs_time": "Fig. 10: precision against time over T_R and n_rot (noisy cube)",
    "fig13_anisotropy": "Fig. 11 and 13: the corner with densities 1:5:10",
    "fig15_outliers": "Fig. 15: outliers drawn within 3% of the bounding-box diagonal",
    "real_meshes": "Real meshes (../shared/data/meshes), sampled, the face normal as truth",
    "real_points": "Point sets with given normals (../shared/data/points)",
    "real_scans": "Real scans without normals (../shared/data/scans): time and memory",
    "speed": "Speed: the performance targets on the 100k-point cube and the 1M-point sphere, 0.2% noise; time against k",
    "scaling": "Time against the number of points at the fast setting (sphere, 0.2% noise)",
    "adaptive": "The adaptive setting against the precise setting and RRHT_Cubes (100k points, 0.2% noise, 2 threads)",
    "refit": "The least-squares refit (refit=True) on smooth, sharp and thin clouds (100k points, 2 threads)",
    "fillets": "Fillets: every RRHT setting against jet fitting on rounded edges (100k points, 2 threads)",
    "confidence": "Confidence per point (confidence_map): does it predict the error? (100k points, 0.2% noise)",
    "orientation": "Orienting the normals: rrht_orient_normals against mst_orient_normals (and Open3D)",
    "default": "The default against its targets: every setting and jet fitting (100k points, k = 100, 2 threads)",
}

COLORS = {"Points": "tab:blue", "Cubes": "tab:orange", "Unif": "tab:green", "jet_K80": "black",
          "jet_K18": "dimgray", "pca_K80": "tab:purple", "vcm": "tab:brown", "pcl_K80": "tab:pink",
          "open3d_K30": "tab:olive", "open3d_hybrid": "tab:cyan"}
STYLES = {"m": "--", "b": ":", "c": "-"}


def style(name):
    """Color by sampling, line style by aggregation as in the paper's plots."""
    if name.startswith("RRHT_"):
        parts = name.split("_")
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


def read_ratios(folder, file="speed_ratios.csv"):
    path = os.path.join(folder, file)
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def targets_table(out, befores=(), file="speed_ratios.csv", column="ratio"):
    """The values rrht_benchmark printed for the targets, from `file` (whose
    values are in `column`), after those of the earlier results `befores` if
    given (columns named after the folders)."""
    rows = read_ratios(out, file)
    if not rows:
        return ""
    # The row of time against k names its slowest k, which differs from run
    # to run: rows are matched without it.
    def key(target):
        return re.sub(r" \(k = \d+\)", "", target)

    if befores:
        olds = [{key(r["target"]): r for r in read_ratios(b, file)} for b in befores]
        names = [os.path.basename(os.path.normpath(d)) for d in list(befores) + [out]]
        lines = ["| target | bound | " + " | ".join("%s | met" % n for n in names) + " |",
                 "|---|---|" + "---|---|" * len(names)]
        for r in rows:
            cells = []
            for old in olds:
                b = old.get(key(r["target"]))
                cells += ["%.3f" % float(b[column]) if b else "", b["met"] if b else ""]
            cells += ["%.3f" % float(r[column]), r["met"]]
            lines.append("| %s | %s | %s |" % (r["target"], r["bound"], " | ".join(cells)))
    else:
        lines = ["| target | %s | bound | met |" % column, "|---|---|---|---|"]
        lines += ["| %s | %.3f | %s | %s |" % (r["target"], float(r[column]), r["bound"], r["met"]) for r in rows]
    met = sum(r["met"] == "yes" for r in rows)
    lines.append("\n%d of %d targets met." % (met, len(rows)))
    return "\n".join(lines) + "\n"


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


# --- Renderings of the error (Fig. 8 and 11) ---------------------------------

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


def adaptive_table(out):
    """The table of adaptive_errors.csv: errors over all points and near the edges."""
    path = os.path.join(out, "adaptive_errors.csv")
    if not os.path.exists(path):
        return ""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    lines = ["| data | estimator | time 2t (s) | > 10° (%) | RMS (°) | > 10° within 1% of an edge (%) |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %.3f | %.2f | %.2f | %.2f (of %.1f%% of the points) |" % (
            r["dataset"], r["estimator"], float(r["median_s"]), float(r["above10_percent"]), float(r["rms_deg"]),
            float(r["above10_near_edges_percent"]), float(r["near_edges_percent"])))
    times = os.path.join(out, "adaptive_time.csv")
    if os.path.exists(times):
        with open(times, newline="") as f:
            lines += ["", "| time, measured in rounds (median of the ratios round by round) | ratio | rounds |", "|---|---|---|"]
            lines += ["| %s | %.3f | %s |" % (r["ratio"], float(r["value"]), r["rounds"]) for r in csv.DictReader(f)]
    return "\n".join(lines) + "\n"


def refit_table(rows):
    """Side by side per cloud: RRHT's defaults without and with the refit, and jet fitting."""
    by = {}
    for r in rows:
        by.setdefault("%s (%g%% noise)" % (r["dataset"], float(r["noise_percent"])), {})[r["estimator"]] = r
    lines = ["| data | K | RRHT > 10° (%) / RMS (°) | with refit | jet_K80 | jet, same K | time with ÷ without refit |",
             "|---|---|---|---|---|---|---|"]
    for data, estimators in by.items():
        for k in ("K30", "K100"):
            plain, refit = estimators.get("RRHT_defaults_" + k), estimators.get("RRHT_refit_" + k)
            if plain is None or refit is None:
                continue
            def cell(r):
                return "—" if r is None else "%.2f / %.2f" % (float(r["above10_percent"]), float(r["rms_deg"]))
            lines.append("| %s | %s | %s | %s | %s | %s | %.2f |" % (
                data, k[1:], cell(plain), cell(refit), cell(estimators.get("jet_K80")), cell(estimators.get("jet_" + k)),
                float(refit["median_s"]) / float(plain["median_s"])))
    return "\n".join(lines) + "\n"


def confidence_table(out):
    """The table of confidence_auc.csv."""
    path = os.path.join(out, "confidence_auc.csv")
    if not os.path.exists(path):
        return ""
    with open(path, newline="") as f:
        rows = [{k: (v if k == "dataset" else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]
    lines = ["| data | points | > 10° (%) | AUC of 1 − confidence for > 10° | points within 1% of an edge (%) | "
             "median confidence there | median elsewhere | ratio | time with ÷ without the map |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %d | %.2f | %.3f | %.1f | %.3f | %.3f | %.2f | %.3f (%d rounds) |" % (
            r["dataset"], r["points"], r["above10_percent"], r["auc"], r["near_edges_percent"],
            r["median_near_edges"], r["median_elsewhere"], r["median_near_edges"] / max(1e-9, r["median_elsewhere"]),
            r["time_with_confidence_over_without"], r["rounds"]))
    return "\n".join(lines) + "\n"


# --- Orientation ------------------------------------------------------------

ORIENTATION_TARGETS = ("Targets: closed shapes ≥ 99.9% outward (≤ 0.1% against the outward normal, within 60°); "
                       "open shapes ≥ 99% consistent (≤ 1% on the minority side); the orientation's time ≤ the "
                       "estimation's at 100k and 1M points.")


def orientation_cloud(r):
    """"cube, 0.2% noise": the cloud of a row of orientation_quality.csv."""
    if int(r["outliers"]):
        return "%s, +%g%% outliers" % (r["dataset"], float(r["outliers_percent"]))
    noise = float(r["noise_percent"])
    return "%s, %s" % (r["dataset"], "%g%% noise" % noise if noise else "clean")


def orientation_wide(rows, pipelines, value, title):
    """A table with a row per cloud and a column per pipeline, `value(row)` in each cell."""
    clouds = OrderedDict()
    for r in rows:
        clouds.setdefault(orientation_cloud(r), {})[r["pipeline"]] = r
    lines = ["\n%s\n" % title, "| cloud | " + " | ".join(pipelines) + " |", "|---|" + "---|" * len(pipelines)]
    for cloud, by_pipeline in clouds.items():
        cells = []
        for p in pipelines:
            r = by_pipeline.get(p)
            cells.append("not run" if r is None else (value(r) if r["status"] == "ok" else r["status"]))
        lines.append("| %s | %s |" % (cloud, " | ".join(cells)))
    return lines


def orientation_floors(out, kind, target):
    """The sentences of orientation_floor.csv on the clouds of `kind`: the
    share of the points nearer the other side of a thin part than their own,
    a floor for the share of wrong orientations, against the `target`."""
    path = os.path.join(out, "orientation_floor.csv")
    if not os.path.exists(path):
        return []
    md = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if r.get("kind", "closed") != kind:
                continue
            floor = float(r["floor_percent"])
            md.append("\nThe floor on %s with %s%% noise: %.3f%% of its points lie nearer the other side of a thin "
                      "part than their own; no orientation from the points alone can tell their side%s.\n"
                      % (r["cloud"], r["noise_percent"], floor,
                         ", and the target of %g is out of reach there" % target if floor > target else ""))
    return md


def orientation_report(rows, out):
    """orientation.md: the quality tables of orientation_quality.csv, the time
    against the number of points of orientation.csv (plot), and the targets."""
    path = os.path.join(out, "orientation_quality.csv")
    quality = []
    if os.path.exists(path):
        with open(path, newline="") as f:
            quality = list(csv.DictReader(f))
    pipelines = list(OrderedDict((r["pipeline"], 0) for r in quality))
    md = [ORIENTATION_TARGETS + "\n"]
    closed = [r for r in quality if r["kind"] == "closed"]
    if closed:
        md += orientation_wide(closed, pipelines,
                               lambda r: "%.3f (%.1f%%)" % (float(r["wrong_percent"]), float(r["counted_percent"])),
                               "### Closed shapes: % of the normals pointing against the exact outward normal, among "
                               "those within 60° of its line (in brackets: their share of the surface points). "
                               "Target ≤ 0.1")
        md += orientation_wide(closed, pipelines, lambda r: "%.3f" % float(r["wrong_all_percent"]),
                               "### Closed shapes: the same over all surface points (a null normal counts as wrong)")
        md += orientation_wide(closed, pipelines, lambda r: "%.3f" % float(r["up_to_flip_percent"]),
                               "### Closed shapes: up to a global flip (the minority side, within 60°): 0 where the "
                               "normals are consistent, pointing out or all in")
        md += orientation_floors(out, "closed", 0.1)
        met = [r for r in closed if r["pipeline"] == pipelines[0] and r["met"] == "yes"]
        md.append("\n%s meets the target on %d of %d closed clouds.\n" % (
            pipelines[0], len(met), sum(1 for r in closed if r["pipeline"] == pipelines[0])))
    opened = [r for r in quality if r["kind"] == "open"]
    if opened:
        md += orientation_wide(opened, pipelines,
                               lambda r: "%.3f (%.1f%%)" % (float(r["wrong_percent"]), float(r["counted_percent"])),
                               "### Open shapes: % of the normals on the minority side, among those within 60° of "
                               "the exact normal's line (in brackets: their share). Target ≤ 1")
        md += orientation_floors(out, "open", 1)
        md += orientation_wide(opened, pipelines, lambda r: "%.3f" % float(r["wrong_all_percent"]),
                               "### Open shapes: the same over all points")
    scans = [r for r in quality if r["kind"] == "scan"]
    if scans:
        md += orientation_wide(scans, pipelines, lambda r: "%.3f" % float(r["wrong_percent"]),
                               "### Real scan (no truth): % of the points whose oriented normal disagrees in sign with "
                               "most of their 10 nearest neighbors (only neighbors within 60° of the point's normal "
                               "line vote). Target ≤ 1")
    unoriented = [r for r in quality if r["status"] == "ok" and int(r["not_oriented"])]
    if unoriented:
        md += ["\n### Points left unoriented (moved to the end of the range)\n", "| cloud | pipeline | points |",
               "|---|---|---|"]
        md += ["| %s | %s | %s |" % (orientation_cloud(r), r["pipeline"], r["not_oriented"]) for r in unoriented]
    if quality:
        md += ["\n### Time of each step on the 100k-point clouds (one run, 2 threads; median over the clouds)\n",
               "| pipeline | normals (s) | orientation (s) | clouds |", "|---|---|---|---|"]
        for p in pipelines:
            ok = [r for r in quality if r["pipeline"] == p and r["status"] == "ok"]
            if ok:
                normals = sorted(float(r["normals_s"]) for r in ok)
                orient = sorted(float(r["orient_s"]) for r in ok)
                md.append("| %s | %.3f | %.3f | %d |" % (p, normals[len(normals) // 2], orient[len(orient) // 2],
                                                         len(ok)))
        md.append("\nOpen3D's own pipeline is one step (estimation and orientation together): its time is in the "
                  "orientation column.\n")
    images = []
    times, above10 = defaultdict(dict), {}
    for r in rows:
        if r["status"] == "ok":
            times[r["estimator"]][r["points"]] = r["median_s"]
            if r["estimator"] == rows[0]["estimator"]:  # the estimation: how far off the normals to orient are
                above10[r["points"]] = r["above10_percent"]
    if times:
        names = list(OrderedDict((r["estimator"], 0) for r in rows))
        sizes = sorted({r["points"] for r in rows})
        dataset = rows[0]["dataset"]
        md += ["\n## Time against the number of points (%s, %g%% noise, 2 threads, median of the rounds)\n" % (
                   dataset, rows[0]["noise_percent"]),
               "| points | " + " | ".join("%s (s)" % n for n in names) + " | %s per point (µs) | " % names[1]
               + "%s normals > 10° (%%) |" % names[0],
               "|---|" + "---|" * (len(names) + 2)]
        for n in sizes:
            cells = [fmt_time(times[e][n]) if n in times[e] else "—" for e in names]
            per_point = "%.2f" % (1e6 * times[names[1]][n] / n) if n in times[names[1]] else "—"
            md.append("| %d | %s | %s | %s |" % (n, " | ".join(cells), per_point,
                                                 "%.1f" % above10[n] if n in above10 else "—"))
        md.append("\nThe noise is a fixed share of the diagonal: the denser the cloud, the noisier the neighborhoods "
                  "and the farther off the normals to orient (last column).")
        failed = [r for r in rows if r["status"] != "ok"]
        if failed:
            md.append("\n" + "; ".join("%s at %d points: %s" % (r["estimator"], r["points"], r["status"])
                                       for r in failed) + ".")
        fig, ax = plt.subplots(figsize=(7, 5))
        for name in names:
            points = sorted(times[name].items())
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], marker="o", markersize=3, label=name)
        first = sorted(times[names[1]].items())
        if first:
            n0, t0 = first[0]
            ax.plot(sizes, [t0 * n / n0 for n in sizes], color="gray", linestyle="--", linewidth=0.8,
                    label="∝ n through %s at %d" % (names[1], n0))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("number of points")
        ax.set_ylabel("time (s), 2 threads (mst_orient_normals: 1)")
        ax.set_title("%s, %g%% noise: orientation against estimation" % (dataset, rows[0]["noise_percent"]))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        images.append(save(fig, os.path.join(out, "orientation_time.png")))
    path = os.path.join(out, "orientation_targets.csv")
    if os.path.exists(path):
        with open(path, newline="") as f:
            targets = list(csv.DictReader(f))
        md += ["\n### Time targets (median of the ratios round by round)\n", "| target | ratio | bound | met | rounds |",
               "|---|---|---|---|---|"]
        md += ["| %s | %.3f | %s | %s | %s |" % (r["target"], float(r["ratio"]), r["bound"], r["met"], r["rounds"])
               for r in targets]
    return images, "\n".join(md) + "\n\n## Every measurement of the time part\n"


def summary(rows):
    """The compact headline table the top-level README quotes: one row per estimator, and
    per cloud its share of normals above 10° and its time over jet_K80's with 2 threads
    (with 1 thread for the single-threaded)."""
    datasets = OrderedDict((r["dataset"], r["points"]) for r in rows)
    out = ["| estimator | " + " | ".join("%s (%dk): > 10°, time ÷ jet" % (d, n // 1000) for d, n in datasets.items())
           + " |", "|---|" + "---|" * len(datasets)]
    cell = {(r["dataset"], r["estimator"], r["threads"]): r for r in rows if r["status"] == "ok"}
    for name in OrderedDict((r["estimator"], 0) for r in rows):
        cells = []
        for dataset in datasets:
            threads = 2 if (dataset, name, 2) in cell else 1
            own, ref = cell.get((dataset, name, threads)), cell.get((dataset, REFERENCE, threads))
            if own is None:
                cells.append("—")
                continue
            ratio = "%.2f×" % (own["median_s"] / ref["median_s"]) if ref else "—"
            cells.append("%.1f%%, %s%s" % (own["above10_percent"], ratio, "" if threads == 2 else " (1 thread)"))
        out.append("| %s | %s |" % (("**%s**" % name) if name.startswith("RRHT") else name, " | ".join(cells)))
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--scratch", default=None, help="folder of the per-point error files")
    parser.add_argument("--before", action="append", default=[],
                        help="earlier results whose target ratios to show next to these (may be repeated)")
    args = parser.parse_args()
    out = args.results
    experiments = OrderedDict()
    for name in TITLES:
        path = os.path.join(out, name + ".csv")
        if os.path.exists(path):
            experiments[name] = read(path)
    machine = ""
    if os.path.exists(os.path.join(out, "machine.txt")):
        with open(os.path.join(out, "machine.txt")) as f:
            machine = f.read().strip()

    index = ["# Benchmark results\n", machine + "\n" if machine else "",
             "Times are medians over the runs given in each CSV (column `runs`); ratios are taken within this run. "
             "RMS and RMS_10 are in degrees (paper, §6: errors above 10° count as 90° in RMS_10). "
             "Peak memory is the resident memory a measurement adds above its input (see benchmark/measure.h).\n"]
    rendered = renderings(args.scratch, out) if args.scratch else []
    for name, rows in experiments.items():
        md = ["# " + TITLES[name] + "\n", machine + "\n" if machine else ""]
        images = []
        extra = ""
        if name == "fig6_time_vs_points":
            images = plot_time_vs_points(rows, out, name, "RRHT_Points_c_noCI",
                                         "Sphere, 0.2% noise, no confidence interval")
        elif name == "scaling":
            images = plot_time_vs_points(rows, out, name, "RRHT_Points_c_fast",
                                         "Sphere, 0.2% noise, fast setting (T = 300, n_rot = 2)")
        elif name == "speed":
            images, against_k = plot_time_vs_k(rows, out)
            extra = targets_table(out, args.before) + against_k
        elif name == "fig7_confidence_interval":
            images, extra = plot_fig7(rows, out)
        elif name == "fig9_noise":
            images = plot_error_vs(rows, out, name, lambda r: r["noise_percent"], "noise (%)",
                                   "Closed cylinder")
        elif name == "fig10_precision_vs_time":
            images = plot_fig10(rows, out)
        elif name == "fig13_anisotropy":
            images = plot_error_vs(rows, out, name, lambda r: r["noise_percent"], "noise (%)",
                                   "Corner 1:5:10")
        elif name == "fig15_outliers":
            images = plot_error_vs(rows, out, name, lambda r: r["outliers_percent"], "outliers (% of the points)",
                                   "0.2% noise", split_by_dataset=True)
        elif name == "headline":
            images = [i for i in rendered if i.startswith("fig8")]
        elif name == "adaptive":
            extra = adaptive_table(out)
        elif name == "refit":
            extra = refit_table(rows)
        elif name == "confidence":
            images = [i for i in rendered if i.startswith("confidence_")]
            extra = confidence_table(out)
        elif name == "orientation":
            images, extra = orientation_report(rows, out)
        elif name == "default":
            extra = targets_table(out, args.before, "default_targets.csv", "value")
        if name == "fig13_anisotropy":
            images += [i for i in rendered if i.startswith("fig11")]
        for image in images:
            md.append("![%s](%s)\n" % (image, image))
        md.append(extra)
        md.append(table(rows, with_errors=has_truth(rows[0])))
        if name == "headline":
            with open(os.path.join(out, "headline_summary.md"), "w") as f:
                f.write(summary(rows))
        with open(os.path.join(out, name + ".md"), "w") as f:
            f.write("\n".join(md))
        index.append("- [%s](%s.md)" % (TITLES[name], name))
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write("\n".join(index) + "\n")
    print("report written to %s" % out)


if __name__ == "__main__":
    main()
