# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The orientation experiment's part of benchmark/report.py: rrht_orient_normals
against mst_orient_normals (and Open3D), its tables and its plot."""

import os
from collections import OrderedDict, defaultdict

from report_plots import plt, save
from report_tables import fmt_time, read_optional

ORIENTATION_TARGETS = ("Targets: closed shapes ≥ 99.9% outward (≤ 0.1% against the outward normal, within 60°); "
                       "open shapes ≥ 99% consistent (≤ 1% on the minority side); the orientation's time ≤ the "
                       "estimation's at 100k and 1M points.")
# Since the closed rows have a floor and a largest inward patch (orientation_quality.csv's
# floor_percent and largest_inward_patch columns).
ORIENTATION_TARGETS_WITH_FLOOR = (
    "Targets: closed shapes ≥ 99.9% outward where no thin part hides the side of the points: at most "
    "max(0.1, floor + 0.1)% of the normals against the outward normal (within 60°), the floor being that of "
    "the cloud's noise (0 when clean), and no connected patch of more than 50 inward normals; open shapes ≥ 99% "
    "consistent (≤ 1% on the minority side); the orientation's time ≤ the estimation's at 100k and 1M points.")


def number(r, column):
    """The value of `column` in the row `r` as a float; None where the column is
    absent (a CSV of an earlier run), empty or negative (n/a)."""
    try:
        value = float(r.get(column) or "")
    except ValueError:
        return None
    return value if value >= 0 else None


def orientation_cloud(r):
    """"cube 100k, 0.2% noise (seed 63)": the cloud of a row of
    orientation_quality.csv (the seed where the CSV has one)."""
    name = "%s %gk" % (r["dataset"], int(r["points"]) / 1000.)
    if int(r["outliers"]):
        return "%s, +%g%% outliers" % (name, float(r["outliers_percent"]))
    noise = float(r["noise_percent"])
    if not noise:
        return "%s, clean" % name
    seed = int(r.get("noise_seed") or 0)
    return "%s, %g%% noise%s" % (name, noise, " (seed %d)" % seed if seed else "")


def orientation_wide(rows, pipelines, value, title, lead=()):
    """A table with a row per cloud and a column per pipeline, `value(row)` in each cell,
    after the columns of `lead`, (header, cell(row)) pairs of the cloud's first row."""
    clouds = OrderedDict()
    for r in rows:
        clouds.setdefault(orientation_cloud(r), OrderedDict())[r["pipeline"]] = r
    headers = ["cloud"] + [h for h, _ in lead] + list(pipelines)
    lines = ["\n%s\n" % title, "| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    for cloud, by_pipeline in clouds.items():
        first = next(iter(by_pipeline.values()))
        cells = [cell(first) for _, cell in lead]
        for p in pipelines:
            r = by_pipeline.get(p)
            cells.append("not run" if r is None else (value(r) if r["status"] == "ok" else r["status"]))
        lines.append("| %s | %s |" % (cloud, " | ".join(cells)))
    return lines


def floor_cell(floors):
    """The floor of a closed row in %: its floor_percent, else (a CSV of an earlier
    run) that of orientation_floor.csv at its cloud and noise, else n/a."""
    def cell(r):
        floor = number(r, "floor_percent")
        if floor is None and not int(r["outliers"]):
            floor = floors.get((r["dataset"], r["kind"], float(r["noise_percent"])))
        return "n/a" if floor is None else "%.3f" % floor
    return cell


def target_cell(r):
    """The target of a closed row: its bound on the share against the outward normal,
    and on the largest inward patch where it has one."""
    bound = number(r, "target_percent")
    patch = number(r, "target_patch")
    return ("n/a" if bound is None else "≤ %g%%" % bound) + ("" if patch is None else ", ≤ %d points" % patch)


def orientation_floors(out, kind, target):
    """The sentences of orientation_floor.csv on the clouds of `kind`: the
    share of the points nearer the other side of a thin part than their own,
    a floor for the share of wrong orientations, against the `target`."""
    md = []
    for r in read_optional(out, "orientation_floor.csv"):
        if r.get("kind", "closed") != kind:
            continue
        floor = float(r["floor_percent"])
        md.append("\nThe floor on %s with %s%% noise: %.3f%% of its points lie nearer the other side of a thin "
                  "part than their own; no orientation from the points alone can tell their side%s.\n"
                  % (r["cloud"], r["noise_percent"], floor,
                     ", and the target of %g is out of reach there" % target if floor > target else ""))
    return md


# The README's table: these pipelines' columns, where the run has them.
README_PIPELINES = OrderedDict([
    ("RRHT_default + rrht_orient_K18", "`rrht_orient_normals`, default normals"),
    ("RRHT_defaults_K100 + rrht_orient_K18", "`rrht_orient_normals`, precise setting's normals"),
    ("RRHT_default + mst_orient_K18", "`mst_orient_normals`, default normals"),
])
README_TABLE_HEADING = "## The README's table"


def readme_table(closed):
    """The README's orientation table, from the closed rows of orientation_quality.csv: each
    closed shape at the largest size with 0.2% noise, for each pipeline of README_PIPELINES
    the worst of the noise draws (% inward, largest inward patch), the largest floor of those
    draws; then, for each, on how many closed clouds of the run (every size, draw, noise level
    and outliers) it meets the target."""
    ok = [r for r in closed if r["status"] == "ok"]
    if not ok:
        return []
    size = max(int(r["points"]) for r in ok)
    pipelines = [p for p in README_PIPELINES if any(r["pipeline"] == p for r in ok)]
    shapes = OrderedDict()
    for r in ok:
        if int(r["points"]) == size and not int(r["outliers"]) and float(r["noise_percent"]) == 0.2:
            shapes.setdefault(r["dataset"], []).append(r)
    draws = max((len({r.get("noise_seed") for r in rs}) for rs in shapes.values()), default=0)
    lines = ["| closed shape, %dk points, 0.2%% noise (worst of %d draw%s) | floor | %s |" % (
                 size // 1000, draws, "" if draws == 1 else "s", " | ".join(README_PIPELINES[p] for p in pipelines)),
             "|---|---|" + "---|" * len(pipelines)]
    for shape, rs in shapes.items():
        floors = [number(r, "floor_percent") or 0. for r in rs]
        cells = []
        for p in pipelines:
            of_p = [r for r in rs if r["pipeline"] == p]
            if not of_p:
                cells.append("not run")
                continue
            worst = max(float(r["wrong_percent"]) for r in of_p)
            patch = max(number(r, "largest_inward_patch") or 0 for r in of_p)
            cells.append("%.2f%% (%d)" % (worst, patch))
        lines.append("| %s | %s | %s |" % (shape.replace("_", " "), "%.2f%%" % max(floors) if max(floors) else "0",
                                           " | ".join(cells)))
    lines.append("")
    for p in pipelines:
        of_p = [r for r in closed if r["pipeline"] == p]
        lines.append("%s: the target met on %d of %d closed clouds." % (
            README_PIPELINES[p], sum(1 for r in of_p if r["met"] == "yes"), len(of_p)))
    return ["\n%s\n" % README_TABLE_HEADING, "Copied in the README, which a test checks against this.\n"] + lines


def orientation_report(rows, out):
    """orientation.md: the quality tables of orientation_quality.csv, the time
    against the number of points of orientation.csv (plot), and the targets."""
    quality = read_optional(out, "orientation_quality.csv")
    pipelines = list(OrderedDict((r["pipeline"], 0) for r in quality))
    closed = [r for r in quality if r["kind"] == "closed"]
    with_floor = any("largest_inward_patch" in r for r in closed)
    md = [(ORIENTATION_TARGETS_WITH_FLOOR if with_floor else ORIENTATION_TARGETS) + "\n"]
    if closed:
        floors = {(r["cloud"], r.get("kind", "closed"), float(r["noise_percent"])): float(r["floor_percent"])
                  for r in read_optional(out, "orientation_floor.csv")}
        md += orientation_wide(closed, pipelines,
                               lambda r: "%.3f (%.1f%%)" % (float(r["wrong_percent"]), float(r["counted_percent"])),
                               "### Closed shapes: % of the normals pointing against the exact outward normal, among "
                               "those within 60° of its line (in brackets: their share of the surface points). "
                               "Floor: the share of the points nearer the other side of a thin part than their own "
                               "(%); target: the row's",
                               lead=[("floor %", floor_cell(floors)), ("target", target_cell)])
        md += orientation_wide(closed, pipelines, lambda r: "%.3f" % float(r["wrong_all_percent"]),
                               "### Closed shapes: the same over all surface points (a null normal counts as wrong)")
        md += orientation_wide(closed, pipelines, lambda r: "%.3f" % float(r["up_to_flip_percent"]),
                               "### Closed shapes: up to a global flip (the minority side, within 60°): 0 where the "
                               "normals are consistent, pointing out or all in")
        md += orientation_wide(closed, pipelines,
                               lambda r: "n/a" if number(r, "largest_inward_patch") is None
                               else "%d" % number(r, "largest_inward_patch"),
                               "### Closed shapes: the largest connected patch of inward normals, in points (inward: "
                               "within 60° of the exact normal's line and against it; two inward points are joined "
                               "where one is among the other's 18 nearest neighbors). Target ≤ 50")
        if with_floor:
            md.append("\nThe floor of a noisy cloud is the share of its points that the noise carried nearer the "
                      "other side of a thin part than their own (orientation_floor.csv): no orientation from the "
                      "points alone can tell their side. A shape whose floor at 0.2% noise is above 0.1% also runs "
                      "at 0.05% noise.\n")
        else:
            md += orientation_floors(out, "closed", 0.1)
        for p in pipelines:
            rows_of_p = [r for r in closed if r["pipeline"] == p]
            if rows_of_p:
                md.append("\n%s meets the target on %d of %d closed clouds.\n" % (
                    p, sum(1 for r in rows_of_p if r["met"] == "yes"), len(rows_of_p)))
        if with_floor:
            md += readme_table(closed)
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
    targets = read_optional(out, "orientation_targets.csv")
    if targets:
        md += ["\n### Time targets (median of the ratios round by round)\n", "| target | ratio | bound | met | rounds |",
               "|---|---|---|---|---|"]
        md += ["| %s | %.3f | %s | %s | %s |" % (r["target"], float(r["ratio"]), r["bound"], r["met"], r["rounds"])
               for r in targets]
    return images, "\n".join(md) + "\n\n## Every measurement of the time part\n"
