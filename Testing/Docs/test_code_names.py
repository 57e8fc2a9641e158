# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that a page names only code that exists (ctest npr.docs.code-names; Documentation/
testing.md, "Pages true to the code").

    test_code_names.py Documentation/architecture.md [more pages]

Every name a page writes in backticks, without spaces, is looked up in the repository:
- a path (`Rendering/Passes/CMakeLists.txt`, `glsl/vtkNPREdgeDetectFS.glsl`,
  `Rendering/Passes/Testing/Cxx/Test<Pass>.cxx`)
  must name a file or folder: from the top, or as the end of a tracked path; `<...>` and `*`
  match any part of one name;
- a module or target (`NPR::Lines`) must be a module's NAME in a `vtk.module` or a target
  the CMake files add; a library (`libvtkNPRLines`) or Python submodule (`vtknpr.vtkNPRIO`) a
  module's LIBRARY_NAME;
- a member (`vtkNPRRenderTarget::Scope`, `vtkNPRPass::Render`) must be named in the files of its
  class (those named after it, or declaring it);
- any other name (`vtkNPRShaderHook`, `CountOpaqueProps`, `NPR_BACKEND`, `gl_FragDepth`) must
  occur as a whole word in the project's code (C++, GLSL, CMake, Python, the plugin's XML).
Names of VTK's own (`VTK::`, `vtkOpaquePass`, ...) are looked up in VTK's headers when they are
installed (the VTK include folder CMake found, given with --vtk-include).
Exits 1 naming each name the code lacks and its line.
"""
import argparse
import fnmatch
import os
import re
import subprocess
import sys

REPOSITORY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CODE_SUFFIXES = (".h", ".cxx", ".glsl", ".cmake", ".txt", ".py", ".xml", ".in", ".module", ".sh",
                 ".plugin")
BACKTICKED = re.compile(r"`([^`\s]+)`")


def tracked_files():
    """The repository's files as git lists them (tracked and untracked, not ignored), or every
    file outside build folders where git or the repository's history is absent."""
    try:
        output = subprocess.run(["git", "-C", REPOSITORY, "ls-files", "--cached", "--others",
                                 "--exclude-standard"], check=True, capture_output=True,
                                text=True).stdout
        paths = output.splitlines()
    except (OSError, subprocess.CalledProcessError):
        paths = []
        for folder, subfolders, names in os.walk(REPOSITORY):
            subfolders[:] = [d for d in subfolders
                             if not d.startswith(("build", ".git", "__pycache__"))]
            paths += [os.path.relpath(os.path.join(folder, n), REPOSITORY) for n in names]
    return [path for path in paths if os.path.exists(os.path.join(REPOSITORY, path))]


class Code:
    """The project's code as text, with its modules, libraries, targets and folders."""

    def __init__(self, vtk_include):
        self.files = tracked_files()
        self.folders = {os.path.dirname(path) for path in self.files}
        for folder in list(self.folders):
            while folder:
                folder = os.path.dirname(folder)
                self.folders.add(folder)
        self.texts = {}
        for path in self.files:
            if path.endswith(CODE_SUFFIXES) and not path.startswith("Documentation/"):
                with open(os.path.join(REPOSITORY, path), encoding="utf-8",
                          errors="replace") as stream:
                    self.texts[path] = stream.read()
        everything = "\n".join(self.texts.values())
        self.words = set(re.findall(r"[A-Za-z_]\w*", everything)) | self.macro_words(everything)
        self.modules, self.libraries = self._modules()
        self.targets = set(re.findall(r"add_(?:library|executable)\s*\(\s*([\w.:-]+)",
                                      "\n".join(self.texts.values())))
        self.vtk_include = vtk_include
        self.vtk_words = self._vtk_words(vtk_include)

    def _modules(self):
        modules, libraries = set(), set()
        for path, text in self.texts.items():
            if path.endswith("vtk.module"):
                name = re.search(r"^NAME\s+(\S+)", text, re.M)
                library = re.search(r"^LIBRARY_NAME\s+(\S+)", text, re.M)
                modules.add(name.group(1))
                libraries.add(library.group(1) if library else name.group(1).split("::")[-1])
        return modules, libraries

    @staticmethod
    def _vtk_words(vtk_include):
        """Every word of VTK's headers, with the methods its macros declare."""
        if not vtk_include or not os.path.isdir(vtk_include):
            return None
        words = set()
        for name in os.listdir(vtk_include):
            if name.endswith(".h"):
                words.add(name[:-2])
                with open(os.path.join(vtk_include, name), encoding="utf-8",
                          errors="replace") as stream:
                    text = stream.read()
                words |= set(re.findall(r"[A-Za-z_]\w*", text)) | Code.macro_words(text)
        return words

    @staticmethod
    def macro_words(text):
        """The methods VTK's Set/Get/Boolean macros declare in a text."""
        words = set()
        for name in re.findall(r"vtk(?:Set|Get|Boolean)\w*Macro\(\s*(\w+)", text):
            words |= {"Set" + name, "Get" + name, name + "On", name + "Off",
                      "Get%sMinValue" % name, "Get%sMaxValue" % name}
        return words

    def class_files(self, name):
        """The files named after a class, or declaring it."""
        declares = re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*%s\s*(?:final\s*)?[:{]" %
                              re.escape(name))
        return [path for path, text in self.texts.items()
                if os.path.basename(path).split(".")[0] == name or declares.search(text)]

    def path_exists(self, name):
        # <name>, NAME and * stand for any part of one name
        pattern = re.sub(r"<[^>]*>|\b[A-Z]{3,}\b", "*", name.rstrip("/"))
        candidates = self.folders | set(self.files)
        if "*" not in pattern:
            return any(path == pattern or path.endswith("/" + pattern) for path in candidates)
        return any(fnmatch.fnmatch(path, pattern) or fnmatch.fnmatch(path, "*/" + pattern)
                   for path in candidates)

    def vtk_member_problem(self, owner, member):
        """Whether VTK's class or one of its bases names the member."""
        while owner and self.is_vtk_name(owner):
            with open(os.path.join(self.vtk_include, owner + ".h"), encoding="utf-8",
                      errors="replace") as stream:
                text = stream.read()
            if re.search(r"\b%s\b" % re.escape(member), text) or member in self.macro_words(text):
                return None
            base = re.search(r"class\s+(?:\w+\s+)*%s\s*:\s*public\s+(\w+)" % owner, text)
            owner = base.group(1) if base else None
        return "VTK's class does not name %s" % member

    def is_vtk_name(self, name):
        """A class of VTK's (a header of that name); None where VTK's headers are not known."""
        if self.vtk_include is None:
            return None
        return os.path.isfile(os.path.join(self.vtk_include, name + ".h"))

    def is_vtk_word(self, name):
        return self.vtk_words is not None and name in self.vtk_words


