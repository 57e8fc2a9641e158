# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Client-server smoke test of the NPR plugin: starts a pvserver and a pvpython client connected to
it; the client loads the plugin on both sides and renders "Render View (NPR)" in the edges style
twice: on the server (remote rendering, the image sent to the client) and on the client (the
geometry delivered to it). Both must match the serial test's baseline. Fails by exception.

  pvpython TestNPRClientServer.py --pvserver PATH --pvpython PATH --plugin NPRView.so
                                  --output-dir DIR --baseline-dir DIR

The client runs as a process of its own, so that it disconnects by exiting and pvserver then exits
by itself, as after a GUI session.
"""
import argparse
import os
import socket
import subprocess
import sys
import time

ap = argparse.ArgumentParser()
ap.add_argument("--pvserver")
ap.add_argument("--pvpython")
ap.add_argument("--connect", type=int, help="(the client) the server's port")
ap.add_argument("--plugin", required=True)
ap.add_argument("--output-dir", required=True)
ap.add_argument("--baseline-dir", required=True)
args = ap.parse_args()
os.makedirs(args.output_dir, exist_ok=True)
THRESHOLD = 10  # vtkTesting's image threshold, as in TestNPRView.py


def client(port):
    from paraview.simple import Connect, GetSettingsProxy, LoadPlugin, Render, SaveScreenshot
    from vtkmodules.vtkTestingRendering import vtkTesting
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from nprviewscene import SIZE, STYLES, create_scene, dark, read_png

    Connect("127.0.0.1", port)
    LoadPlugin(args.plugin, remote=False, ns=globals())  # the client instantiates the view too
    LoadPlugin(args.plugin, remote=True, ns=globals())
    view, _ = create_scene()
    view.Style = STYLES.index("Edges")
    # The geometry size (MB) above which the server renders and sends the image.
    settings = GetSettingsProxy("RenderViewSettings")
    failures = []
    for where, threshold in (("server", 0.0), ("client", 1e6)):
        settings.RemoteRenderThreshold = threshold
        Render(view)
        path = os.path.join(args.output_dir, "cs-edges-%s.png" % where)
        SaveScreenshot(path, view, ImageResolution=SIZE)
        lines = dark(read_png(path))
        testing = vtkTesting()
        for a in ("-V", os.path.join(args.baseline_dir, "edges.png"), "-T", args.output_dir):
            testing.AddArgument(a)
        same = testing.RegressionTest(path, THRESHOLD) == vtkTesting.PASSED
        print("rendered on the %s: %d line pixels, %s the serial baseline"
              % (where, lines, "matches" if same else "DIFFERS FROM"))
        if not same or lines < 3000:
            failures.append(where)
    if failures:
        raise RuntimeError("FAIL: rendering on the " + " and ".join(failures))


def driver():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    log_path = os.path.join(args.output_dir, "pvserver.log")
    with open(log_path, "w") as log:
        server = subprocess.Popen([args.pvserver, "--server-port=%d" % port,
                                   "--force-offscreen-rendering"], stdout=log,
                                  stderr=subprocess.STDOUT)
    started = time.time()
    try:
        while "Accepting connection" not in open(log_path).read():
            if server.poll() is not None:
                raise RuntimeError("pvserver exited with %s before listening" % server.returncode)
            if time.time() > started + 60:
                raise RuntimeError("pvserver did not start listening within 60 s")
            time.sleep(0.2)
        command = [args.pvpython, "--force-offscreen-rendering", os.path.abspath(__file__),
                   "--connect", str(port), "--plugin", args.plugin,
                   "--output-dir", args.output_dir, "--baseline-dir", args.baseline_dir]
        status = subprocess.call(command, timeout=240)
        if status != 0:
            raise RuntimeError("FAIL: the client exited with %d" % status)
        status = server.wait(timeout=30)  # pvserver ends with its client's session
        if status != 0:
            raise RuntimeError("FAIL: pvserver exited with %d (log: %s)" % (status, log_path))
        print("PASS (%.1f s, server and client)" % (time.time() - started))
    finally:
        if server.poll() is None:
            server.kill()


if args.connect:
    client(args.connect)
else:
    if not (args.pvserver and args.pvpython):
        ap.error("--pvserver and --pvpython are needed")
    driver()
