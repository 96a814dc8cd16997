#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Writes tests/quick_tests.txt, the tests labelled quick (`ctest -L quick`,
the edit-build-test loop), from the times of a whole default run:

    cd build && ctest -j2 -LE heavy
    /usr/bin/python3 ../tests/scripts/quick_label.py Testing/Temporary/CTestCostData.txt

The rule: every test that took under LIMIT seconds (default 4), and in each
family of tests (the part of the name before the first dot: unit,
three_d, invariance, ...) at least its fastest one, so that every kind of
claim is checked at its smallest size. Left out: the families `threads`
(runs alone, holding both cores) and `benchmarks` (smoke runs of the
benchmark scripts, no claim). tests/CMakeLists.txt reads the file; a name
no longer in the suite is ignored there."""
import argparse
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUTPUT = os.path.join(HERE, "..", "quick_tests.txt")
LEFT_OUT = ("threads", "benchmarks")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cost_data", help="ctest's Testing/Temporary/CTestCostData.txt")
    parser.add_argument("--limit", type=float, default=4.0, help="seconds (default 4)")
    args = parser.parse_args()
    times = {}
    with open(args.cost_data) as f:
        for line in f:
            if line.startswith("---"):
                break
            name, _, cost = line.split()
            times[name] = float(cost)
    families = {}
    for name, seconds in times.items():
        family = name.split(".")[0]
        if family not in LEFT_OUT:
            families.setdefault(family, []).append((seconds, name))
    quick = {name for tests in families.values() for seconds, name in tests
             if seconds < args.limit}
    quick |= {min(tests)[1] for tests in families.values()}
    with open(OUTPUT, "w") as f:
        f.write("# The tests labelled quick: written by tests/scripts/quick_label.py\n"
                f"# (every test under {args.limit:g} s and each family's fastest).\n")
        for name in sorted(quick):
            f.write(name + "\n")
    total = sum(times[name] for name in quick)
    print(f"{len(quick)} of {len(times)} tests, {total:.0f} s of the run's "
          f"{sum(times.values()):.0f} s (serial) -> {OUTPUT}")


if __name__ == "__main__":
    main()
