# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the npr-render test scripts share: their arguments (--npr-render, --data, --out), a run
of npr-render, a counted check and the exit status.

    from npr_cli_checks import CLI
    cli = CLI()
    rc, out, err = cli.run(model, "-o", cli.out("a.png"))
    cli.check(rc == 0, "renders")
    cli.exit()
"""
import argparse
import os
import subprocess
import sys


class CLI:
    def __init__(self, timeout=600):
        parser = argparse.ArgumentParser()
        parser.add_argument("--npr-render", required=True)
        parser.add_argument("--data", required=True)
        parser.add_argument("--out", required=True)
        self.args = parser.parse_args()
        os.makedirs(self.args.out, exist_ok=True)
        self.timeout = timeout
        self.passes = []
        self.failures = []

    def model(self, name):
        return os.path.join(self.args.data, name)

    def out(self, name):
        return os.path.join(self.args.out, name)

    def run(self, *argv):
        """npr-render's exit status, standard output and standard error."""
        # No progress line, whatever the machine's speed (the checks read stderr).
        result = subprocess.run([self.args.npr_render, *argv], capture_output=True, text=True,
                                timeout=self.timeout,
                                env=dict(os.environ, NPR_PROGRESS_SECONDS="100000"))
        return result.returncode, result.stdout, result.stderr

    def check(self, condition, message):
        print(("ok: " if condition else "FAILED: ") + message)
        (self.passes if condition else self.failures).append(message)

    def exit(self):
        print("%d passed, %d failed" % (len(self.passes), len(self.failures)))
        sys.exit(1 if self.failures else 0)
