"""The FlowRecon plugin in the Python of the ParaView Qt GUI, for the scripts it
runs (paraview --script=...): loaded from FLOWRECON_PLUGIN unless PV_PLUGIN_PATH
already did."""

import os

from flowrecon_testing.gui_qt import check


def load_plugin(ns, names=("FlowComplex",)):
    """Loads the plugin's filters into `ns` (the script's globals()) and checks
    that each of `names` is there."""
    from paraview.simple import LoadPlugin

    if "FlowComplex" not in ns:
        plugin = os.environ.get("FLOWRECON_PLUGIN", "")
        check(os.path.exists(plugin), "plugin %r does not exist" % plugin)
        LoadPlugin(plugin, remote=False, ns=ns)
    for name in names:
        check(name in ns, "the plugin did not define %s" % name)
