#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The FE part of a 3D model towards 10^6 dofs: the blocks' sparse
factorisation by MUMPS, which every other phase reuses. prm/block_on_plane_3d.prm
with n elements along the plane's length and width and n across each
block's height (compact blocks, where the factors fill in most; the
dofs grow as n^3, the pairs as n^2), the iterative mixed system with the
pairs' preconditioner (so that no dense interface part and no second
factorisation counts), and one contact solve at full strength (Safety
factor/Compute = false: the safety-factor iteration is not what is
measured here). Per block, from the --verbose lines, what MUMPS
reports: the factors' entries, the flops and its memory (used and
estimated by its analysis); from summary.json the factorisation phase,
the whole run and the peak memory.

Sizes whose factorisation would not fit in Geometry/Memory limit (default:
this machine's memory) are refused by the program after MUMPS's analysis,
before anything is allocated for the factors: the row then shows the
analysis's estimate (memory and flops) from the one-line error.

    /usr/bin/python3 benchmarks/factorisation_scaling.py [build/fdem-slope]
        [--levels 16,24,32,42] [--memory-limit MiB]

Prints a Markdown table.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

BLOCK_LINE = re.compile(r"block '([^']*)': MUMPS: factors (\S+) entries.*?, (\S+) flops.*"
                        r"memory (\d+) MB \(estimated (\d+) MB\)")
REFUSED = re.compile(r"matrix of (\d+) dofs would need about (\d+) MiB \(MUMPS's analysis; "
                     r"(\S+) flops\) beside the (\d+) MiB")


def measure(exe, n, memory_limit):
    settings = {"Geometry/Block on plane/Elements along length": n,
                "Geometry/Block on plane/Elements along width": n,
                "Geometry/Block on plane/Elements across height": n,
                "Geometry/Memory limit": memory_limit,
                "Solver/Mixed system": "iterative",
                "Solver/Mixed preconditioner": "pairs",
                "Safety factor/Compute": "false",
                "Safety factor/Stiffness check": "false"}
    result = common.run_case(exe, "block_on_plane_3d.prm", settings, timeout=7200,
                             args=["--verbose"])
    row = {"n": n}
    if result.ok:
        s = result.summary
        blocks = BLOCK_LINE.findall(result.stdout)
        row.update(status="factorised", dofs=s["n_dofs"], pairs=common.n_pairs(s),
                   entries=sum(float(b[1]) for b in blocks),
                   flops=sum(float(b[2]) for b in blocks),
                   used=sum(int(b[3]) for b in blocks),
                   estimated=sum(int(b[4]) for b in blocks),
                   factorisation=s["timings"].get("factorisation"),
                   total=s["timings"].get("total"), peak=s["peak_memory_MiB"])
        return row
    refused = REFUSED.search(result.stderr)
    if not refused:
        sys.exit(f"factorisation_scaling.py: n = {n}: {result.failure()}")
    row.update(status="refused", largest=int(refused.group(1)),
               estimated=float(refused.group(2)) * (1 << 20) / 1e6,
               flops=float(refused.group(3)), held=int(refused.group(4)))
    return row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exe", nargs="?", default=common.DEFAULT_EXE)
    parser.add_argument("--levels", default="16,24,32,42")
    parser.add_argument("--memory-limit", default="0",
                        help="Geometry/Memory limit (MiB; 0: this machine's memory)")
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    rows = []
    for n in (int(x) for x in args.levels.split(",")):
        rows.append(measure(exe, n, args.memory_limit))
        print(f"n = {n}: {rows[-1]}", file=sys.stderr, flush=True)

    def cell(row, key):
        return common.number(row.get(key))
    header = ["n", "status", "dofs", "pairs", "factors' entries", "flops",
              "MUMPS memory used (MB)", "estimated by the analysis (MB)",
              "factorisation (s)", "total (s)", "peak (MiB)"]
    table = []
    for r in rows:
        table.append([r["n"], r["status"] + (f" (block of {r['largest']} dofs)"
                                             if r["status"] == "refused" else ""),
                      cell(r, "dofs"), cell(r, "pairs"), f"{r['entries']:.3g}" if "entries" in r
                      else "–", f"{r['flops']:.3g}", cell(r, "used"), cell(r, "estimated"),
                      cell(r, "factorisation"), cell(r, "total"), cell(r, "peak")])
    print("\n".join(common.markdown_table(header, table, "rlrrrrrrrrr")))
    done = [r for r in rows if r["status"] == "factorised" and r.get("factorisation")]
    if len(done) >= 2:
        print(f"\nFactorisation time grows as dofs^"
              f"{common.fit_exponent([r['dofs'] for r in done], [r['factorisation'] for r in done]):.2f}, "
              f"the factors' entries as dofs^"
              f"{common.fit_exponent([r['dofs'] for r in done], [r['entries'] for r in done]):.2f}, "
              f"the flops as dofs^"
              f"{common.fit_exponent([r['dofs'] for r in done], [r['flops'] for r in done]):.2f}; "
              f"flop rate {done[-1]['flops'] / done[-1]['factorisation'] / 1e9:.1f} GFlop/s "
              f"at the largest.")


if __name__ == "__main__":
    main()
