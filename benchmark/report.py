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
import os
from collections import OrderedDict

from report_orientation import orientation_report
from report_plots import plot_error_vs, plot_fig7, plot_fig10, plot_time_vs_k, plot_time_vs_points, renderings
from report_tables import (adaptive_table, confidence_table, has_truth, read, refit_table, summary, table, targets_table,
                           threads_table)

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
    "scaling": "Time and memory against the number of points, the default and the fast setting (sphere, 0.2% noise)",
    "adaptive": "The adaptive setting against the precise setting and RRHT_Cubes (100k points, 0.2% noise, 2 threads)",
    "refit": "The least-squares refit (refit=True) on smooth, sharp and thin clouds (100k points, 2 threads)",
    "fillets": "Fillets: every RRHT setting against jet fitting on rounded edges (100k points, 2 threads)",
    "confidence": "Confidence per point (confidence_map): does it predict the error? (100k points, 0.2% noise)",
    "orientation": "Orienting the normals: rrht_orient_normals against mst_orient_normals (and Open3D)",
    "default": "The default against its targets: every setting and jet fitting (100k points, k = 100, 2 threads)",
    "threads": "Threads: the default, jet fitting and the bare neighbor queries from 1 thread to every core",
}


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
            images = plot_time_vs_points(rows, out, name, "RRHT_default",
                                         "Sphere, 0.2% noise, the default and the fast setting (T = 300, n_rot = 2)")
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
        elif name == "threads":
            extra = targets_table(out, args.before, "threads_targets.csv") + threads_table(rows)
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
