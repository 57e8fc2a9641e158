# SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
# SPDX-License-Identifier: BSD-3-Clause
"""Installed paraview-vtknpr (Utilities/check-packages.sh, in a clean chroot), with pvpython:

  pvpython check_plugin.py PLUGIN VERSION PNG

loads the installed plugin by its path, checks that ParaView reports it as loaded with VERSION,
and renders the "Render View (NPR)" (style Edges) of the plugin tests' scene into PNG, which must
have lines in it. Fails by exception."""
import os
import sys

from paraview.simple import LoadPlugin, Render, SaveScreenshot

plugin, version, output = sys.argv[1:4]
sys.path.insert(0, "/src/Plugin/Testing/Python")
from nprviewscene import create_scene, dark, read_png  # noqa: E402

LoadPlugin(plugin, ns=globals())
from paraview.modules.vtkRemotingCore import vtkPVPluginsInformation  # noqa: E402

information = vtkPVPluginsInformation()
information.CopyFromObject(None)  # this process's plugins
found = {information.GetPluginName(i): (information.GetPluginLoaded(i),
                                        information.GetPluginVersion(i),
                                        information.GetPluginFileName(i))
         for i in range(information.GetNumberOfPlugins())}
print("NPRView:", found.get("NPRView"))
assert "NPRView" in found, sorted(found)
loaded, plugin_version, path = found["NPRView"]
assert loaded, "NPRView not loaded"
from paraview import servermanager  # noqa: E402

if plugin_version == "" and servermanager.vtkSMProxyManager.GetVersionMajor() >= 6:
    # ParaView 6 reports the versions its plugin configuration files give, none for a plugin
    # loaded by path; the version the plugin returns (GetPluginVersionString) is in its binary.
    with open(plugin, "rb") as binary:
        assert b"\0" + version.encode() + b"\0" in binary.read(), "no version string in " + plugin
    print("NPRView: ParaView 6 reports no version for it; NPRView.so carries %s" % version)
else:
    assert plugin_version == version, (plugin_version, version)
assert os.path.realpath(path) == os.path.realpath(plugin), (path, plugin)

view, _ = create_scene()
view.Style = "Edges"
Render(view)
SaveScreenshot(output, view)
lines = dark(read_png(output))
print("the NPR view's image: %d line pixels" % lines)
assert lines > 500, lines
print("passed")
