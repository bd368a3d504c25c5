"""Joins the two sides of bench/stiff/run into one markdown table per problem: for each
tolerance, each solver's error, steps, evaluations and wall time, and SciPy's Radau and BDF
against mechkit's method of the same name, LSODA against radau5, as ratios (theirs / ours:
above 1 is mechkit ahead)."""

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
    print("| tol | solver | error | steps | evaluations | Jacobians | wall (ms) | SciPy/mechkit evals | SciPy/mechkit time |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (problem, tol), solvers in sorted(by.items(), key=lambda kv: -kv[0][1]):
        if problem != p:
            continue
        for name, r in solvers.items():
            ratio_e = ratio_t = ""
            ours = solvers.get("bdf" if name == "scipy-BDF" else "radau5")
            if ours and name.startswith("scipy") and r["error"] != "failed":
                ratio_e = f"{int(r['evaluations']) / int(ours['evaluations']):.2f}"
                ratio_t = f"{float(r['wall_s']) / float(ours['wall_s']):.0f}"
            wall = "-" if r["wall_s"] == "-" else f"{1e3 * float(r['wall_s']):.3g}"
            print(
                f"| {tol:g} | {name} | {r['error']} | {r['steps']} | {r['evaluations']} | {r['jacobians']} | {wall} | {ratio_e} | {ratio_t} |"
            )
