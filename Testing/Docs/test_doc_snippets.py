# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the code blocks of one page of Documentation/ as a reader would (ctest
npr.docs.snippets.<page>; Documentation/testing.md, "Code on the pages").

    test_doc_snippets.py --page Documentation/edges.md --bin-dir build/bin --output-dir DIR

Each fenced block, by its language:
- sh: each npr-render command (a line starting `npr-render` or `build/bin/npr-render`, with its
  `\` continuations) runs with the built npr-render as python blocks run, and must exit 0 and
  write the files its -o, --edge-mask, --reference-mask and --camera-out name, as pictures that
  are not blank. A command whose model is not in the repository (`model.stl`, the benchmark's
  `build/benchmarks/` meshes) is not run, and says so. Other commands are not run.
- cmake, json, xml and unlabelled blocks (build files, file contents, program output): not run.
- python: run as it stands, with /usr/bin/python3, PYTHONPATH and no DISPLAY, from a folder of its
  own whose Testing/ is the repository's (the pages' commands run from the repository root; the
  block's output lands in that folder). It must exit 0, print no VTK error, and write every file
  it names (a .png, .svg, .pdf, .ps or .eps not under Testing/) as a picture that is not blank.
- cpp: must be marked as part of a program, below.
A block under a marker line `<!-- snippet: PATH -->` (the line just above its fence) is part of
the program PATH (from the repository root): its lines appear in PATH in the same order and
consecutively, each piece allowed one extra indentation, where a line `// ...` or `# ...` of the
block stands for lines left out. PATH must then be run by a test: Examples/Snippets/NAME.cxx is
built as npr-snippet-NAME, which this test runs as a python block is run (once per page) with the
same checks on the files the program names; any other PATH must be named in a CMakeLists.txt or
a test script of the repository.

A python block that imports pyvista is run by npr.pyvista.entry.snippet, where PyVista is
installed (Debian 13 and unstable), not here: Debian 12 does not package PyVista.
Pages whose code blocks need another program than python3 are run by their own tests:
pyvista.md (PyVista, which Debian 12 does not package: npr.pyvista.entry.snippet runs its first
block where PyVista is installed) and paraview.md (pvpython and pvbatch: npr.paraview.doc_snippet
runs its first block in the ParaView stages). Their blocks are not run here.
Exits 1 naming each block that failed.
"""
import argparse
import json
import os
import re
import shlex
import shutil
import subprocess
import sys

NOT_RUN = {"sh", "cmake", "json", "xml", ""}
OWN_TESTS = {"pyvista.md": "npr.pyvista.entry.snippet", "paraview.md": "npr.paraview.doc_snippet"}
OUTPUT = re.compile(r"""["']([\w./-]+\.(?:png|svg|pdf|ps|eps))["']""")
MARKER = re.compile(r"^<!--\s*snippet:\s*(\S+)\s*-->\s*$")
PYVISTA = re.compile(r"^\s*(import pyvista|from pyvista)\b", re.M)
ELISION = re.compile(r"^\s*(//|#) \.\.\.")
REPOSITORY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

failures = []


def fail(where, message):
    failures.append("%s: %s" % (where, message))
    print("FAIL %s: %s" % (where, message))


def blocks(page):
    """(line number, language, text, marker or None) of each fenced block of the page."""
    lines = open(page).read().split("\n")
    found, start = [], None
    for number, line in enumerate(lines):
        fence = re.match(r"^\s*```(\S*)\s*$", line)
        if not fence:
            continue
        if start is None:
            start, language = number, fence.group(1)
            continue
        marker = MARKER.match(lines[start - 1]) if start > 0 else None
        found.append((start + 1, language, "\n".join(lines[start + 1:number]) + "\n",
                      marker.group(1) if marker else None))
        start = None
    return found


def pieces(text):
    """The block's runs of lines between elisions."""
    runs, run = [], []
    for line in text.rstrip("\n").split("\n"):
        if ELISION.match(line):
            runs.append(run)
            run = []
        else:
            run.append(line)
    runs.append(run)
    trimmed = []
    for run in runs:
        while run and not run[0].strip():
            run = run[1:]
        while run and not run[-1].strip():
            run = run[:-1]
        if run:
            trimmed.append(run)
    return trimmed


def find_run(run, lines, start):
    """The index after the first place at or after start where run's lines follow one another in
    lines, each with the same extra indentation; None if nowhere."""
    for first in range(start, len(lines) - len(run) + 1):
        line = lines[first]
        if not run[0] or not line.endswith(run[0]):
            continue
        indent = line[:len(line) - len(run[0])]
        if indent.strip():
            continue
        if all(lines[first + k] == (indent + run[k] if run[k] else "")
               or (not run[k] and not lines[first + k].strip()) for k in range(len(run))):
            return first + len(run)
    return None


def check_verbatim(where, text, path):
    if not os.path.isfile(path):
        fail(where, "the marker names %s, which does not exist" % path)
        return False
    lines = open(path).read().split("\n")
    at = 0
    for run in pieces(text):
        found = find_run(run, lines, at)
        if found is None:
            fail(where, "these lines are not in %s (in this order, one after another):\n  %s"
                 % (os.path.relpath(path, REPOSITORY), "\n  ".join(run)))
            return False
        at = found
    return True


def is_run_by_a_test(path):
    """Whether a CMakeLists.txt or a test script of the repository names the file."""
    name = os.path.basename(path)
    for folder, dirs, files in os.walk(REPOSITORY):
        dirs[:] = [d for d in dirs if not d.startswith(".") and d != "build"]
        for file_name in files:
            if file_name == "CMakeLists.txt" or (folder.endswith(("Testing", "Packages"))
                                                  and file_name.endswith(".sh")):
                if name in open(os.path.join(folder, file_name)).read():
                    return True
    return False


def blank(path):
    """Why the file is no picture, or None."""
    size = os.path.getsize(path)
    if path.endswith(".json"):
        try:
            json.load(open(path))
            return None
        except ValueError:
            return "not JSON"
    if path.endswith((".ogv", ".mp4", ".avi")):
        return None if size > 1000 else "a video of %d bytes" % size
    if path.endswith(".svg"):
        return None if "<path" in open(path).read() else "an SVG without a <path>"
    if path.endswith((".pdf", ".ps", ".eps")):
        head = open(path, "rb").read(4)
        return None if head in (b"%PDF", b"%!PS") and size > 500 else "not a PDF or PostScript"
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        return "not a PNG"
    data = memoryview(scalars).cast("B")
    step = scalars.GetNumberOfComponents()
    first = bytes(data[0:step])
    differing = sum(1 for i in range(0, len(data), step) if bytes(data[i:i + step]) != first)
    pixels = len(data) // step
    if differing < pixels // 1000:  # a line mask has under 1 % of its pixels on lines
        return "blank: %d of %d pixels differ from the first" % (differing, pixels)
    return None


def run(where, command, names, output_dir, folder_of=None, fresh=True):
    """Runs command in a folder of its own with Testing/ reachable and checks the named files.
    The commands of one block share the folder of folder_of; all but the first keep it (fresh)."""
    folder = os.path.join(output_dir, re.sub(r"[^\w.-]", "_", folder_of or where))
    if fresh:
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        os.symlink(os.path.join(REPOSITORY, "Testing"), os.path.join(folder, "Testing"))
    env = dict(os.environ, DISPLAY="")
    result = subprocess.run(command, cwd=folder, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, universal_newlines=True, timeout=300)
    sys.stdout.write(result.stdout)
    if result.returncode != 0:
        fail(where, "exit status %d" % result.returncode)
    if "ERR|" in result.stdout or re.search(r"^(ERROR|Warning): In ", result.stdout, re.M):
        fail(where, "VTK printed an error or warning")
    for name in sorted(set(names)):
        if name.startswith("Testing/"):
            continue
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            fail(where, "names %s but did not write it" % name)
            continue
        why = blank(path)
        if why:
            fail(where, "%s: %s" % (name, why))
        else:
            print("%s: wrote %s (%d bytes)" % (where, name, os.path.getsize(path)))


MODEL = re.compile(r"\.(stl|obj|ply|vtp|vtk|gltf|glb|off)$", re.I)
WRITTEN = ("-o", "--output", "--edge-mask", "--reference-mask", "--camera-out")


def npr_render_commands(text):
    """The block's npr-render commands, each as its arguments (continuations joined, comments
    dropped)."""
    commands, pending = [], ""
    for line in text.split("\n"):
        pending += line.rstrip()
        if pending.endswith("\\"):
            pending = pending[:-1] + " "
            continue
        words = shlex.split(pending, comments=True)
        while words and re.match(r"^\w+=", words[0]):  # VAR=value before the program
            words = words[1:]
        if words and words[0] in ("npr-render", "build/bin/npr-render"):
            commands.append(words[1:])
        pending = ""
    return commands


def run_npr_render(where, block, first, arguments, bin_dir, output_dir):
    """Runs one documented npr-render command from a folder whose Testing/ is the repository's
    (block's, afresh when first); False when its model is not in the repository."""
    models = [word for before, word in zip([""] + arguments, arguments)
              if MODEL.search(word) and before not in WRITTEN]
    absent = [model for model in models if not os.path.isfile(os.path.join(REPOSITORY, model))]
    if absent or not models:
        print("%s: not run: npr-render %s (its model %s is not in the repository)"
              % (where, " ".join(arguments), ", ".join(absent) or "?"))
        return False
    written = [arguments[i + 1] for i, word in enumerate(arguments[:-1]) if word in WRITTEN]
    if "--orbit" in arguments:  # -o NAME.png writes NAME_0001.png, ...
        written = [re.sub(r"\.png$", "_0001.png", name) for name in written]
    print("%s: npr-render %s" % (where, " ".join(arguments)))
    run(where, [os.path.join(bin_dir, "npr-render"), *arguments], written, output_dir, block, first)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--page", required=True)
    parser.add_argument("--bin-dir", required=True, help="where npr-snippet-NAME are built")
    parser.add_argument("--output-dir", required=True)
    args = parser.parse_args()
    page = os.path.basename(args.page)
    if page in OWN_TESTS:
        print("%s: its blocks are run by %s, not here" % (page, OWN_TESTS[page]))
        return 0
    programs, counted = set(), 0
    for line, language, text, marker in blocks(args.page):
        where = "%s:%d" % (page, line)
        if marker:
            counted += 1
            path = os.path.join(REPOSITORY, marker)
            if not check_verbatim(where, text, path):
                continue
            snippet = re.match(r"^Examples/Snippets/(\w+)\.cxx$", marker)
            if snippet:
                programs.add(snippet.group(1))
            elif not is_run_by_a_test(path):
                fail(where, "no CMakeLists.txt or test script names %s" % marker)
            print("%s: part of %s" % (where, marker))
        elif language == "python" and PYVISTA.search(text):
            counted += 1
            print("%s: imports pyvista: run by npr.pyvista.entry.snippet" % where)
        elif language == "python":
            counted += 1
            script = os.path.join(args.output_dir, "%s-%d.py" % (page[:-3], line))
            os.makedirs(args.output_dir, exist_ok=True)
            with open(script, "w") as f:
                f.write(text)
            run(where, ["/usr/bin/python3", script], OUTPUT.findall(text), args.output_dir)
        elif language == "sh":
            first = True  # the block's first command that runs starts its folder afresh
            for number, command in enumerate(npr_render_commands(text)):
                counted += 1
                if run_npr_render("%s.%d" % (where, number + 1), where, first, command,
                                  args.bin_dir, args.output_dir):
                    first = False
        elif language not in NOT_RUN:
            counted += 1
            fail(where, "a ```%s block needs a marker <!-- snippet: PATH --> naming its program"
                 % language)
    for name in sorted(programs):
        source = os.path.join(REPOSITORY, "Examples", "Snippets", name + ".cxx")
        run("%s:npr-snippet-%s" % (page, name), [os.path.join(args.bin_dir, "npr-snippet-" + name)],
            OUTPUT.findall(open(source).read()), args.output_dir)
    print("%s: %d code blocks checked, %d failures" % (page, counted, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
