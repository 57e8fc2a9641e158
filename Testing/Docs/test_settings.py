# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks every front end of vtkNPRPass's settings against the one table of them,
Rendering/Passes/vtkNPRPassSettings.json (ctest npr.docs.settings; Documentation/testing.md,
"Settings table"; how to add a setting: Documentation/contributing.md).

    PYTHONPATH=build/lib/python3/dist-packages \\
      test_settings.py --npr-render build/bin/npr-render

For every row of the table:
- vtkNPRPass (the wrapped vtknpr module): the getter's default, and the setter's clamp (a value
  below the range and one above read back as its ends);
- npr-render and npr-view: the --help entry of the flag (its stated default and range), the range
  or values its usage error accepts, the default of the field of nprPassSettings.h, and the line
  of nprPassSettings.cxx setting the pass from that field; npr-view's keys that step the setting
  (their stops in nprViewer.cxx and their rows in viewer.md);
- ParaView (Plugin/Views/NPRView.xml read as a file): the property's default, range or enumeration
  domain and help, and vtkPVNPRView.cxx forwarding it to the row's setter;
- PyVista (Rendering/Python/vtknpr/pyvista.py read with ast): the keyword in SETTINGS and
  _SETTERS, reaching the row's setter with a reader of the row's type;
- the pages: the default and range a row of cli.md, paraview.md or pyvista.md states.
And the other way: every field of nprPassSettings, NPRView.xml property and PyVista keyword has a
row (or, for ParaView, is one of the view's own). Exits 1 naming each disagreement.
"""
import argparse
import ast
import json
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import test_reference_tables as reference
import vtknpr

REPOSITORY = reference.REPOSITORY
TABLE = os.path.join(REPOSITORY, "Rendering", "Passes", "vtkNPRPassSettings.json")
COLORS = {"black": [0.0, 0.0, 0.0], "white": [1.0, 1.0, 1.0]}
NUMBER = r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?"
# "1..179", "1e-5 – 0.1": a range as the pages and --help write it.
STATED_RANGE = re.compile(r"(?<![\w.])(%s)\s*(?:\.\.|–)\s*(%s)(?![\w.])" % (NUMBER, NUMBER))
# "(default 30)", "(default black)", "(default `silhouettes,creases,contours`)"
STATED_DEFAULT = re.compile(r"\(default\s+`?([^`\s);]+)")
# "`inside` (on the nearer object, default)", "float (default)", "`surface` (default: ...)"
NAMED_DEFAULT = re.compile(r"`?([\w+]+)`? \((?:[^()]*?,\s*)?default\b")

failures = reference.failures
fail = reference.fail


def name_of(row):
    return "vtkNPRPass::%s%s" % ("Get%s()->" % row["pass"] if row["pass"] else "", row["method"])


def same(a, b):
    if isinstance(a, (list, tuple)) or isinstance(b, (list, tuple)):
        return (isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)) and len(a) == len(b)
                and all(same(x, y) for x, y in zip(a, b)))
    if isinstance(a, bool) or isinstance(b, bool):
        return a == b
    return math.isclose(float(a), float(b), rel_tol=1e-9, abs_tol=1e-12)


def numeric(row):
    return row["type"] in ("int", "uint", "double")


def limits(row):
    """The row's [low, high]: its range, or the indices of an enumeration's values."""
    if row["type"] == "enum":
        return [0, len(row["values"]) - 1]
    return row.get("range")


def value_of_text(row, text):
    """A default as a page or --help writes it, in the row's terms (None if unreadable)."""
    text = text.strip().strip("`").lower()
    if row["type"] == "bool":
        return {"on": True, "off": False, "true": True, "false": False}.get(text)
    if row["type"] == "color":
        numbers = re.findall(NUMBER, text)
        return COLORS.get(text) or ([float(n) for n in numbers] if len(numbers) == 3 else None)
    if row["type"] == "enum":
        names = [value.lower() for value in row["values"]]
        return names.index(text) if text in names else None
    return float(text) if re.fullmatch(NUMBER, text) else None


def check_stated(row, where, text, default, need_default, of_row=True):
    """The default and range a piece of text (a --help entry, a table row) states for the row;
    only the range where the text is not the row's alone (of_row false)."""
    stated = STATED_DEFAULT.search(text) or (NAMED_DEFAULT.search(text) if row["type"] == "enum"
                                             else None)
    if of_row and stated:
        value = value_of_text(row, stated.group(1))
        if value is None or not same(value, default):
            fail(where, "states the default %r, the table %r" % (stated.group(1), default))
    elif of_row and need_default:
        fail(where, "states no default (the table: %r)" % (default,))
    found = STATED_RANGE.search(text)
    if numeric(row) and found and not same([float(found.group(1)), float(found.group(2))],
                                           row["range"]):
        fail(where, "states the range %s..%s, the table %s" % (found.group(1), found.group(2),
                                                               row["range"]))


# ---- vtkNPRPass ---------------------------------------------------------------------------------
def check_pass(rows):
    npr = vtknpr.vtkNPRPass()
    for row in rows:
        owner = getattr(npr, "Get" + row["pass"])() if row["pass"] else npr
        get, set_ = getattr(owner, "Get" + row["method"]), getattr(owner, "Set" + row["method"])
        if not same(get(), row["default"]):
            fail(name_of(row), "defaults to %r, the table %r" % (get(), row["default"]))
        low_high = limits(row)
        if low_high is None:
            continue
        low, high = low_high
        probes = [(high, high)] if "unclamped" in row else [(low - 1, low), (high + 1, high)]
        for probe, expected in probes:
            set_(probe)
            if not same(get(), expected):
                fail(name_of(row), "set to %r reads back %r, the table's range %r"
                     % (probe, get(), low_high))
        set_(row["default"])


# ---- npr-render and nprPassSettings -------------------------------------------------------------
def settings_defaults(header):
    """{field: default} of the nprPassSettings struct, its initialisers read as values."""
    fields = {}
    pattern = r"^\s*(?:bool|int|double|std::string)\s+(\w+)(?:\[3\])?\s*=\s*([^;]+);"
    for field, value in re.findall(pattern, open(header).read(), re.M):
        value = value.strip()
        if value.startswith("{"):
            fields[field] = [float(n) for n in re.findall(NUMBER, value)]
        elif value in ("true", "false"):
            fields[field] = value == "true"
        elif value.startswith('"'):
            fields[field] = value.strip('"')
        elif "::" in value:
            owner, constant = value.split("::")
            fields[field] = getattr(getattr(vtknpr, owner), constant)
        else:
            fields[field] = float(value)
    return fields


def settings_applied(source):
    """{(pass, method, field)} that nprApplyPassSettings sets ("" for vtkNPRPass itself)."""
    text = open(source).read()
    passes = dict(re.findall(r"\w+\* (\w+) = pass->Get(\w+)\(\);", text), **{"pass": ""})
    return {(passes.get(variable), method, field) for variable, method, field in
            re.findall(r"(\w+)->Set(\w+)\(.*?settings\.(\w+)", text)}


def usage_range(program, flag, row):
    """What the program accepts for the flag: [low, high] as its usage error says, or the values
    its usage error lists, less any of them the program refuses."""
    if row["type"] == "enum":
        listed = reference.accepted_values(program, flag) or []
        return [value for value in listed if "got '%s'" % value not in reference.run(
            program, flag, value)[1]]
    _, text = reference.run(program, flag, "1e30" if row["type"] == "double" else "99999999999")
    found = re.search(r"expects (?:a number|an integer) in (%s)\.\.(%s)," % (NUMBER, NUMBER), text)
    return [float(found.group(1)), float(found.group(2))] if found else text.strip()


def check_cli_flag(row, program, entries, page_rows):
    cli = row["cli"]
    flag, where = cli["flag"], "npr-render %s (%s)" % (cli["flag"], name_of(row))
    default = cli.get("default", row["default"])
    if flag not in entries:
        fail(where, "not in --help")
        return
    help_text, page_row = entries[flag][1], page_rows.get(flag, "")
    if "item" in cli:  # one of a list's values: in the list's default when on by default
        for place, text in (("--help", help_text), ("cli.md", page_row)):
            stated = STATED_DEFAULT.search(text)
            listed = stated is not None and cli["item"] in stated.group(1).split(",")
            if listed != default:
                fail(where, "%s: `%s` %s the default list" % (place, cli["item"],
                                                             "not in" if default else "in"))
    elif "sets" in cli:
        if cli["sets"] == default:
            fail(where, "sets %r, which is already the default" % (cli["sets"],))
    else:
        need = row["type"] != "color"
        check_stated(row, where + " --help", help_text, default, need)
        check_stated(row, where + " in Documentation/cli.md", page_row, default, need)
        if numeric(row) or row["type"] == "enum":
            check_parser(row, program, flag, where)


def check_parser(row, program, flag, where):
    accepted = usage_range(program, flag, row)
    if row["type"] == "enum":
        expected, agree = row["values"], sorted(accepted) == sorted(row["values"])
    else:
        expected, agree = row["range"], same(accepted, row["range"])
    if not agree:
        fail(where, "the parser accepts %r, the table %r" % (accepted, expected))


def check_cli(rows, program):
    entries = reference.help_entries(program)
    page_rows = reference.documented("Documentation/cli.md", "flag", reference.is_flag)
    fields = settings_defaults(os.path.join(REPOSITORY, "Examples", "Common", "nprPassSettings.h"))
    applied = settings_applied(os.path.join(REPOSITORY, "Examples", "Common",
                                            "nprPassSettings.cxx"))
    named = set()
    for row in rows:
        if "not_exposed" in row["cli"]:
            continue
        field, where = row["cli"]["field"], "nprPassSettings::%s" % row["cli"]["field"]
        named.add(field)
        default = row["cli"].get("default", row["default"])
        value = fields.get(field)
        if isinstance(value, str) and row["type"] == "enum":
            value = row["values"].index(value) if value in row["values"] else value
        if value is None or not same(value, default):
            fail(where, "defaults to %r, the table %r" % (value, default))
        if (row["pass"], row["method"], field) not in applied:
            fail(where, "nprApplyPassSettings does not give it to %s" % name_of(row))
        check_cli_flag(row, program, entries, page_rows)
    for field in sorted(set(fields) - named):
        fail("nprPassSettings::%s" % field, "has no row in %s" % os.path.basename(TABLE))


def check_viewer(rows):
    """npr-view's keys that step a setting: the clamp of nprViewer.cxx and viewer.md's row."""
    source = open(os.path.join(REPOSITORY, "Examples", "npr-view", "nprViewer.cxx")).read()
    page_rows = reference.documented("Documentation/viewer.md", "key", lambda name: True)
    for row in rows:
        keys = row.get("viewer", {}).get("keys", [])
        field = row["cli"].get("field")
        where = "npr-view keys %s (%s)" % (" ".join(keys), name_of(row))
        for end, function in zip(row.get("range", []) if keys else [], ("max", "min")):
            found = re.search(r"s\.%s = std::%s\((%s), s\.%s" % (field, function, NUMBER, field),
                              source)
            if found is None or not same(float(found.group(1)), end):
                fail(where, "nprViewer.cxx does not stop at %r (std::%s)" % (end, function))
        for key in keys:
            if key not in page_rows:
                fail(where, "Documentation/viewer.md has no row for the key `%s`" % key)
            else:
                check_stated(row, where + " in Documentation/viewer.md", page_rows[key],
                             row["default"], False)


# ---- ParaView ----------------------------------------------------------------------------------
def forwarded(source):
    """{setter of vtkPVNPRView: its body} (the forwarding macros expanded to their calls)."""
    text = open(source).read()
    bodies = dict(re.findall(r"vtkPVNPRView::(Set\w+)\([^)]*\)\s*\{(.*?)\n\}", text, re.S))
    for name, owner, setter in re.findall(
            r"vtkPVNPRViewForward(?:Color)?\(\s*(\w+),\s*(?:\w+,\s*)?(\w+\(\)),\s*(\w+)\)", text):
        bodies["Set" + name] = "GetNPRPass()->%s->%s(" % (owner, setter)
    return bodies


def check_domain(row, where, element):
    if row["type"] == "bool":
        if element.find("BooleanDomain") is None:
            fail(where, "has no BooleanDomain")
    elif row["type"] == "enum":
        values = [int(entry.get("value")) for entry in element.findall("EnumerationDomain/Entry")]
        if sorted(values) != list(range(len(row["values"]))):
            fail(where, "enumerates %r, the table %d values" % (values, len(row["values"])))
    else:
        domain = element.find("DoubleRangeDomain")
        domain = element.find("IntRangeDomain") if domain is None else domain
        low_high = [[0.0] * 3, [1.0] * 3] if row["type"] == "color" else row["range"]
        found = None if domain is None else [[float(n) for n in domain.get(end).split()]
                                             for end in ("min", "max")]
        if found is None or not same(found if row["type"] == "color" else sum(found, []),
                                     low_high):
            fail(where, "range domain %r, the table %r" % (found, low_high))


def entry_text(element, value):
    for entry in element.findall("EnumerationDomain/Entry"):
        if int(entry.get("value")) == value:
            return entry.get("text")
    return None


def check_paraview_page(row, where, element, page_row):
    cells = page_row.split(" | ")
    if len(cells) < 4:
        fail(where, "no row with Default and Range columns in Documentation/paraview.md")
        return
    default_cell, range_cell = cells[2], cells[3]
    if row["type"] == "enum":
        stated = default_cell.strip().lower() == (entry_text(element, row["default"]) or "").lower()
    else:
        stated = same(value_of_text(row, default_cell), row["default"])
    if not stated:
        fail(where, "Documentation/paraview.md states the default %r, the table %r"
             % (default_cell, row["default"]))
    if numeric(row):
        check_stated(row, where + " in Documentation/paraview.md", range_cell, row["default"],
                     False)


def check_paraview(rows, table):
    source = os.path.join(REPOSITORY, "Plugin", "Views", "NPRView.xml")
    view = ET.parse(source).getroot().find(".//RenderViewProxy[@name='NPRRenderView']")
    properties = {element.get("name"): element for element in view
                  if element.tag.endswith("Property")}
    bodies = forwarded(os.path.join(REPOSITORY, "Plugin", "Views", "vtkPVNPRView.cxx"))
    page_rows = reference.documented("Documentation/paraview.md", "property",
                                     lambda name: re.match(r"^\w+$", name) is not None)
    named = set(table["front_end_only"]["paraview"])
    for row in rows:
        name = row["paraview"].get("property")
        if name is None:
            continue
        named.add(name)
        where = "NPRView.xml %s (%s)" % (name, name_of(row))
        element = properties.get(name)
        if element is None:
            fail(where, "no such property")
            continue
        if row["type"] == "enum" and entry_text(element, row["default"]) is None:
            fail(where, "no enumeration entry for the default %r" % row["default"])
        written = element.get("default_values", "")
        value = [float(n) for n in written.split()]
        value = value[0] if len(value) == 1 else value
        if row["type"] == "bool":
            value = bool(value)
        if not same(value, row["default"]):
            fail(where, "default_values %r, the table %r" % (written, row["default"]))
        check_domain(row, where, element)
        help_text = " ".join(element.findtext("Documentation", "").split()).lower()
        if row["help"].lower() not in help_text:
            fail(where, "its Documentation does not say %r" % row["help"])
        owner = r"GetNPRPass\(\)->" + (r"Get%s\(\)->" % row["pass"] if row["pass"] else "")
        if not re.search(owner + "Set%s\\(" % row["method"],
                         bodies.get(element.get("command"), "")):
            fail(where, "vtkPVNPRView::%s does not call %s" % (element.get("command"),
                                                                name_of(row)))
        check_paraview_page(row, where, element, page_rows.get(name, ""))
    for name in sorted(set(properties) - named):
        fail("NPRView.xml %s" % name, "has no row in %s" % os.path.basename(TABLE))


# ---- PyVista -----------------------------------------------------------------------------------
def pyvista_source(module):
    """(SETTINGS, {keyword: (reader, [(pass, setter)])}, {pass key: pass}, enable_npr's style)."""
    tree = ast.parse(open(module).read(), module)
    settings = reference.literal_assignment(module, "SETTINGS")
    setters, passes, style = {}, {}, None
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "_SETTERS":
            for key, value in zip(node.value.keys, node.value.values):
                reader, targets = value.elts
                setters[key.value] = (reader.id, ast.literal_eval(targets))
        elif isinstance(node, ast.Dict) and any(getattr(k, "value", "") == "npr"
                                                for k in node.keys):
            for key, value in zip(node.keys, node.values):
                getter = getattr(getattr(value, "func", None), "attr", "Get")
                passes[key.value] = getter[len("Get"):]
        elif isinstance(node, ast.FunctionDef) and node.name == "enable_npr":
            style = node.args.defaults[0].value
    return settings, setters, passes, style


READERS = {"bool": "bool", "int": "int", "uint": "int", "double": "float", "color": "_color"}


def check_pyvista(rows):
    module = os.path.join(REPOSITORY, "Rendering", "Python", "vtknpr", "pyvista.py")
    settings, setters, passes, style = pyvista_source(module)
    page_rows = reference.documented("Documentation/pyvista.md", "setting",
                                     lambda name: re.match(r"^\w+$", name) is not None)
    numeric_keywords = {row["pyvista"].get("keyword") for row in rows if numeric(row)}
    named = set()
    for row in rows:
        spelling = row["pyvista"]
        if "argument" in spelling:
            if style != row["values"][row["default"]]:
                fail("enable_npr(%s=)" % spelling["argument"], "defaults to %r, the table %r"
                     % (style, row["values"][row["default"]]))
            continue
        keyword = spelling.get("keyword")
        if keyword is None:
            continue
        named.add(keyword)
        where = "vtknpr.pyvista %s (%s)" % (keyword, name_of(row))
        if keyword not in settings or keyword not in setters:
            fail(where, "not in SETTINGS and _SETTERS")
            continue
        reader, targets = setters[keyword]
        reaches = [(passes.get(which), setter) for which, setter in targets]
        if (row["pass"], "Set" + row["method"]) not in reaches:
            fail(where, "sets %r, not %s" % (targets, name_of(row)))
        if READERS.get(row["type"], reader) != reader or (row["type"] == "enum"
                                                          and reader in READERS.values()):
            fail(where, "reads its value with %s, the table's type is %s" % (reader, row["type"]))
        if numeric(row):
            check_stated(row, where + " SETTINGS", settings[keyword], row["default"], False)
        # A row naming several settings states a range for its one numeric setting, if any.
        names = set(reference.backticked(page_rows.get(keyword, ""))) & set(settings)
        if len(names) == 1 or numeric(row) and len(names & numeric_keywords) == 1:
            check_stated(row, where + " in Documentation/pyvista.md", page_rows[keyword],
                         row["default"], False, of_row=len(names) == 1)
    for keyword in sorted(set(settings) - named):
        fail("vtknpr.pyvista %s" % keyword, "has no row in %s" % os.path.basename(TABLE))


def check_table(rows):
    """What the other checks rely on: each row complete, its default in its range."""
    for row in rows:
        for key in ("pass", "method", "type", "default", "help", "cli", "paraview", "pyvista"):
            if key not in row:
                fail(name_of(row) if "method" in row else repr(row), "has no %r" % key)
        low_high = limits(row)
        if low_high and not low_high[0] <= row["default"] <= low_high[1]:
            fail(name_of(row), "default %r outside its range %r" % (row["default"], low_high))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--npr-render", required=True)
    arguments = parser.parse_args()
    table = json.load(open(TABLE))
    rows = table["settings"]
    check_table(rows)
    check_pass(rows)
    check_cli(rows, arguments.npr_render)
    check_viewer(rows)
    check_paraview(rows, table)
    check_pyvista(rows)
    problems = failures
    if problems:
        print("%d disagreement(s) with %s" % (len(problems), os.path.relpath(TABLE, REPOSITORY)))
        return 1
    print("the %d settings of %s agree with vtkNPRPass, npr-render, NPRView.xml, vtknpr.pyvista "
          "and the pages" % (len(rows), os.path.relpath(TABLE, REPOSITORY)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