def looks_like_path(name, code):
    """A name ending as code files do, or whose first part is one of the repository's."""
    if not re.fullmatch(r"[\w./<>*+-]+", name) or name.startswith("//"):
        return False
    first = name.split("/")[0]
    return name.endswith(CODE_SUFFIXES) or ("/" in name and (
        first in ("build", "bin", "") or any(os.path.basename(f) == first for f in code.folders)))


def is_output(name):
    """A build tree's, an installed system's, a program's or another project's file."""
    if name.startswith(("build/", "bin/", "/", "Testing/Temporary")):
        return True
    return "/" not in name and not name.startswith(("vtkNPR", "npr", "Test", "test_"))


def is_code_word(name):
    """Names the project or VTK could define: vtk*, npr*, NPR_* and CamelCase."""
    return bool(re.fullmatch(r"(vtk|npr|NPR_)\w+|[A-Z][a-z]\w*[A-Z]\w*", name))


def is_ours(name):
    return name.startswith(("vtkNPR", "npr", "NPR"))


def member_problem(code, owner, member):
    files = code.class_files(owner)
    if files:
        named = any(re.search(r"\b%s\b" % re.escape(member), code.texts[f]) or
                    member in code.macro_words(code.texts[f]) for f in files)
        return None if named else "%s does not name %s" % (owner, member)
    if code.is_vtk_name(owner):
        return code.vtk_member_problem(owner, member)
    return "no class %s" % owner if is_ours(owner) else None  # another project's class


def problem(code, name):
    """Why the code lacks the name, or None."""
    name = re.sub(r"\(\)$", "", name)
    if looks_like_path(name, code):
        if is_output(name) or code.path_exists(name) or code.path_exists(name + ".in"):
            return None
        return None if code.is_vtk_name(name[:-2]) else "no such file or folder"
    if name.endswith("::"):
        return None  # a namespace on its own
    if name.startswith("NPR::"):
        return None if name in code.modules or name in code.targets else "no such module"
    library = re.fullmatch(r"lib(vtk\w+NPR)(\.so[.\d]*)?", name)
    if library:
        return None if library.group(1) in code.libraries else "no such library"
    if name.startswith("vtknpr."):
        first = name.split(".")[1]
        found = (first in code.libraries or first in code.words or
                 code.path_exists("Rendering/Python/vtknpr/%s.py" % first))
        return None if found else "not in the vtknpr package"
    if re.fullmatch(r"\w+(::~?\w+)+", name) and not name.startswith(("VTK::", "std::")):
        owner, member = name.rsplit("::", 1)
        return member_problem(code, owner.split("::")[-1], member)
    if not re.fullmatch(r"\w+", name) or not is_code_word(name):
        return None  # a value, a flag, a command, a style name, another library's function
    if name in code.words or (not is_ours(name) and code.is_vtk_word(name)):
        return None
    return "not in the code"


def check_page(code, page):
    failures = 0
    with open(page, encoding="utf-8") as stream:
        lines = stream.read().split("\n")
    for number, line in enumerate(lines, start=1):
        for name in BACKTICKED.findall(line):
            why = problem(code, name)
            if why:
                failures += 1
                print("FAIL %s:%d: `%s`: %s" % (os.path.relpath(page, REPOSITORY), number, name,
                                                why))
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("pages", nargs="+")
    parser.add_argument("--vtk-include", help="VTK's include folder (its class headers)")
    args = parser.parse_args()
    code = Code(args.vtk_include)
    failures = sum(check_page(code, page) for page in args.pages)
    names = sum(len(BACKTICKED.findall(open(page, encoding="utf-8").read())) for page in args.pages)
    print("%d names checked in %d pages, %d not in the code" % (names, len(args.pages), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
