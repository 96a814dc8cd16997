#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""What fdem-slope prints, as a user sees it (doc/troubleshooting.md, "What
the program prints").

  screen_checks.py default EXE CASE.prm [MAX_LINES [DOC.md...]]
        the default screen has at most MAX_LINES lines (default 25), one
        line per safety-factor step, and ends with the result block: K to 3
        decimals and in full, the certificate in words, the stiffness check,
        the warnings and the results folder; no contact iteration, no time
        stamp; log.txt in the results folder has the full log, the screen's
        lines included; each DOC.md that shows the screen (a code block
        starting "Case: prm/<case>.prm") shows it as it is today
  screen_checks.py quiet EXE CASE.prm
        --quiet: stdout is one line, K to 17 digits, equal to summary.json's;
        stderr is empty
  screen_checks.py verbose EXE CASE.prm
        --verbose: the contact iterations and time stamps are on the screen,
        and the screen is log.txt
  screen_checks.py notes EXE CASE.prm
        a certified case with conditioning notes (the rock wedge): no note
        on the screen, each in log.txt and summary.json, counted in the
        result block's warnings line
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402

NOTE = "significant digits"


def run(exe, prm, args=()):
    """The run of @p prm with @p args, its screen and log.txt."""
    with fdem_run.temporary_run(exe, prm, args=list(args)) as result:
        assert result.returncode == 0, f"exit {result.returncode}: {result.stderr}"
        log_file = result.file("log.txt")
        assert os.path.exists(log_file), "no log.txt in the results folder"
        return result, open(log_file).read()


def check_docs(screen, prm, docs):
    """The code block of each of @p docs that starts with the case's line
    must be @p screen, with the case's path as prm/<name>.prm."""
    name = os.path.basename(prm)
    shown = re.sub(r"^Case: \S+", f"Case: prm/{name}", screen)
    for doc in docs:
        blocks = re.findall(rf"```\n(Case: prm/{re.escape(name)} .*?)```", open(doc).read(), re.DOTALL)
        assert blocks, f"{doc} shows no screen of {name}"
        for block in blocks:
            assert block == shown, f"{doc} shows another screen than today's:\n{block}"
        print(f"{doc}: the screen as it is today")


def check_default(exe, prm, max_lines="25", *docs):
    result, log = run(exe, prm)
    screen = result.stdout.splitlines()
    print(result.stdout)
    summary = result.summary
    assert result.stderr == "", result.stderr
    assert len(screen) <= int(max_lines), f"{len(screen)} lines on the screen, allowed {max_lines}"
    assert not any("contact iteration" in l or l.startswith("[") for l in screen), \
        "contact iterations or time stamps on the default screen"
    steps = [l for l in screen if re.match(r"\s+step\s+\d+: K = ", l)]
    assert len(steps) == len(summary["iterations"]), \
        f"{len(steps)} step lines for {len(summary['iterations'])} steps"
    K = summary["safety_factor"]
    block = screen[screen.index(next(l for l in screen if l.startswith("Result of "))):]
    text = "\n".join(block)
    assert re.search(rf"Safety factor\s+K = {K:.3f}\s+\({K:.8g}\)", text), f"K = {K:.3f} not in the block"
    assert re.search(r"Certificate\s+certified", text), "no certificate in words"
    assert re.search(r"Stiffness check\s+(stable|NOT stable|not checked)", text), "no stiffness check"
    assert re.search(r"Warnings\s+", text) and re.search(r"Results\s+\S+-output/", text)
    if summary["fe_stress_factor"]["computed"]:
        assert f"FE-stress factor {summary['fe_stress_factor']['factor']:.3f}" in text
    # Nothing is lost: the screen's lines are in the log file, with the detail.
    missing = [l for l in screen if l not in log.splitlines()]
    assert not missing, f"screen lines missing from log.txt: {missing}"
    assert "contact iteration" in log, "log.txt lacks the contact iterations"
    print(f"{len(screen)} lines on the screen, {len(log.splitlines())} in log.txt")
    check_docs(result.stdout, prm, docs)


def check_quiet(exe, prm):
    result, log = run(exe, prm, ["--quiet"])
    print(repr(result.stdout), repr(result.stderr))
    assert result.stderr == "", result.stderr
    lines = result.stdout.splitlines()
    assert len(lines) == 1, f"--quiet printed {len(lines)} lines"
    assert float(lines[0]) == result.summary["safety_factor"], "--quiet's K is not summary.json's"
    assert "Result of " in log, "log.txt lacks the result block under --quiet"


def check_verbose(exe, prm):
    result, log = run(exe, prm, ["--verbose"])
    assert "contact iteration" in result.stdout, "--verbose shows no contact iterations"
    assert re.search(r"^\[\s*[0-9.]+ s", result.stdout, re.MULTILINE), "--verbose shows no time stamps"
    assert result.stdout == log, "--verbose's screen is not log.txt"
    print(f"{len(result.stdout.splitlines())} lines, the same as log.txt")


def check_notes(exe, prm):
    result, log = run(exe, prm)
    summary = result.summary
    notes = summary["conditioning"]["notes"]
    print(result.stdout)
    print(f"{len(notes)} conditioning notes, up to {summary['conditioning']['max_digits_lost']} digits")
    assert summary["status"] == "completed"
    assert notes, "no conditioning note in summary.json: the case no longer tests the rule"
    assert all(n.startswith("[ill-conditioned] ") and NOTE in n for n in notes)
    assert NOTE not in result.stdout + result.stderr, "a conditioning note reached the screen"
    assert log.count(NOTE) >= len(notes), "log.txt lacks conditioning notes"
    assert f"{len(notes)} conditioning notes in log.txt" in result.stdout


if __name__ == "__main__":
    checks = {"default": check_default, "quiet": check_quiet, "verbose": check_verbose,
              "notes": check_notes}
    checks[sys.argv[1]](*sys.argv[2:])
