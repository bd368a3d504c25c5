#!/usr/bin/env python3
"""Writes forcedata.d: the course's periodic surface force F(x) = -F0 sin(2 pi x/b) with
F0 = 1 N and b = 1 m, sampled at 101 points from x = 0 to b/4 (100 intervals), two columns
x [m] and F [N] without a header, as the course's data files are. Run from this directory:
python3 forcedata.py (the test `forcedata_matches_its_formula` checks the file)."""
import math

F0, b, n = 1.0, 1.0, 100
with open("forcedata.d", "w") as out:
    out.write("% forcedata.d: F(x) = -F0 sin(2 pi x/b), F0 = 1 N, b = 1 m, x from 0 to b/4\n")
    out.write("% columns: x [m], F [N]; written by forcedata.py\n")
    for i in range(n + 1):
        x = (b / 4) * i / n
        out.write(f"{x:.17g} {-F0 * math.sin(2 * math.pi * x / b):.17g}\n")
