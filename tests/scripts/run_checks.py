#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Checks that run the fdem-slope executable as a user would.

  run_checks.py vtu EXE CASE.prm [simplex]
                                         run the case; read every VTU file of
                                         its PVD back with VTK and check fields;
                                         with 'simplex', every cell must be a
                                         line, triangle or tetrahedron
  run_checks.py parameters-doc EXE DOC.md [--write]
                                         doc/parameters.md must be what
                                         --print-parameters prints (--write
                                         regenerates it)
  run_checks.py no-equilibrium EXE CASE.prm
                                         the case has no static equilibrium:
                                         exit code 3, one line on stderr, a
                                         summary.json that says why, and no
                                         result files that look valid
  run_checks.py deterministic EXE CASE.prm
                                         two runs give the same summary.json,
                                         byte for byte, timings and
                                         peak memory aside
  run_checks.py threads EXE CASE.prm [SETTING=VALUE ...]
                                         the case with 2 BLAS threads twice and
                                         with 1 (OPENBLAS_NUM_THREADS): the
                                         two-thread runs alike byte for byte,
                                         summary.json's n_blas_threads as set,
                                         and the one-thread run the same steps
                                         and statuses, K to 1e-10 relative;
                                         without the variable one thread,
                                         also per rank under mpirun -np 2
  run_checks.py wedge EXE CASE.prm [TOL] [SHARE]
                                         a rock wedge (Geometry/Source = wedge):
                                         K must match the vector limit
                                         equilibrium of wedge_reference.py
                                         (weight and plane areas from the
                                         run's summary) to TOL relative
                                         (default 1e-5); where a plane lifts
                                         off, it must carry under SHARE
                                         (default 0.05) of the normal force
  run_checks.py wedge-fold EXE CASE.prm [TOL]
                                         a rock wedge sliding on both planes,
                                         no cohesion: sqrt(K* - K) of three
                                         solves 1e-4 to 1.6e-5 below the limit
                                         equilibrium, extrapolated to zero,
                                         must be that limit to TOL relative
                                         (default 1e-8)
  run_checks.py wedge-slope EXE CASE.prm [TOL]
                                         the same wedge: the slope of K* a
                                         step computes 1e-3 and 1e-4 below
                                         the limit against the slope between
                                         full solves 10 % of the distance
                                         either side, to TOL relative to
                                         slope - 1 (default 1e-2)
  run_checks.py plane-strain EXE CASE.prm CASE_2D.prm [REFERENCE.prm TOL]
                                         a 2D model extruded along z with
                                         rollers on its ends: both certified,
                                         the same K to 2e-6 relative and the
                                         2D statuses once per node plane; with
                                         REFERENCE (2D, another mesh of the
                                         section), K within TOL of its K
  run_checks.py plane-strain-contact EXE CASE.prm CASE_2D.prm WIDTH TOL
                                         one contact solve at full strength
                                         of a 3D model of WIDTH with rollers
                                         on its sides and of its 2D section:
                                         both converge, the 3D total normal
                                         force per unit width within TOL of
                                         the 2D one
  run_checks.py mpi EXE CASE.prm [N]     the case serially and with
                                         `mpirun -np N` (default 2) in separate
                                         folders: the same safety factor to
                                         1e-10 relative, one screen, the same output
                                         files with the same number of cells
  run_checks.py invariance EXE REF.prm OTHER.prm...
                                         the same model in other units or
                                         with another common Young's modulus:
                                         every run completes with the same K
                                         as REF to 1e-8 relative, the same
                                         safety-factor steps (contact result
                                         and stick/slip/open counts of each)
                                         and the same final statuses of every
                                         interface
  run_checks.py modulus-scale EXE CASE.prm SOLVER BLOCK1,BLOCK2 E_REF E...
                                         the Young's modulus of the blocks
                                         set to E_REF, then to each E, with
                                         Solver/Direct solver = SOLVER: the
                                         same as invariance (1e-8, steps,
                                         statuses)
  run_checks.py fe-stress EXE CASE.prm K0 [PATH=VALUE...]
                                         from Initial factor K0 (and the
                                         entries PATH set to VALUE), the
                                         first step sticks everywhere and
                                         its K* is the FE-stress factor
  run_checks.py mesh-convergence EXE CASE.prm H1,H2,... TOL
                                         the slope case at each
                                         Geometry/Slope/Mesh size H: every run
                                         certified, and the largest K over the
                                         smallest within TOL relative
  run_checks.py reference-factor EXE CASE.prm REF.prm TOL [stiffness-dependent]
                                         both certified, not stiffness-
                                         dependent, their K within TOL (or
                                         both stiffness-dependent, and K and
                                         the stiffness check's two K each
                                         within TOL)
  run_checks.py block-low-rank EXE CASE.prm TOL
                                         the case (which sets Solver/Block
                                         low-rank tolerance) and the same
                                         case full rank (tolerance 0): both
                                         complete, their K within TOL
                                         relative; the low-rank run's log
                                         reports MUMPS's compression and
                                         the full-rank run's does not
  run_checks.py undrained-sphere EXE CASE.prm XC,YC,ZC R C GAMMA TOL [TERRAIN [WATER GAMMA_SAT]]
                                         certified, and within TOL of the
                                         exact phi = 0 K of the sphere
                                         (undrained_sphere.py; under the
                                         grid TERRAIN,
                                         undrained_sphere_terrain.py, with
                                         GAMMA_SAT below the water table
                                         grid WATER), and the same turned
  run_checks.py undrained-ellipsoid EXE CASE.prm XC,YC,ZC R B C GAMMA TOL [L]
                                         certified, and within TOL of the
                                         exact phi = 0 K of the spheroid,
                                         or of the capsule of straight
                                         length L (undrained_sphere.py, 320
                                         points)
  run_checks.py bad-input EXE BAD.prm    the run must fail with one line on
                                         stderr containing the text of the
                                         file's '# expect:' line, a non-zero
                                         exit, and no summary.json
  run_checks.py bad-layout EXE BAD.prm   as bad-input, and `--validate` must
                                         fail with the same line
  run_checks.py triple-point EXE CASE.prm
                                         blocks meeting at a point: the run
                                         completes, the one pair that closes
                                         the loop there is left out (log), and
                                         the last solved K* is within 1e-3 of K

Placeholders in a .prm: @PRM_DIR@ (the project's prm/ folder) and @DATA_DIR@
(the .prm file's own data/ folder) become absolute paths, in included files
too; the case runs in a fresh temporary folder (tools/fdem_run.py).
"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402  tools/fdem_run.py: run a case, read its outputs


def completed_run(exe, prm, **kwargs):
    """The run of @p prm in a temporary folder (see fdem_run.run_case),
    which must succeed."""
    result = fdem_run.run_case(exe, prm, **kwargs)
    assert result.returncode == 0, result.stderr
    assert result.summary is not None, "no summary.json"
    return result


# VTK cell types of simplices: line, triangle, tetrahedron, and their
# quadratic forms.
VTK_SIMPLEX_CELLS = {3, 5, 10, 21, 22, 24}


def check_vtu(exe, prm, cells="any"):
    import csv
    import vtk  # Debian's python3-vtk9
    from vtk.util.numpy_support import vtk_to_numpy

    with fdem_run.temporary_run(exe, prm) as result:
        assert result.returncode == 0, result.stderr
        summary = result.summary
        assert summary["status"] == "completed"

        def listed(pvd_name):
            pvd = open(result.file(pvd_name)).read()
            return [part.split('"')[0] for part in pvd.split('file="')[1:]]

        files = listed("solution.pvd")
        expected_blocks = {b["name"] for b in summary["blocks"]}
        expected_interfaces = {i["name"] for i in summary["interfaces"]}
        assert len(files) == len(expected_blocks) + len(expected_interfaces), files
        # The steps file lists one set of files per safety-factor step with a
        # static solution if they were written (Output/Write steps), else the
        # final state's (tests/scripts/paraview_checks.py checks both).
        if "iterations" in summary:
            steps = listed("safety_factor_steps.pvd")
            n_static = sum(1 for s in summary["iterations"] if s["contact_result"] == "converged")
            if steps == files:
                assert not [f for f in os.listdir(result.output) if "-step" in f]
            else:
                assert len(steps) == n_static * len(files), (len(steps), n_static)
                files += steps
        block_fields = ["displacement", "stress", "stress_zz"]
        interface_fields = ["normal_force", "tangential_force", "normal_pressure",
                            "shear_stress", "gap", "slip", "status", "local_safety_factor"]
        for name in files:
            r = vtk.vtkXMLUnstructuredGridReader()
            r.SetFileName(result.file(name))
            r.Update()
            grid = r.GetOutput()
            assert grid.GetNumberOfPoints() > 0 and grid.GetNumberOfCells() > 0, name
            if cells == "simplex":
                types = {grid.GetCellType(c) for c in range(grid.GetNumberOfCells())}
                assert types <= VTK_SIMPLEX_CELLS, f"{name}: cells of VTK types {types}"
            fields = block_fields if name.startswith("block-") else interface_fields
            data = grid.GetPointData()
            if name.startswith("block-"):
                assert grid.GetCellData().GetArray("block_id") is not None, f"{name}: no block_id"
                at = slice(None)
            else:
                # The pair fields are NaN at nodes that are no pair (status 3, 4).
                at = vtk_to_numpy(data.GetArray("status")) <= 2
                assert at.any(), f"{name}: no node pair"
            for field in fields:
                array = data.GetArray(field)
                assert array is not None, f"{name}: no field '{field}'"
                values = vtk_to_numpy(array)[at]
                assert values.size > 0 and all(math.isfinite(v) for v in values.ravel()), \
                    f"{name}: '{field}' is empty or not finite"
            print(f"{name}: {grid.GetNumberOfPoints()} points, fields {', '.join(fields)}")
        # The interface VTU carries the same normal forces as the CSV table.
        rows = list(csv.DictReader(open(result.file("interfaces.csv"))))
        csv_total = sum(float(r["normal_force"]) for r in rows)
        json_total = sum(i["total_normal_force"] for i in summary["interfaces"])
        assert abs(csv_total - json_total) <= 1e-9 * abs(json_total), (csv_total, json_total)


def check_bad_input(exe, prm):
    """The run fails with one line holding the '# expect:' text, and writes
    no summary.json; with '# validate: same', --validate fails with the same
    line (it reads every file the run would read)."""
    expect, validate = None, False
    for line in open(prm):
        if line.startswith("# expect:"):
            expect = line[len("# expect:"):].strip()
        validate = validate or line.strip() == "# validate: same"
    assert expect, f"{prm} has no '# expect:' line"
    runs = [[], ["--validate"]] if validate else [[]]
    stderr = []
    for args in runs:
        with fdem_run.temporary_run(exe, prm, args=args) as result:
            lines = result.stderr.strip().splitlines()
            print(" ".join(args + ["stderr:"]), result.stderr.strip())
            assert result.returncode != 0, "the run did not fail"
            assert result.returncode < 128, f"the run crashed (exit {result.returncode})"
            assert len(lines) == 1, f"expected one line on stderr, got {len(lines)}"
            assert lines[0].startswith("fdem-slope: error: "), lines[0]
            assert expect in lines[0], f"'{expect}' not in the message"
            for root, _, files in os.walk(result.workdir):
                assert "summary.json" not in files, "a summary.json was written"
            stderr.append(result.stderr)
    assert len(set(stderr)) == 1, "--validate and the run say different things"


def check_bad_layout(exe, prm):
    check_bad_input(exe, prm)
    full = fdem_run.run_case(exe, prm)
    with fdem_run.temporary_run(exe, prm, args=["--validate"]) as result:
        print("--validate stderr:", result.stderr.strip())
        assert result.returncode == 1, f"--validate exit {result.returncode}, expected 1"
        assert result.stderr == full.stderr, "--validate and the run say different things"
        # Nothing in the folder but the .prm files that fdem_run filled in.
        prepared = {os.path.basename(result.prm), fdem_run.INCLUDED}
        assert set(os.listdir(result.workdir)) <= prepared, "--validate wrote files"


def check_triple_point(exe, prm):
    import re
    result = fdem_run.run_case(exe, prm, args=["--validate"])
    assert result.returncode == 0 and result.stdout.strip().endswith("valid."), result.stderr
    # The pairs left out and made are in the full log (--verbose's screen).
    result = completed_run(exe, prm, args=["--verbose"])
    left_out = [l for l in result.stdout.splitlines() if "is left out" in l]
    print("\n".join(left_out))
    assert len(left_out) == 1, f"{len(left_out)} pairs left out, expected 1"
    made = {m.group(1): int(m.group(2)) for m in
            re.finditer(r"interface '([^']*)': (\d+) node pairs", result.stdout)}
    summary = result.summary
    assert summary["status"] == "completed" and summary["converged"], summary["status"]
    # The only judgement allowed: the limit is a bracket whose K* exceeds K
    # a little (equilibrium lost before K reaches K*), K the conservative
    # value (doc/theory.md, "The certificate").
    assert all("conservative value" in w for w in summary["warnings"]), summary["warnings"]
    name = re.match(r"\s*interface '([^']*)'", left_out[0]).group(1)
    pairs = {i["name"]: i["n_pairs"] for i in summary["interfaces"]}
    for interface, n in made.items():
        assert pairs[interface] == n - (interface == name), (interface, n, pairs)
    K = summary["safety_factor"]
    solved = [s for s in summary["iterations"] if s["K"] <= K and s["F_tau"] > 0]
    step = max(solved, key=lambda s: s["K"])
    K_star = step["F_R"] / step["F_tau"] * step["K"]
    print(f"K = {K}, last solved K = {step['K']}, its K* = {K_star}")
    assert abs(K_star - step["K"]) < 1e-3 * K and abs(step["K"] - K) < 1e-3 * K


def check_no_equilibrium(exe, prm):
    with fdem_run.temporary_run(exe, prm) as result:
        lines = result.stderr.strip().splitlines()
        print("stderr:", result.stderr.strip())
        assert result.returncode == 3, f"exit code {result.returncode}, expected 3"
        assert len(lines) == 1 and "no static equilibrium" in lines[0], lines
        summary = result.summary
        assert summary is not None, "no summary.json"
        assert summary["status"].startswith("no static equilibrium"), summary["status"]
        assert summary["contact"]["converged"] is False
        for name in os.listdir(result.output):
            assert not name.endswith((".vtu", ".pvd", ".csv")), f"{name} was written"


def check_certified(exe, prm, warning="no-warning"):
    """The reported K carries a certificate whose numbers hold: a solved
    step of the iteration at the certificate's K with its K*, |K* - K| / K
    within the tolerance, and the safety factor that K* (fixed point) or K
    (bracket). The stiffness check: a warning, and a relative change above
    the warning threshold, exactly when `warning` is "warning"."""
    summary = completed_run(exe, prm).summary
    c = summary["certificate"]
    print("certificate:", json.dumps(c))
    print("stiffness_sensitivity:", json.dumps(summary["stiffness_sensitivity"]))
    assert summary["converged"] and c["holds"], c
    K, K_star, tolerance = c["K"], c["K_star"], c["tolerance"]
    assert abs(K_star - K) <= tolerance * K, (K, K_star)
    steps = [s for s in summary["iterations"] if s["K"] == K and s["K_star"] == K_star]
    assert steps, "no step of the iteration has the certificate's K and K*"
    reported = K_star if c["kind"] == "fixed point" else K
    assert summary["safety_factor"] == reported, (summary["safety_factor"], reported)
    if c["kind"] == "bracket":
        # The step above: no static solution, or a limit state (every pair
        # slipping, K* = K to the 1e-10 of sliding_forces.cc's test).
        failed = [s for s in summary["iterations"] if s["K"] == c["K_failed"]]
        assert failed and (failed[0]["K_star"] is None or
                           ("limit state" in c["failure"] and
                            abs(failed[0]["K_star"] / failed[0]["K"] - 1) <= 1e-10)), \
            "no failed step at K_failed"
        assert c["K_failed"] - K <= tolerance * K
    check = summary["stiffness_sensitivity"]
    assert check["computed"], check["not_computed"]
    change = check["relative_change"]
    # "not certified" when K could not be certified with the blocks scaled.
    large = isinstance(change, str) or change > 0.01
    warned = any("stiffness" in w for w in summary["warnings"])
    if warning == "warning":
        assert warned and large, (change, summary["warnings"])
    else:
        assert not warned and not large, (change, summary["warnings"])


def check_fe_stress(exe, prm, initial_factor, *settings):
    """The FE-stress factor is the iteration's first K* when its first step
    ends with every pair stuck: a step in stick has the rows of the all-stick
    state whatever the strengths, and eq. (11) at K0 gives K0 F_R(K0) / F_tau
    = sum (c A - mu f_n) / F_tau. @p initial_factor must be small enough for
    the first step to stick everywhere (the check asserts that it does).
    1e-9 relative: the two solves have the same rows and differ only in
    how the factors are reached (measured 7e-16)."""
    overrides = {"Safety factor/Initial factor": initial_factor}
    overrides.update(setting.split("=", 1) for setting in settings)
    summary = completed_run(exe, prm, settings=overrides).summary
    fe = summary["fe_stress_factor"]
    first = summary["iterations"][0]
    print("fe_stress_factor:", json.dumps(fe))
    print("first step:", json.dumps(first))
    assert fe["computed"] and fe["factor"] > 0, fe
    assert first["n_slip"] == 0 and first["n_open"] == 0, "the first step did not stick everywhere"
    difference = abs(first["K_star"] - fe["factor"]) / fe["factor"]
    print(f"relative difference {difference:.2e}")
    assert difference <= 1e-9, (first["K_star"], fe["factor"])


def check_stiffness_consistency(exe, prm, stiffer_prm, softer_prm):
    """The stiffness check of @p prm against fresh runs: its K_stiffer and
    K_softer must be the K of @p stiffer_prm and @p softer_prm (the moving
    blocks' E times and divided by the factor) to 1e-9 relative: C and g_bar
    are linear in the blocks' compliance, so the check solves the very
    same problems up to round-off (measured: see tests/CMakeLists.txt)."""
    check = completed_run(exe, prm).summary["stiffness_sensitivity"]
    for key, path in (("K_stiffer", stiffer_prm), ("K_softer", softer_prm)):
        K = completed_run(exe, path).summary["safety_factor"]
        print(f"{key}: check {check[key]!r}, fresh run {K!r}, relative difference {abs(check[key] - K) / K:.2e}")
        assert abs(check[key] - K) <= 1e-9 * K, (key, check[key], K)


def check_mesh_convergence(exe, prm, sizes, tolerance):
    """K of the slope case @p prm at each mesh size of @p sizes (comma
    separated, Geometry/Slope/Mesh size): each run certified, and all K
    within @p tolerance of each other (max / min - 1). No VTU or report: only
    K is compared."""
    Ks = []
    for h in sizes.split(","):
        summary = completed_run(exe, prm, settings={"Geometry/Slope/Mesh size": h,
                                                    "Output/Report": "false"}).summary
        assert summary["converged"] and summary["certificate"]["holds"], summary["certificate"]
        Ks.append(summary["safety_factor"])
        print(f"mesh size {h}: {summary['n_dofs']} dofs, K = {Ks[-1]!r}, "
              f"stiffness check {summary['stiffness_sensitivity']['relative_change']!r}")
    spread = max(Ks) / min(Ks) - 1
    print(f"spread of K (max / min - 1): {spread:.2e}, tolerance {tolerance}")
    assert spread <= float(tolerance), (Ks, spread)


def check_deterministic(exe, prm):
    # Wall times and peak memory differ from run to run; nothing else may.
    texts = [json.dumps(fdem_run.result_part(completed_run(exe, prm).summary), sort_keys=True)
             for _ in range(2)]
    assert texts[0] == texts[1], "two runs of the same input differ"


def check_threads(exe, prm, *settings):
    """The BLAS's threads (doc/theory.md, "Threads"): with OpenBLAS's
    threads the dense solves split their products between the cores, which
    reorders sums inside a product. OpenBLAS does not promise that the order
    is the same from run to run (it was on most machines; not on one where
    OPENBLAS_CORETYPE was set), so what is checked is what round-off
    allows: two runs with 2 threads and a run with 1 thread take the same
    steps to the same statuses and K to 1e-10 relative, the round-off of
    the LU's sums carried through about a hundred status iterations
    (measured 2.3e-13 between 1 and 2 threads on prm/slope_3d.prm at Mesh
    size 1.25 m)."""
    settings = dict(s.split("=", 1) for s in settings)

    def run(n_threads):
        environment = dict(os.environ, OPENBLAS_NUM_THREADS=str(n_threads))
        summary = completed_run(exe, prm, settings=settings, env=environment).summary
        assert summary["n_blas_threads"] == n_threads, (
            f"OPENBLAS_NUM_THREADS={n_threads}, but summary.json says "
            f"{summary['n_blas_threads']} BLAS threads (0: not OpenBLAS; bootstrap.sh "
            "installs libopenblas0-pthread)")
        assert summary["converged"], summary["certificate"]
        return summary

    two = [run(2), run(2)]
    one = run(1)
    K1 = one["safety_factor"]
    steps_one = [(s["n_stick"], s["n_slip"], s["n_open"]) for s in one["iterations"]]
    for label, summary in (("first", two[0]), ("second", two[1])):
        K2 = summary["safety_factor"]
        print(f"K with 2 threads ({label} run) {K2!r}, with 1 thread {K1!r}: "
              f"relative difference {K2 / K1 - 1:.2e} (tolerance 1e-10)")
        assert abs(K2 / K1 - 1) <= 1e-10, (label, K2, K1)
        steps = [(s["n_stick"], s["n_slip"], s["n_open"]) for s in summary["iterations"]]
        assert steps == steps_one, (label, steps, steps_one)
    # With neither variable set, one thread (per rank under mpirun).
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")}
    environment.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    for launcher in ([], ["mpirun", "-np", "2", "--oversubscribe"]):
        unset = completed_run(exe, prm, settings=settings, env=environment,
                              launcher=launcher).summary
        assert unset["n_blas_threads"] == 1, (launcher, unset["n_blas_threads"])


def check_plane_strain(exe, prm, prm_2d, reference=None, tolerance=None):
    """The plane-strain limit: @p prm, a 2D model (@p prm_2d) extruded along
    z with rollers on both ends, gives the 2D model's K, both certified.
    The 2D solution, constant along z, solves the discrete 3D model exactly
    when the 3D mesh is the 2D mesh extruded (the elements along z hold
    constants); so the two K differ only by the iteration's stopping:
    each is certified to Safety factor/Tolerance (1e-6 relative), and
    2e-6 allows both ends of that. The statuses of the certified state are
    the 2D ones once per node plane along z. With @p reference, another 2D
    model of the same section (the slope generator's mesh), K must also lie
    within @p tolerance of its K: the 2D discretisation error, measured
    over meshes (doc/verification.md)."""
    runs = {}
    for name, path in (("3D", prm), ("2D", prm_2d)) + ((("reference", reference),) if reference else ()):
        summary = completed_run(exe, path).summary
        assert summary["converged"] and summary["certificate"]["holds"], (name, summary["certificate"])
        c = summary["certificate"]
        state = [s for s in summary["iterations"] if s["K"] == c["K"] and s["K_star"] == c["K_star"]][-1]
        runs[name] = (summary, state)
        print(f"{name}: dimension {summary['dimension']}, {summary['n_dofs']} dofs, "
              f"{summary['interfaces'][0]['n_pairs']} pairs, K = {summary['safety_factor']!r} "
              f"({len(summary['iterations'])} steps); certified state: {state['n_stick']} stick, "
              f"{state['n_slip']} slip, {state['n_open']} open, F_R = {state['F_R']!r}")
    (s3, state3), (s2, state2) = runs["3D"], runs["2D"]
    assert s3["dimension"] == 3 and s2["dimension"] == 2
    K3, K2 = s3["safety_factor"], s2["safety_factor"]
    print(f"3D against 2D: relative difference {K3 / K2 - 1:.2e} (tolerance 2e-6)")
    assert abs(K3 / K2 - 1) <= 2e-6, (K3, K2)
    planes, rest = divmod(s3["interfaces"][0]["n_pairs"], s2["interfaces"][0]["n_pairs"])
    assert rest == 0, "the 3D pairs are not the 2D pairs once per node plane"
    for status in ("n_stick", "n_slip", "n_open"):
        assert state3[status] == planes * state2[status], (status, state3[status], state2[status])
    if reference:
        K_ref = runs["reference"][0]["safety_factor"]
        print(f"3D against the reference: relative difference {K3 / K_ref - 1:.2e} (tolerance {tolerance})")
        assert abs(K3 / K_ref - 1) <= float(tolerance), (K3, K_ref)


def certified_run(exe, prm, stiffness_dependent=False):
    """The run of @p prm, whose K must be certified (a fixed point or a
    bracket) and not stiffness-dependent (or, with @p stiffness_dependent,
    must be: the check's warning and both of its K); its summary."""
    summary = completed_run(exe, prm).summary
    c = summary["certificate"]
    assert summary["converged"] and c["holds"], c
    check = summary["stiffness_sensitivity"]
    print(f"{os.path.basename(prm)}: {summary['n_dofs']} dofs, "
          f"{summary['interfaces'][0]['n_pairs']} pairs, K = {summary['safety_factor']!r} "
          f"({c['kind']}, {len(summary['iterations'])} steps), stiffness change "
          f"{check['relative_change']!r} (K stiffer {check['K_stiffer']!r}, "
          f"softer {check['K_softer']!r})")
    warned = any("stiffness" in w for w in summary["warnings"])
    assert warned == stiffness_dependent, summary["warnings"]
    if stiffness_dependent:
        assert check["K_stiffer"] is not None and check["K_softer"] is not None, check
    return summary


def check_reference_factor(exe, prm, reference_prm, tolerance, stiffness=None):
    """@p prm and @p reference_prm (another model of the same slope: the 2D
    section of a plane-strain case) both certified, their K within
    @p tolerance relative. With @p stiffness = "stiffness-dependent" both
    must warn that K depends on the sliding mass's stiffness, and the two
    models must then agree also with the moving blocks stiffer and softer:
    the same elastic model in 3D and in its section has the same K at each
    stiffness, so a plane-strain comparison holds for all three."""
    assert stiffness in (None, "stiffness-dependent"), stiffness
    dependent = stiffness is not None
    runs = [certified_run(exe, p, dependent) for p in (prm, reference_prm)]
    keys = ["safety_factor"] + (["K_stiffer", "K_softer"] if dependent else [])
    for key in keys:
        K, K_ref = (r["safety_factor"] if key == "safety_factor" else
                    r["stiffness_sensitivity"][key] for r in runs)
        print(f"{key}: {K!r} against {K_ref!r}, relative difference "
              f"{K / K_ref - 1:.2e} (tolerance {tolerance})")
        assert abs(K / K_ref - 1) <= float(tolerance), (key, K, K_ref)


def check_block_low_rank(exe, prm, tolerance):
    """MUMPS's block low-rank factorisation ("Solver/Block low-rank
    tolerance" set in @p prm) against the full-rank one of the same case:
    the approximate factors move K by less than @p tolerance relative. The
    low-rank run's log must show MUMPS's low-rank statistics (its "after
    low-rank compression" line per block), so that the test compares two
    different factorisations, not the same one twice."""
    runs = {}
    for name, settings in (("low-rank", None),
                           ("full rank", {"Solver/Block low-rank tolerance": "0"})):
        with fdem_run.temporary_run(exe, prm, settings=settings) as result:
            assert result.returncode == 0, result.stderr
            assert result.summary is not None, "no summary.json"
            log = open(result.file("log.txt")).read()
            runs[name] = (result.summary, log)
    (low, low_log), (full, full_log) = runs["low-rank"], runs["full rank"]
    compressed = [line.strip() for line in low_log.splitlines()
                  if "after low-rank compression" in line]
    print("\n".join(compressed))
    assert compressed, "the low-rank run's log reports no compression"
    assert "after low-rank compression" not in full_log, "the full-rank run compressed"
    assert low["converged"] and full["converged"], (low["certificate"], full["certificate"])
    K, K_full = low["safety_factor"], full["safety_factor"]
    print(f"K low-rank {K!r}, full rank {K_full!r}: relative difference "
          f"{K / K_full - 1:.2e} (tolerance {tolerance})")
    assert abs(K / K_full - 1) <= float(tolerance), (K, K_full)


def check_undrained_sphere(exe, prm, centre, radius, cohesion, unit_weight, tolerance, terrain=None,
                           water=None, saturated_unit_weight=None):
    """@p prm, a slope on a sphere with phi = 0, certified and within
    @p tolerance of the exact K of the rigid mass turning about the
    sphere's axis (undrained_sphere.py), or under the terrain grid
    @p terrain about the axis of least K (undrained_sphere_terrain.py,
    40 points per piece: 20 to 80 agree within 3e-7), with the unit weight
    @p saturated_unit_weight below the water table grid @p water if given.
    The same model turned by 30
    degrees about (1, 2, 3) (Geometry/Rotation, gravity turned with it:
    the pairs' exact normals turn with the mesh) takes the same steps to
    the same K, to 1e-8 as the invariance tests. It did not while the
    sliding direction came from the solve's rigid unknowns W gamma, whose
    gauge (the blocks' support dofs) depends on the frame: K* = 1.0306
    against 1.0198 at K = 1, 20 against 11 steps, 1.8e-7 apart
    (doc/theory.md, "The sliding force")."""
    import undrained_sphere  # noqa: E402
    import undrained_sphere_terrain  # noqa: E402
    summary = certified_run(exe, prm)
    K = summary["safety_factor"]
    centre = tuple(map(float, centre.split(",")))
    if terrain:
        exact, axis = undrained_sphere_terrain.undrained_sphere_terrain_factor(
            terrain, centre, float(radius), float(cohesion), float(unit_weight),
            water=water, gamma_sat=float(saturated_unit_weight) if water else None)
        print(f"axis of the exact turn {axis}")
    else:
        exact = undrained_sphere.undrained_sphere_factor(centre, float(radius), float(cohesion),
                                                         float(unit_weight))
    print(f"exact {exact!r}; relative difference {K / exact - 1:.2e} (tolerance {tolerance})")
    assert abs(K / exact - 1) <= float(tolerance), (K, exact)
    compare_turned(exe, prm, summary)


def compare_turned(exe, prm, summary, settings=None):
    """The run of @p prm with @p settings turned by 30 degrees about
    (1, 2, 3) (Geometry/Rotation; the gravity direction, (0, 0, -1) unless
    set, turned with it) against @p summary, the run as it is: the same
    safety-factor steps (statuses, and which solves converged) and K to
    1e-8 relative, as the unit and stiffness invariance tests ask."""
    import numpy as np  # noqa: E402  /usr/bin/python3
    settings = dict(settings or {})
    axis, angle = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0), np.radians(30.0)
    cross = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    rotation = np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross
    gravity = np.array([float(g) for g in
                        settings.get("Loads/Gravity direction", "0, 0, -1").split(",")])
    turned = completed_run(exe, prm, settings={
        **settings, "Geometry/Rotation angle": "30", "Geometry/Rotation axis": "1, 2, 3",
        "Loads/Gravity direction": ", ".join(repr(float(g)) for g in rotation @ gravity)}).summary
    K = summary["safety_factor"]
    print(f"turned: K = {turned['safety_factor']!r} ({len(turned['iterations'])} steps, "
          f"{len(summary['iterations'])} unturned), relative difference "
          f"{turned['safety_factor'] / K - 1:.2e} (tolerance 1e-8)")
    assert turned["converged"] == summary["converged"], turned["certificate"]
    assert turned["certificate"]["holds"] == summary["certificate"]["holds"]

    # Statuses and whether each solve converged; not why a solve failed:
    # far beyond the limit (the wedge at K = 1) "runaway" and "no
    # rigid-mode equilibrium" both say "a mechanism", and which test sees
    # it first is round-off.
    def path(s):
        return [(i["n_stick"], i["n_slip"], i["n_open"], i["contact_result"] == "converged")
                for i in s["iterations"]]
    assert path(turned) == path(summary), (path(turned), path(summary))
    assert abs(turned["safety_factor"] / K - 1) <= 1e-8, (turned["safety_factor"], K)


def check_turned(exe, prm, *assignments):
    """@p prm (with the entries PATH=VALUE of @p assignments) certified, and
    the same run turned (compare_turned()). K must not depend on the frame:
    every decision of the program is taken on quantities that turn with
    the model (doc/theory.md, "The sliding force", for the one that did
    not)."""
    settings = dict(a.split("=", 1) for a in assignments)
    summary = completed_run(exe, prm, settings=settings).summary
    assert summary["converged"] and summary["certificate"]["holds"], summary["certificate"]
    print(f"{os.path.basename(prm)}: K = {summary['safety_factor']!r} "
          f"({len(summary['iterations'])} steps)")
    compare_turned(exe, prm, summary, settings)


def check_undrained_ellipsoid(exe, prm, centre, radius, half_length, cohesion, unit_weight, tolerance,
                              straight_length="0"):
    """@p prm, a slope on a spheroid (semi-axes @p radius in x and z,
    @p half_length along y, its axis of revolution), or on a capsule (its
    halves apart by @p straight_length, a cylinder between), with phi = 0,
    certified and within @p tolerance of the exact K of the rigid mass
    turning about that axis, the surface's only rigid mechanism
    (undrained_sphere.py with 320 points in y; 160, 320 and 640 points
    agree within 8.3e-7 on the spheroid, 5.2e-7 on the capsule)."""
    import undrained_sphere  # noqa: E402
    K = certified_run(exe, prm)["safety_factor"]
    exact = undrained_sphere.undrained_sphere_factor(
        tuple(map(float, centre.split(","))), float(radius), float(cohesion), float(unit_weight),
        n=320, b=float(half_length), straight=float(straight_length))
    print(f"exact {exact!r}; relative difference {K / exact - 1:.2e} (tolerance {tolerance})")
    assert abs(K / exact - 1) <= float(tolerance), (K, exact)


def check_plane_strain_contact(exe, prm, prm_2d, width, tolerance):
    """One contact solve at full strength (Safety factor/Compute = false)
    of @p prm, a 3D model of @p width (m) along the axis of a cylindrical
    sliding surface with rollers on its sides, and of @p prm_2d, its
    section in 2D: both converge, and the 3D interface's total normal
    force per unit width is the 2D one within @p tolerance (relative), the
    discretisation error of the 2D total measured over meshes
    (doc/verification.md)."""
    totals = []
    for path in (prm, prm_2d):
        summary = completed_run(exe, path, settings={"Safety factor/Compute": "false",
                                                     "Output/Report": "false"}).summary
        assert summary["status"] == "completed", summary["status"]
        interface = summary["interfaces"][0]
        totals.append(interface["total_normal_force"])
        print(f"dimension {summary['dimension']}: {summary['n_dofs']} dofs, {interface['n_pairs']} pairs "
              f"({interface['n_stick']} stick, {interface['n_slip']} slip, {interface['n_open']} open), "
              f"total normal force {interface['total_normal_force']!r}")
    per_width = totals[0] / float(width)
    print(f"3D per unit width {per_width!r} against 2D {totals[1]!r}: relative difference "
          f"{per_width / totals[1] - 1:.2e} (tolerance {tolerance})")
    assert abs(per_width / totals[1] - 1) <= float(tolerance), (per_width, totals[1])


def check_wedge(exe, prm, tolerance="1e-5", max_share="0.05"):
    from wedge_reference import safety_factor_of_run
    result = completed_run(exe, prm)
    summary = result.summary
    # The entries as the run read them (parameters.prm), included files too.
    exact, mode = safety_factor_of_run(result.parameters, summary)
    K = summary["safety_factor"]
    print(f"K = {K!r}, limit equilibrium {exact!r} ({mode}), relative error {K / exact - 1:.3e}")
    assert summary["converged"], summary["safety_factor_reason"]
    assert abs(K / exact - 1) <= float(tolerance), "K differs from the limit equilibrium"
    if mode != "both planes":
        planes = {i["name"]: i for i in summary["interfaces"]}
        lifted = planes["plane B" if mode == "plane A only" else "plane A"]
        sliding = planes["plane A" if mode == "plane A only" else "plane B"]
        share = lifted["total_normal_force"] / sliding["total_normal_force"]
        print(f"normal force on the lifted plane: {share:.3e} of the sliding plane's")
        assert abs(share) <= float(max_share), "the plane that lifts off still carries the wedge"


def check_wedge_fold(exe, prm, tolerance="1e-8"):
    """Below the limit of a wedge sliding on both planes every pair slips and
    K* - K falls off as the square of the distance to the limit: the slip
    directions turn towards the line of intersection, and K* - K measures
    how far the shears still cancel. sqrt(K* - K) is then linear in K near
    the limit, and its zero, extrapolated from three solves just below it,
    is the fold where the all-slipping states end. For a wedge without
    cohesion that fold must be the limit equilibrium itself, whatever the
    mesh: the resultant normal forces follow from the equilibrium across
    the line of intersection alone. The iteration's answer stops short of
    it where the solves end (1e-6 below, relative, on prm/rock_wedge.prm,
    where the mixed system's reciprocal condition falls to 1e-11); the fold
    shows the contact solution itself converging to the limit equilibrium
    to TOL."""
    from wedge_reference import safety_factor_of_run
    one_solve = {"Safety factor/Maximum iterations": "1", "Safety factor/Stiffness check": "false"}
    first = fdem_run.run_case(exe, prm, settings=one_solve)
    assert first.summary is not None, first.failure()
    exact, mode = safety_factor_of_run(first.parameters, first.summary)
    assert mode == "both planes", f"the wedge slides on {mode}: no fold"
    # 1e-4 to 1.6e-5 below the limit: close enough that sqrt(K* - K) is a
    # parabola in K to far below TOL (measured on prm/rock_wedge.prm: its
    # slope changes by 1.2e-3 of itself over these distances), far enough
    # from where the solves end for K* - K (4e-10 at the nearest) to keep
    # its digits.
    points = []
    for r in (1e-4, 4e-5, 1.6e-5):
        K = exact * (1 - r)
        run = fdem_run.run_case(exe, prm, settings={**one_solve,
                                                    "Safety factor/Initial factor": repr(K)})
        assert run.summary is not None, run.failure()
        step = run.summary["iterations"][0]
        assert step["contact_result"] == "converged", (K, step["contact_result"])
        assert step["n_stick"] == 0 and step["n_slip"] > 0, (K, step)
        h = step["K_star"] - step["K"]
        assert h > 0, (K, step["K_star"])
        points.append((step["K"], math.sqrt(h)))
        print(f"K = {step['K']!r}: K* - K = {h:.6e}, sqrt {math.sqrt(h):.6e}, "
              f"{step['n_slip']} slip, {step['n_open']} open")
    # The parabola through the three (K, sqrt(h)), its zero nearest the points.
    (K0, g0), (K1, g1), (K2, g2) = points
    d01, d12 = (g1 - g0) / (K1 - K0), (g2 - g1) / (K2 - K1)
    curvature = (d12 - d01) / (K2 - K0)
    slope = d12 + curvature * (K2 - K1)  # the parabola's slope at K2
    disc = slope * slope - 4 * curvature * g2
    fold = K2 + 2 * g2 / (-slope + math.sqrt(disc))
    print(f"fold {fold!r}, limit equilibrium {exact!r}, relative difference {fold / exact - 1:.3e} "
          f"(tolerance {tolerance})")
    assert abs(fold / exact - 1) <= float(tolerance), "the fold is not the limit equilibrium"


def check_wedge_slope(exe, prm, tolerance="1e-2"):
    """The slope of K* that a step with every pair slipping computes
    (K_star_slope in summary.json: two solves of the mixed system at
    K -/+ dK with the step's statuses and slip directions held, a Newton
    step each) against the slope of K* between two full solves (status
    iteration to convergence) 10 % of the distance to the limit either
    side, at 1e-3 and 1e-4 below the wedge's limit equilibrium. The
    central difference of the full solves has a truncation error of the
    square of the 10 % times the change of K*'s curvature (measured on
    prm/rock_wedge.prm: h' from full solves a factor 2 apart agreed with the
    mean of their slopes to 0.2 to 0.4 %); TOL (relative to h' = slope - 1)
    leaves room for it."""
    from wedge_reference import safety_factor_of_run
    one_solve = {"Safety factor/Maximum iterations": "1", "Safety factor/Stiffness check": "false"}
    first = fdem_run.run_case(exe, prm, settings=one_solve)
    assert first.summary is not None, first.failure()
    exact, mode = safety_factor_of_run(first.parameters, first.summary)
    assert mode == "both planes", f"the wedge slides on {mode}: no fold"

    def step_at(r):
        run = fdem_run.run_case(exe, prm, settings={**one_solve,
                                                    "Safety factor/Initial factor": repr(exact * (1 - r))})
        assert run.summary is not None, run.failure()
        step = run.summary["iterations"][0]
        assert step["contact_result"] == "converged", (r, step["contact_result"])
        assert step["n_stick"] == 0 and step["n_slip"] > 0, (r, step)
        return step

    for r in (1e-3, 1e-4):
        centre, below, above = step_at(r), step_at(1.1 * r), step_at(0.9 * r)
        assert centre["K_star_slope"] is not None, "no slope computed for an all-slipping step"
        assert centre["n_slope_solves"] == 2, centre
        computed = centre["K_star_slope"] - 1
        between = ((above["K_star"] - above["K"]) - (below["K_star"] - below["K"])) / \
            (above["K"] - below["K"])
        print(f"{r:g} below the limit: h' computed {computed:.6e}, between full solves "
              f"{between:.6e}, relative difference {computed / between - 1:.2e} (tolerance {tolerance})")
        assert abs(computed / between - 1) <= float(tolerance), "the slope of K* is not K*'s slope"


def invariance_outcome(exe, prm, settings=None):
    """What must not change between equivalent runs of @p prm: K, each
    step's outcome and statuses, each interface's final statuses."""
    result = fdem_run.run_case(exe, prm, settings=settings or {})
    label = f"{os.path.basename(prm)} {settings or ''}".strip()
    assert result.returncode == 0, f"{label}: exit {result.returncode}: {result.stderr}"
    summary = result.summary
    assert summary["status"] == "completed", f"{label}: {summary['status']}"
    # Whether each solve converged, not why one failed: far beyond
    # the limit (the wedge at K = 1) "runaway" and "no rigid-mode
    # equilibrium" both say "a mechanism", and which test sees it
    # first is round-off (measured on the wedge in lbf, ft, psf).
    steps = [(s["contact_result"] == "converged", s["n_stick"], s["n_slip"], s["n_open"])
             for s in summary["iterations"]]
    statuses = {i["name"]: (i["n_stick"], i["n_slip"], i["n_open"])
                for i in summary["interfaces"]}
    return summary["safety_factor"], steps, statuses


def compare_outcomes(labels, outcomes, tolerance=1e-8):
    """The first outcome is the reference; every other must have its K to
    @p tolerance relative, its steps and its statuses."""
    K_ref, steps_ref, statuses_ref = outcomes[0]
    print(f"{labels[0]}: K = {K_ref!r}, {len(steps_ref)} steps, statuses {statuses_ref}")
    failures = []
    for label, (K, steps, statuses) in zip(labels[1:], outcomes[1:]):
        difference = K / K_ref - 1
        print(f"{label}: K = {K!r} ({difference:+.2e}), {len(steps)} steps, "
              f"statuses {statuses}")
        if not abs(difference) <= tolerance:
            failures.append(f"{label}: K = {K!r}, {difference:+.2e} from {K_ref!r}")
        if steps != steps_ref:
            failures.append(f"{label}: safety-factor steps {steps} differ from {steps_ref}")
        if statuses != statuses_ref:
            failures.append(f"{label}: statuses {statuses} differ from {statuses_ref}")
    assert not failures, "\n".join(failures)


def check_invariance(exe, reference, *others):
    """Runs REF and OTHERS; all must agree (see the usage above)."""
    # Two runs at a time: most of a small run's time is the program's start.
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(2) as pool:
        outcomes = list(pool.map(lambda prm: invariance_outcome(exe, prm),
                                 (reference,) + others))
    compare_outcomes([os.path.basename(p) for p in (reference,) + others], outcomes)


def check_modulus_scale(exe, prm, solver, blocks, reference_modulus, *moduli):
    """@p prm with the Young's modulus of each of @p blocks (comma-separated)
    set to each of @p moduli, with Solver/Direct solver = @p solver: the same
    K to 1e-8 (the invariance tests' tolerance), steps and statuses as at
    @p reference_modulus. Loads and strengths stay: K does not depend on a
    common stiffness (doc/theory.md), at every magnitude a double holds."""
    def settings(modulus):
        entries = {f"Blocks/{b.strip()}/Young's modulus": modulus for b in blocks.split(",")}
        entries["Solver/Direct solver"] = solver
        return entries
    from concurrent.futures import ThreadPoolExecutor
    all_moduli = (reference_modulus,) + moduli
    with ThreadPoolExecutor(2) as pool:
        outcomes = list(pool.map(lambda E: invariance_outcome(exe, prm, settings(E)), all_moduli))
    compare_outcomes([f"{solver}, E = {E}" for E in all_moduli], outcomes)


def check_cohesion_scale(exe, prm, *cohesions):
    """@p prm with the sliding surface's cohesion set to each of
    @p cohesions, so large that friction adds nothing a double holds (the
    friction share is below 1e-90 from 1e100 on): K is proportional to the
    cohesion, K/c the same to 1e-8 (the invariance tests' tolerance) in the
    same steps, certified, at every magnitude up to 1e300. The secant of
    the iteration once overflowed there: h (K - K_prev) at K = 4e198 gave
    K = inf, and the run ended in "no static equilibrium"."""
    ratios = []
    for c in cohesions:
        summary = completed_run(exe, prm, settings={
            "Interfaces/sliding surface/Cohesion": c}).summary
        assert summary["converged"] and summary["certificate"]["holds"], summary["certificate"]
        steps = [(s["n_stick"], s["n_slip"], s["n_open"]) for s in summary["iterations"]]
        ratios.append((summary["safety_factor"] / float(c), steps))
        print(f"cohesion {c}: K = {summary['safety_factor']!r}, K/c = {ratios[-1][0]!r}, "
              f"{len(steps)} steps")
    for c, (ratio, steps) in zip(cohesions[1:], ratios[1:]):
        assert abs(ratio / ratios[0][0] - 1) <= 1e-8, (c, ratio, ratios[0][0])
        assert steps == ratios[0][1], (c, steps, ratios[0][1])


def vtu_cells(path):
    import vtk
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetNumberOfCells()


def check_mpi(exe, prm, n_ranks="2"):
    runs, compressed = [], []
    for launcher in ([], ["mpirun", "-np", n_ranks, "--oversubscribe"]):
        with fdem_run.temporary_run(exe, prm, launcher=launcher) as result:
            assert result.returncode == 0, result.stdout + result.stderr
            files = sorted(os.listdir(result.output))
            cells = {f: vtu_cells(result.file(f)) for f in files if f.endswith(".vtu")}
            # MUMPS's block low-rank statistics, one line per compressed
            # factorisation (tests/mpi/slope_3d_block_low_rank.prm).
            compressed.append(sum("after low-rank compression" in line
                                  for line in open(result.file("log.txt"))))
            runs.append((result.stdout, result.summary, files, cells))
    (_, serial, serial_files, serial_cells), (log, parallel, files, cells) = runs
    # A low-rank factorisation stays low-rank on the ranks: as many blocks
    # compressed as serially (none where the case asks for full rank).
    print(f"low-rank compressed factorisations: serial {compressed[0]}, "
          f"{n_ranks} ranks {compressed[1]}")
    assert compressed[0] == compressed[1], compressed
    assert serial["n_mpi_ranks"] == 1 and parallel["n_mpi_ranks"] == int(n_ranks)
    # Only rank 0 prints: one log, as long as the serial one.
    assert log.count("Result of ") == 1, "more than one rank printed the log"
    # Only rank 0 writes, and all of each block: the same files and cells.
    assert files == serial_files, f"output files differ: {files} vs {serial_files}"
    assert cells == serial_cells, f"VTU cells differ: {cells} vs {serial_cells}"
    assert serial["converged"] and parallel["converged"]
    K1, K2 = serial["safety_factor"], parallel["safety_factor"]
    print(f"K serial = {K1!r}, K with {n_ranks} ranks = {K2!r}, "
          f"relative difference {abs(K2 / K1 - 1):.2e}")
    # The ranks change only the order of the sums in the assembly and the
    # factorisation (round-off, about 1e-15 relative in u). The status
    # iteration may then take another path where a pair sits at a threshold
    # to round-off (seen on the coarse 3D wedge: another slip count at one
    # step), but a fixed point (K* = K) ends in the same state and K to
    # round-off: 1e-10 leaves a wide margin over the measured 2e-16 to 4e-15
    # (4e-12 on the tetrahedra's wedge), far below any error of the method
    # or the mesh.
    # A conservative bound (a static K_lo below a K_hi whose solve fails,
    # farther apart than the tolerance: a plane lifting off) certifies less:
    # K_lo is a static state, so the limit is at least K_lo, and the failed
    # solve above it is the status iteration giving up, not a proof. Solves
    # in the last 1e-4 below the limit succeed or fail with round-off, so
    # each run's K_lo is the lower bound its own path found. With MUMPS's
    # dynamic scheduling on two ranks that round-off changes with the load
    # of the machine: 50 runs of tests/mpi/wedge_3d_amesos_mumps.prm under
    # load gave K = 0.5777454756 (45) and 0.5778081928 (5), 1.1e-4 apart,
    # both static states. The runs must then make the same kind of claim
    # and agree to 1e-3, ten times that spread and ten times inside the
    # 1e-2 (Bracket agreement) that the claim itself allows.
    kinds = [s["certificate"]["kind"] + (" (conservative)" if s["certificate"].get("conservative") else "")
             for s in (serial, parallel)]
    print("certificates:", kinds)
    assert kinds[0] == kinds[1], "the certificate depends on the number of ranks"
    # A bracket on a fold (the 3D wedges: every pair slipping) ends where
    # the iteration aimed, L(1 - 1.5 tol) less the error estimate, L being
    # Newton's root on sqrt(K* - K) from the slope of K*: a difference
    # quotient over dK = sqrt(K* - K)/100, about (L - K)/60, that carries
    # the round-off of K* (1e-15 to 1e-14 between ranks) into the aim
    # multiplied by about K/dK, 1e5 to 1e6 in the last steps. Measured
    # 2.0e-10 on the tetrahedra's wedge with the same statuses at every
    # step; 1e-8 for such brackets, still a hundredth of the tolerance.
    fixed_point = serial["certificate"]["kind"] == "fixed point"
    tolerance = 1e-3 if serial["certificate"].get("conservative") else \
        1e-10 if fixed_point else 1e-8
    assert abs(K2 / K1 - 1) <= tolerance, "the safety factor depends on the number of ranks"
    same_path = all([s[key] for s in serial["iterations"]] == [s[key] for s in parallel["iterations"]]
                    for key in ("n_stick", "n_slip", "n_open", "n_contact_iterations"))
    print("status iteration: " + ("the same path" if same_path else "another path, same K"))


def parameters_doc(exe, doc, write=False):
    listing = subprocess.run([exe, "--print-parameters"], capture_output=True,
                             text=True, check=True).stdout
    text = ("# Parameters\n\n"
            "Generated by `fdem-slope --print-parameters` (the default case, "
            "prm/paper_slope.prm's block, boundary and interface names); do not "
            "edit by hand: run `tests/scripts/run_checks.py parameters-doc "
            "build/fdem-slope doc/parameters.md --write`.\n\n"
            "Blocks, boundaries and interfaces get one subsection per name listed "
            "in their `Names` entry. Units are the model's own (e.g. kN, m, kPa).\n\n"
            "```\n" + listing + "```\n")
    if write:
        open(doc, "w").write(text)
    assert open(doc).read() == text, f"{doc} is out of date: regenerate it (--write)"


if __name__ == "__main__":
    command, exe, path = sys.argv[1:4]
    if command == "parameters-doc":
        parameters_doc(exe, path, "--write" in sys.argv)
    else:
        {"vtu": check_vtu, "bad-input": check_bad_input,
         "bad-layout": check_bad_layout, "triple-point": check_triple_point,
         "no-equilibrium": check_no_equilibrium,
         "deterministic": check_deterministic, "threads": check_threads,
         "wedge": check_wedge, "wedge-fold": check_wedge_fold,
         "wedge-slope": check_wedge_slope, "mpi": check_mpi,
         "plane-strain": check_plane_strain,
         "plane-strain-contact": check_plane_strain_contact,
         "reference-factor": check_reference_factor,
         "block-low-rank": check_block_low_rank,
         "undrained-sphere": check_undrained_sphere, "turned": check_turned,
         "undrained-ellipsoid": check_undrained_ellipsoid,
         "certified": check_certified, "fe-stress": check_fe_stress,
         "mesh-convergence": check_mesh_convergence,
         "stiffness-consistency": check_stiffness_consistency,
         "invariance": check_invariance, "modulus-scale": check_modulus_scale,
         "cohesion-scale": check_cohesion_scale}[command](exe, path, *sys.argv[4:])
    print("passed")
