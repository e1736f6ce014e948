#!/usr/bin/python3
"""The roll axes a seed draws, without running it, and how new each is (issue 36: why the second
cycle falls short at some seeds; docs/SCIENCE.md, "Which rolls the seeds draw").

The protocol's one random choice is each cycle's roll axis (protocols/stages/roll.cpp, `axis:
random`): the run's generator, a 64-bit Mersenne twister seeded with the run's seed, draws one
uniform angle in [0, 180) degrees per roll stage and nothing else draws from it in
protocols/axial_crumpling.yaml. So a seed's axes are the same at every mesh, compaction and
material, and can be listed here for any seed. This reproduces the draw of the C++ standard
library the simulator is built with (libstdc++: the generator's 64-bit output, converted to a
double and divided by 2^64, scaled to [0, pi)); tests/pipeline/test_seed_roll_axes.py checks it
against the axes run files record (/stage_ends/NNNNNN@roll_axis_deg).

A roll's novelty is its smallest angle to any axis rolled before (roll_axes.py): in this model
a cycle whose axis lies within a few degrees of an earlier one adds little crease length
(docs/studies/roll_side/). For k earlier axes drawn uniformly the novelty has mean 90/(k + 1)
degrees, 45 for the second cycle; the summary gives each seed's novelty per cycle beside that,
and for a set of seeds how often the second roll repeats the first within 10 degrees (1 in 9
for a uniform draw).

usage: seed_roll_axes.py --seeds 1 2 3 [--cycles 10] [-o OUT.csv]
       seed_roll_axes.py --seeds 1-100 --cycles 10 -o OUT.csv
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from roll_axes import angle_between  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
from common import die, write_csv  # noqa: E402

MASK64 = (1 << 64) - 1


class MT19937_64:
    """std::mt19937_64 (the C++ standard's parameters), seeded as its constructor seeds it."""
    N, M = 312, 156

    def __init__(self, seed):
        self.mt = [seed & MASK64]
        for i in range(1, self.N):
            prev = self.mt[-1]
            self.mt.append((6364136223846793005 * (prev ^ (prev >> 62)) + i) & MASK64)
        self.index = self.N

    def _twist(self):
        mt, upper, lower = self.mt, 0xFFFFFFFF80000000, 0x7FFFFFFF
        for i in range(self.N):
            x = (mt[i] & upper) | (mt[(i + 1) % self.N] & lower)
            xa = x >> 1
            if x & 1:
                xa ^= 0xB5026F5AA96619E9
            mt[i] = mt[(i + self.M) % self.N] ^ xa
        self.index = 0

    def __call__(self):
        if self.index >= self.N:
            self._twist()
        y = self.mt[self.index]
        self.index += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        y ^= y >> 43
        return y & MASK64


def drawn_axes(seed, cycles):
    """The roll axes (degrees, [0, 180)) a run of `seed` draws in its first `cycles` cycles."""
    g = MT19937_64(seed)
    out = []
    for _ in range(cycles):
        u = float(g()) / 2.0 ** 64  # libstdc++'s generate_canonical<double> of a 64-bit engine
        if u >= 1.0:
            u = math.nextafter(1.0, 0.0)
        phi = math.pi * u
        out.append(math.fmod(phi * 180.0 / math.pi, 180.0))
    return out


def novelties(axes):
    """Each roll's smallest angle to the axes before it (None for the first)."""
    return [None] + [min(angle_between(a, b) for b in axes[:k]) for k, a in enumerate(axes) if k]


def parse_seeds(items):
    seeds = []
    for it in items:
        try:
            if "-" in it:
                lo, hi = (int(x) for x in it.split("-"))
                seeds += list(range(lo, hi + 1))
            else:
                seeds.append(int(it))
        except ValueError:
            die(f"--seeds: '{it}' is neither a seed nor a range FIRST-LAST")
    if not seeds or min(seeds) < 0:
        die("--seeds: give seeds >= 0")
    return seeds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", nargs="+", required=True, help="seeds, or ranges FIRST-LAST")
    ap.add_argument("--cycles", type=int, default=10, help="cycles (roll stages) per seed")
    ap.add_argument("-o", "--output", help="OUT.csv: seed, cycle, axis, novelty")
    a = ap.parse_args()
    if a.cycles < 1:
        die("--cycles: at least 1")
    seeds = parse_seeds(a.seeds)
    rows = []
    for s in seeds:
        axes = drawn_axes(s, a.cycles)
        for c, (ax, nov) in enumerate(zip(axes, novelties(axes)), start=1):
            rows.append({"seed": s, "cycle": c, "axis_deg": round(ax, 3),
                         "angle_to_earlier_axes_deg": None if nov is None else round(nov, 3),
                         "uniform_mean_deg": None if c == 1 else round(90.0 / c, 3)})
    if a.output:
        write_csv(a.output, rows)
    if len(seeds) <= 12:
        for s in seeds:
            mine = [r for r in rows if r["seed"] == s]
            print(f"seed {s}: axes " + " ".join(f"{r['axis_deg']:.1f}" for r in mine))
            print("  novelty " + " ".join(
                "-" if r["angle_to_earlier_axes_deg"] is None
                else f"{r['angle_to_earlier_axes_deg']:.1f}" for r in mine))
    if a.cycles >= 2:
        second = [r["angle_to_earlier_axes_deg"] for r in rows if r["cycle"] == 2]
        repeats = sum(1 for x in second if x < 10)
        print(f"second roll within 10 degrees of the first: {repeats} of {len(second)} seeds "
              f"(uniform draw: 1 in 9, {len(second) / 9:.1f} expected)")
        for c in range(2, a.cycles + 1):
            nov = [r["angle_to_earlier_axes_deg"] for r in rows if r["cycle"] == c]
            print(f"cycle {c}: mean novelty {sum(nov) / len(nov):.1f} degrees over "
                  f"{len(nov)} seeds (uniform draw: {90.0 / c:.1f})")


if __name__ == "__main__":
    main()
