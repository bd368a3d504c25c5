"""Joins the two sides of bench/stiff/run into one markdown table per problem: for each
tolerance, each solver's error, steps, evaluations and wall time, and mechkit's radau5 against
each SciPy solver as ratios (theirs / ours: above 1 is mechkit ahead)."""

import sys
from collections import defaultdict


def read(path):
    rows = []
    with open(path) as f:
        header = f.readline().rstrip("\n").split("\t")
        for line in f:
            rows.append(dict(zip(header, line.rstrip("\n").split("\t"))))
    return rows


rows = read(sys.argv[1]) + read(sys.argv[2])
by = defaultdict(dict)
for r in rows:
    by[(r["problem"], float(r["tol"]))][r["solver"]] = r

problems = list(dict.fromkeys(r["problem"] for r in rows))
for p in problems:
    print(f"\n### {p}\n")
    print("| tol | solver | error | steps | evaluations | Jacobians | wall (ms) | SciPy/radau5 evals | SciPy/radau5 time |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (problem, tol), solvers in sorted(by.items(), key=lambda kv: -kv[0][1]):
        if problem != p:
            continue
        ours = solvers.get("radau5")
        for name, r in solvers.items():
            ratio_e = ratio_t = ""
            if ours and name.startswith("scipy") and r["error"] != "failed":
                ratio_e = f"{int(r['evaluations']) / int(ours['evaluations']):.2f}"
                ratio_t = f"{float(r['wall_s']) / float(ours['wall_s']):.0f}"
            wall = "-" if r["wall_s"] == "-" else f"{1e3 * float(r['wall_s']):.3g}"
            print(
                f"| {tol:g} | {name} | {r['error']} | {r['steps']} | {r['evaluations']} | {r['jacobians']} | {wall} | {ratio_e} | {ratio_t} |"
            )
