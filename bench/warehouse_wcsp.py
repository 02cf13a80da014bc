#!/usr/bin/env python3
"""Writes a random uncapacitated warehouse-location problem in toulbar2's .wcsp format, shaped
like toulbar2's `warehouse` instances but larger, for the local-search measurements of
docs/WCSP_LOCAL_SEARCH.md (the shipped `warehouse` has 5 warehouses; the hard ones have 50+).

    warehouse_wcsp.py WAREHOUSES STORES SEED > FILE.wcsp

Variables 0..W-1: warehouse w open (1) or closed (0), unary cost `open` when open.
Variables W..W+S-1: the warehouse serving store s, unary cost demand x distance.
Hard binary tables: store s served by w forbids w closed. Points are uniform in the unit
square; costs are integers. toulbar2 proves the optimum (`toulbar2 FILE.wcsp`).
"""
import math
import random
import sys


def main():
    warehouses, stores, seed = (int(a) for a in sys.argv[1:4])
    rng = random.Random(seed)
    wpos = [(rng.random(), rng.random()) for _ in range(warehouses)]
    spos = [(rng.random(), rng.random()) for _ in range(stores)]
    demand = [rng.randint(5, 50) for _ in range(stores)]
    opening = [rng.randint(20000, 60000) for _ in range(warehouses)]
    supply = [[int(1000 * demand[s] * math.dist(spos[s], wpos[w])) for w in range(warehouses)]
              for s in range(stores)]
    ub = sum(opening) + sum(max(row) for row in supply) + 1
    functions = [f"1 {w} 0 1\n1 {opening[w]}" for w in range(warehouses)]
    for s in range(stores):
        functions.append(f"1 {warehouses + s} 0 {warehouses}\n" +
                         "\n".join(f"{w} {supply[s][w]}" for w in range(warehouses)))
    for s in range(stores):
        for w in range(warehouses):
            functions.append(f"2 {w} {warehouses + s} 0 1\n0 {w} {ub}")
    print(f"wh{warehouses}x{stores}s{seed} {warehouses + stores} {warehouses} {len(functions)} {ub}")
    print(" ".join(["2"] * warehouses + [str(warehouses)] * stores))
    print("\n".join(functions))


if __name__ == "__main__":
    main()
