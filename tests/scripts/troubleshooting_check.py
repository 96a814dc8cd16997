#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""doc/troubleshooting.md lists every warning and note the program can give.

  troubleshooting_check.py ROOT

Every warning and note is made by postprocess::warning_text("id", ...) or
postprocess::note_text("id", ...) (include/fdem/postprocess/run_log.h); the
check finds every id in source/ and include/ and fails if one is not a
heading of doc/troubleshooting.md's warnings (`### \\`id\\``). It also fails
where a warning is made without an id: a call of warn(...) or
warnings.push_back(...) whose argument is not warning_text(...) (or the
variable `warning`, passed on), and a string literal that prints
"warning:" outside the two places that print tagged warnings. And every
"fdem-slope: error: ..." line written in the sources must be quoted in the
page up to its first variable part.
"""
import glob
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
# Where a tagged warning is printed with a "warning:" prefix.
PRINTERS = {"source/model.cc", "source/checks/layout_checks.cc", "source/main.cc", "source/run/run_case.cc"}


def sources():
    files = glob.glob(os.path.join(ROOT, "source", "**", "*.cc"), recursive=True) + \
        glob.glob(os.path.join(ROOT, "include", "**", "*.h"), recursive=True)
    for path in sorted(files):
        yield os.path.relpath(path, ROOT), open(path).read()


def without_comments(text):
    return re.sub(r"//[^\n]*|/\*.*?\*/", "", text, flags=re.DOTALL)


def main():
    doc = open(os.path.join(ROOT, "doc", "troubleshooting.md")).read()
    listed = set(re.findall(r"^### `([a-z0-9-]+)`", doc, re.MULTILINE))
    failures, ids = [], set()
    for path, text in sources():
        code = without_comments(text)
        for m in re.finditer(r"\b(warning_text|note_text)\(\s*\"([^\"]*)\"", code):
            ids.add(m.group(2))
            if m.group(2) not in listed:
                failures.append(f"{path}: {m.group(1)}(\"{m.group(2)}\") is not listed in doc/troubleshooting.md")
        for m in re.finditer(r"\b(?:warn|warnings\.push_back)\(\s*([^;]*)", code):
            argument = m.group(1)
            if not re.match(r"(postprocess::)?warning_text\(|warning\)|const ", argument):
                failures.append(f"{path}: a warning without an id: {m.group(0)[:70]}")
        if path not in PRINTERS and re.search(r"\"[^\"\n]*warning: ", code):
            failures.append(f"{path}: prints \"warning:\" itself; make it with warning_text()")
        for m in re.finditer(r"\"fdem-slope: error: ([^\"]*)\"", code):
            fixed = m.group(1).split("\\n")[0]
            if fixed and fixed not in doc:
                failures.append(f"{path}: the error line 'fdem-slope: error: {fixed}' is not in doc/troubleshooting.md")
    unused = listed - ids
    if unused:
        failures.append(f"doc/troubleshooting.md lists ids no source uses: {sorted(unused)}")
    print(f"{len(ids)} warning and note ids in the sources: {sorted(ids)}")
    assert not failures, "\n".join(failures)


if __name__ == "__main__":
    main()
