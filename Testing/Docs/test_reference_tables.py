# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks the reference tables of the pages against what they describe (ctest
npr.docs.reference-tables; Documentation/testing.md, "Reference tables").

    test_reference_tables.py --npr-render build/bin/npr-render --npr-view build/bin/npr-view

Both ways: every option of the source is documented on its page, and every documented one exists.
- Documentation/cli.md's `flag` tables against `npr-render --help` (long and short flags); and
  for each flag whose usage error lists the values it accepts (`--style x`: "valid styles: ..."),
  every value is named in the flag's --help entry and, in backticks, in the flag's table row;
- Documentation/viewer.md's `flag` table and its marked flag list against `npr-view --help` (run
  without DISPLAY: --help needs no X display);
- Documentation/paraview.md's `Property` column against the NPR view proxy of
  Plugin/Views/NPRView.xml (every property the GUI shows), and each enumeration entry in its row;
- Documentation/pyvista.md's `setting` column against `SETTINGS` of
  Rendering/Python/vtknpr/pyvista.py, read with ast: importing the module needs PyVista.

A page documents the names in backticks in the column of its tables headed as above (one row per
name or several names in a row), and, where a page names options only in a sentence, the
backticked flags of the paragraph under a line `<!-- flag list -->`.
Exits 1 naming each missing or unknown name and its page.
"""
import argparse
import ast
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

REPOSITORY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FLAG_LIST_MARKER = "<!-- flag list -->"
# An option line of --help: two spaces, then the flag(s); descriptions are indented further.
HELP_OPTION = re.compile(r"^  (--?[A-Za-z].*)$")
# Flags at the start of an option line or after a comma ("-o, --output FILE").
HELP_FLAG = re.compile(r"(?:^|,\s*)(--?[A-Za-z][\w-]*)(?: ([A-Z][A-Za-z]*))?")
# The usage errors that list what a flag accepts.
ACCEPTED = (re.compile(r"\(valid \w+: ([^)]+)\)"),
            re.compile(r"expects ([\w+]+(?:, [\w+]+)* or [\w+]+), got"))
PROBE = "@not-a-value@"

failures = []


def fail(where, message):
    failures.append("%s: %s" % (where, message))
    print("FAIL %s: %s" % (where, message))


def page_path(page):
    return os.path.join(REPOSITORY, page)


def tables(text):
    """Each Markdown table of the text as a list of rows, each a list of cells (header first)."""
    found, rows = [], []
    for line in text.split("\n") + [""]:
        if line.lstrip().startswith("|"):
            rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
        elif rows:
            found.append([row for row in rows if not re.match(r"^:?-+:?$", row[0] or "-")])
            rows = []
    return found


def backticked(text):
    return re.findall(r"`([^`]+)`", text)


def documented(page, column, is_name):
    """{name: its row (or paragraph)} of the page: the backticked names that pass is_name in the
    column headed `column` of its tables, and in the paragraphs under FLAG_LIST_MARKER."""
    text = open(page_path(page)).read()
    names = {}
    for table in tables(text):
        header = [cell.lower() for cell in table[0]]
        if column not in header:
            continue
        at = header.index(column)
        for row in table[1:]:
            for name in backticked(row[at] if at < len(row) else ""):
                if is_name(name):
                    names.setdefault(name, " | ".join(row))
    for paragraph in text.split(FLAG_LIST_MARKER)[1:]:
        paragraph = paragraph.lstrip("\n").split("\n\n")[0]
        for name in backticked(paragraph):
            if is_name(name):
                names.setdefault(name, paragraph)
    return names


def is_flag(name):
    return re.match(r"^--?[A-Za-z][\w-]*$", name) is not None


def compare(page, source, actual, names):
    """Both ways: each name of the source on the page, each name of the page in the source."""
    if not names:
        fail(page, "no reference table found (its column header changed?)")
    for name in sorted(set(actual) - set(names)):
        fail(page, "`%s` is in %s but not documented on the page" % (name, source))
    for name in sorted(set(names) - set(actual)):
        fail(page, "`%s` is documented but %s has no such name" % (name, source))


def run(program, *arguments):
    """(exit status, stdout + stderr) of the program, without an X display."""
    environment = dict(os.environ)
    environment.pop("DISPLAY", None)
    done = subprocess.run([program] + list(arguments), env=environment, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=120)
    return done.returncode, done.stdout


def help_entries(program):
    """{flag: (its value's name or None, its --help text)} from `program --help`."""
    status, text = run(program, "--help")
    if status != 0:
        fail(os.path.basename(program), "--help exited %d:\n%s" % (status, text))
        return {}
    entries, current = {}, []
    for line in text.split("\n"):
        option = HELP_OPTION.match(line)
        if option:
            current = HELP_FLAG.findall(option.group(1))
            for flag, value in current:
                entries[flag] = (value or None, line)
        elif line.startswith("    ") and current:  # a description's next line
            for flag, value in current:
                entries[flag] = (value or None, entries[flag][1] + " " + line.strip())
        else:
            current = []
    return entries


def accepted_values(program, flag):
    """The values the program's usage error lists for the flag, or None."""
    _, text = run(program, flag, PROBE)
    for pattern in ACCEPTED:
        found = pattern.search(text)
        if found:
            return [value for value in re.split(r", | or |\|", found.group(1)) if value]
    return None


def mentions(text, word):
    return re.search(r"(?<![\w+-])%s(?![\w+-])" % re.escape(word), text) is not None


def check_program(program, page, check_values):
    name = os.path.basename(program)
    entries = help_entries(program)
    names = documented(page, "flag", is_flag)
    compare(page, "`%s --help`" % name, entries, names)
    if not check_values:
        return
    values_of = {flag: accepted_values(program, flag) if value else None
                 for flag, (value, _) in entries.items()}
    for flag, (value, help_text) in sorted(entries.items()):
        values = values_of[flag]
        # Values another flag has (--compare-style takes --style's) are named by naming that flag.
        if any(other != flag and values and values_of[other] == values and mentions(help_text, other)
               and mentions(names.get(flag, ""), other) for other in entries):
            continue
        for accepted in values or []:
            if not mentions(help_text, accepted):
                fail(name, "--help: the `%s` entry does not name `%s`, a value %s accepts"
                     % (flag, accepted, name))
            if flag in names and "`%s`" % accepted not in names[flag]:
                fail(page, "the `%s` row does not name `%s`, a value %s accepts"
                     % (flag, accepted, name))


def check_paraview(page, xml_file):
    source = os.path.relpath(xml_file, REPOSITORY)
    view = ET.parse(xml_file).getroot().find(".//RenderViewProxy[@name='NPRRenderView']")
    if view is None:
        fail(source, "no RenderViewProxy NPRRenderView")
        return
    # The GUI shows every property but those marked never shown or information only.
    shown = {element.get("name"): element for element in view
             if element.tag.endswith("Property") and element.get("panel_visibility") != "never"
             and element.get("information_only") != "1"}
    names = documented(page, "property", lambda name: re.match(r"^\w+$", name) is not None)
    compare(page, source, shown, names)
    for name, element in sorted(shown.items()):
        for entry in element.findall("./EnumerationDomain/Entry"):
            if name in names and not mentions(names[name], entry.get("text")):
                fail(page, "the `%s` row does not name `%s`, an entry of its enumeration in %s"
                     % (name, entry.get("text"), source))


def literal_assignment(module, variable):
    """The literal value assigned to the module's top-level variable (the module not imported)."""
    for node in ast.parse(open(module).read(), module).body:
        if isinstance(node, ast.Assign) and any(
                isinstance(target, ast.Name) and target.id == variable for target in node.targets):
            return ast.literal_eval(node.value)
    fail(os.path.relpath(module, REPOSITORY), "no literal %s = ..." % variable)
    return {}


def check_pyvista(page, module):
    settings = literal_assignment(module, "SETTINGS")
    names = documented(page, "setting", lambda name: re.match(r"^\w+$", name) is not None)
    compare(page, "SETTINGS of %s" % os.path.relpath(module, REPOSITORY), settings, names)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--npr-render", required=True)
    parser.add_argument("--npr-view", required=True)
    arguments = parser.parse_args()
    check_program(arguments.npr_render, "Documentation/cli.md", check_values=True)
    # npr-view's style options are npr-render's (one parser); cli.md has their values.
    check_program(arguments.npr_view, "Documentation/viewer.md", check_values=False)
    check_paraview("Documentation/paraview.md",
                   os.path.join(REPOSITORY, "Plugin", "Views", "NPRView.xml"))
    check_pyvista("Documentation/pyvista.md",
                  os.path.join(REPOSITORY, "Rendering", "Python", "vtknpr", "pyvista.py"))
    if failures:
        print("%d problem(s) in the reference tables" % len(failures))
        return 1
    print("the reference tables match the programs, NPRView.xml and SETTINGS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
