#!/usr/bin/env python3
"""Writes a random radio-link frequency assignment problem shaped like the CELAR instances
(Cabon et al. 1999) in toulbar2's .wcsp format, for the held-out measurements of
docs/BENCHMARKS.md ("Held-out instances").

    celar_like_wcsp.py PAIRS SEED RADIUS > FILE.wcsp

Links come in duplex pairs of variables (2p, 2p+1) bound by a hard |f_a - f_b| = 238; each
pair's domain holds 44 or 36 frequencies, two bands of 22 or 18 channels 14 apart, the
upper band 238 above the lower (for 22 channels the bands overlap). Pairs are points in the
unit square; between pairs closer than RADIUS each of the four cross links, with
probability 1/2, gets a soft interference constraint |f_i - f_j| <= d costs c, d in
{0, 14, ..., 112}, c in {1, 10, 100, 1000} (weights 4:3:2:1), as CELAR's four cost levels.
toulbar2 proves the optimum (`toulbar2 FILE.wcsp`).
"""
import math
import random
import sys

pairs, seed, radius = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
rng = random.Random(seed)
n = 2 * pairs
doms = []
for p in range(pairs):
    half = rng.choice([22, 18])
    low = [14 * k for k in range(half)]
    doms.append(low + [f + 238 for f in low]); doms.append(list(doms[-1]))
pos = [(rng.random(), rng.random()) for _ in range(pairs)]
funcs = []
for p in range(pairs):
    a, b = 2 * p, 2 * p + 1
    tuples = []
    for i, fa in enumerate(doms[a]):
        for j, fb in enumerate(doms[b]):
            if abs(fa - fb) == 238: tuples.append(f"{i} {j} 0")
    funcs.append((f"2 {a} {b} HARD {len(tuples)}", tuples))
for p in range(pairs):
    for q in range(p + 1, pairs):
        dist = math.dist(pos[p], pos[q])
        if dist > radius: continue
        for a in (2 * p, 2 * p + 1):
            for b in (2 * q, 2 * q + 1):
                if rng.random() < 0.5: continue
                d = rng.choice([0, 14, 28, 42, 56, 70, 84, 112])
                c = rng.choices([1, 10, 100, 1000], weights=[4, 3, 2, 1])[0]
                tuples = [f"{i} {j} {c}" for i, fa in enumerate(doms[a])
                          for j, fb in enumerate(doms[b]) if abs(fa - fb) <= d]
                funcs.append((f"2 {a} {b} 0 {len(tuples)}", tuples))
# Top: one more than every soft function at its dearest, so only the duplex pairs are hard.
ub = 1 + sum(max(int(x.split()[2]) for x in tuples) for _, tuples in funcs[pairs:] if tuples)
out = [f"celarlike{pairs}s{seed} {n} 44 {len(funcs)} {ub}", " ".join(str(len(d)) for d in doms)]
for head, tuples in funcs:
    out.append(head.replace("HARD", str(ub))); out.extend(tuples)
print("\n".join(out))
