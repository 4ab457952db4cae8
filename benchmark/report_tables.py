# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Markdown tables of benchmark/report.py: the results of an experiment, the
ratios of its targets, and the README's headline summary."""

import csv
import os
import re
from collections import OrderedDict

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


def read_optional(folder, file):
    """The rows of a CSV file that an experiment may not have written, as strings; [] if it is absent."""
    path = os.path.join(folder, file)
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def targets_table(out, befores=(), file="speed_ratios.csv", column="ratio"):
    """The values rrht_benchmark printed for the targets, from `file` (whose
    values are in `column`), after those of the earlier results `befores` if
    given (columns named after the folders)."""
    rows = read_optional(out, file)
    if not rows:
        return ""
    # The row of time against k names its slowest k, which differs from run
    # to run: rows are matched without it.
    def key(target):
        return re.sub(r" \(k = \d+\)", "", target)

    if befores:
        olds = [{key(r["target"]): r for r in read_optional(b, file)} for b in befores]
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


def adaptive_table(out):
    """The table of adaptive_errors.csv: errors over all points and near the edges."""
    rows = read_optional(out, "adaptive_errors.csv")
    if not rows:
        return ""
    lines = ["| data | estimator | time 2t (s) | > 10° (%) | RMS (°) | > 10° within 1% of an edge (%) |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %.3f | %.2f | %.2f | %.2f (of %.1f%% of the points) |" % (
            r["dataset"], r["estimator"], float(r["median_s"]), float(r["above10_percent"]), float(r["rms_deg"]),
            float(r["above10_near_edges_percent"]), float(r["near_edges_percent"])))
    times = read_optional(out, "adaptive_time.csv")
    if times:
        lines += ["", "| time, measured in rounds (median of the ratios round by round) | ratio | rounds |", "|---|---|---|"]
        lines += ["| %s | %.3f | %s |" % (r["ratio"], float(r["value"]), r["rounds"]) for r in times]
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
    rows = [{k: (v if k == "dataset" else float(v)) for k, v in r.items()}
            for r in read_optional(out, "confidence_auc.csv")]
    if not rows:
        return ""
    lines = ["| data | points | > 10° (%) | AUC of 1 − confidence for > 10° | points within 1% of an edge (%) | "
             "median confidence there | median elsewhere | ratio | time with ÷ without the map |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %d | %.2f | %.3f | %.1f | %.3f | %.3f | %.2f | %.3f (%d rounds) |" % (
            r["dataset"], r["points"], r["above10_percent"], r["auc"], r["near_edges_percent"],
            r["median_near_edges"], r["median_elsewhere"], r["median_near_edges"] / max(1e-9, r["median_elsewhere"]),
            r["time_with_confidence_over_without"], r["rounds"]))
    return "\n".join(lines) + "\n"


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


def threads_table(rows):
    """The speed-up of each estimator on each cloud over its own median time with 1 thread."""
    counts = sorted({int(r["threads"]) for r in rows})
    lines = ["| cloud | estimator | " + " | ".join("%d thread%s" % (c, "" if c == 1 else "s") for c in counts) + " |",
             "|---|---|" + "---|" * len(counts)]
    keys = OrderedDict(((r["dataset"], r["points"], r["estimator"]), None) for r in rows)
    for dataset, points, estimator in keys:
        time = {int(r["threads"]): float(r["median_s"]) for r in rows
                if (r["dataset"], r["points"], r["estimator"]) == (dataset, points, estimator)}
        cells = ["%.2f s" % time[1] if c == 1 else "%.2f×" % (time[1] / time[c]) if c in time and time[c] > 0 else ""
                 for c in counts]
        lines.append("| %s %sk | %s | %s |" % (dataset, int(points) // 1000, estimator, " | ".join(cells)))
    return "Time with 1 thread, then the speed-up over it (median times):\n\n" + "\n".join(lines) + "\n\n"
