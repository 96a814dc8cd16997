#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Writes tests/test_times.txt from the times of a whole default run: each
test's seconds, which tests/CMakeLists.txt gives ctest as the test's COST
(so that a fresh build folder, as in CI, starts the long tests first), and
the word quick on the tests labelled quick (`ctest -L quick`, the
edit-build-test loop):

    cd build && ctest -j2 -LE heavy
    /usr/bin/python3 ../tests/scripts/quick_label.py Testing/Temporary/CTestCostData.txt

The rule: every test that took under LIMIT seconds (default 3), and in each
family of tests (the part of the name before the first dot: unit,
three_d, invariance, ...) at least its fastest one, so that every kind of
claim is checked at its smallest size. Left out: the families `threads`
(runs alone, holding both cores) and `benchmarks` (smoke runs of the
benchmark scripts, no claim). A name no longer in the suite is ignored by
tests/CMakeLists.txt; a new test has no cost (ctest then guesses) and is
not quick until the file is written again."""
import argparse
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUTPUT = os.path.normpath(os.path.join(HERE, "..", "test_times.txt"))
LEFT_OUT = ("threads", "benchmarks")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cost_data", help="ctest's Testing/Temporary/CTestCostData.txt")
    parser.add_argument("--limit", type=float, default=3.0, help="seconds (default 3)")
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
        f.write("# Seconds of each test in one `ctest -j2 -LE heavy` run on 2 cores, and the\n"
                "# tests labelled quick (every test under "
                f"{args.limit:g} s and each family's fastest):\n"
                "# written by tests/scripts/quick_label.py.\n")
        for name in sorted(times):
            f.write(f"{name} {times[name]:.1f}{' quick' if name in quick else ''}\n")
    total = sum(times[name] for name in quick)
    print(f"{len(quick)} of {len(times)} tests, {total:.0f} s of the run's "
          f"{sum(times.values()):.0f} s (serial) -> {OUTPUT}")


if __name__ == "__main__":
    main()
