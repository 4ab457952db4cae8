#!/usr/bin/python3
# Copyright (c) 2026 The CGAL RRHT authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The targets of poisson_benchmark's surfaces, from poisson.csv, as a table at
the top of poisson.md: on every shape and noise, both 99th-percentile
distances of the surface from RRHT + rrht_orient_normals (to the true surface,
from it) at most 1.5 times those from the exact normals, and at most those
from jet fitting + mst_orient_normals (where that reconstruction failed or
was refused, it has none to beat). Beside them, those of RRHT's normals given
the exact normals' signs: what the orientation leaves to the normals.

    report_poisson.py RESULTS_DIR
"""

import argparse
import csv
import os

TITLE = "## Targets"
FACTOR = 1.5


def p99s(row):
    """(to true, from true) 99th percentiles of an ok row, else None."""
    if row is None or row["status"] != "ok":
        return None
    return float(row["to_true_p99_percent"]), float(row["from_true_p99_percent"])


def cell(values):
    return "%.3f / %.3f" % values if values else "none"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    args = parser.parse_args()
    with open(os.path.join(args.results, "poisson.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    cases = {}
    for r in rows:
        cases.setdefault((r["shape"], r["noise_percent"]), {})[r["normals"]] = r
    lines = [TITLE, "",
             "Both 99th-percentile distances (to the true surface / from it, %% of the diagonal) of the surface "
             "from RRHT + `rrht_orient_normals` at most %g times those from the exact normals, and at most "
             "those from jet fitting + `mst_orient_normals` (none: that reconstruction failed or was refused). "
             "*RRHT, exact signs*: RRHT's normals each given the exact normal's sign, what an orientation "
             "without a mistake would give." % FACTOR, "",
             "| shape, noise | RRHT + rrht_orient | %g × exact | jet + MST | met | RRHT, exact signs |" % FACTOR,
             "|---|---|---|---|---|---|"]
    met = 0
    for (shape, noise), by in cases.items():
        ours, exact, jet = p99s(by.get("rrht_orient")), p99s(by.get("exact")), p99s(by.get("jet_mst"))
        bound = (FACTOR * exact[0], FACTOR * exact[1]) if exact else None
        ok = bool(ours and bound and all(o <= b for o, b in zip(ours, bound)) and
                  (jet is None or all(o <= j for o, j in zip(ours, jet))))
        met += ok
        lines.append("| %s, %s%% | %s | %s | %s | %s | %s |" % (shape, noise, cell(ours), cell(bound), cell(jet),
                                                               "yes" if ok else "no",
                                                               cell(p99s(by.get("rrht_exact_signs")))))
    lines += ["", "Met on %d of %d." % (met, len(cases)), ""]
    md_path = os.path.join(args.results, "poisson.md")
    with open(md_path) as f:
        md = f.read()
    if TITLE + "\n" not in md:
        # After the introduction, before the first shape.
        at = md.index("\n## ") + 1
        md = md[:at] + "\n".join(lines) + "\n" + md[at:]
    with open(md_path, "w") as f:
        f.write(md)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
