#!/usr/bin/env pvpython
"""The plugin carries its help: a Qt help file with a page per filter and reader, at
the address ParaView's "?" button asks for, explaining every output and array.

    pvpython Testing/ParaView/test_help.py QCH PLUGIN PLUGIN_XML_DIR DATA_DIR
    (QCH NO_HELP when the build has no help: reported as skipped, exit 77)

Checks, reading the .qch (an SQLite file) the way Qt's help engine does:
  - namespace FlowRecon.org, virtual folder FlowRecon: pqHelpReaction::showProxyHelp
    (ParaView 5.11) looks up qthelp://<namespace>/<namespace's base name>/<group>.<proxy>.html;
  - a page for every source, reader and filter of the plugin's XML, titled with its
    label, linking to the overview index.html (the help window's home page);
  - every picture a page shows is in the help, and is a PNG; the overview and the
    Flow Reconstruction page show at least one;
  - every block and array name of every output port of every filter, run on
    DATA_DIR/torus.xyz, is named on that filter's page (so a new array fails this test
    until it is documented);
  - the plugin library embeds this very .qch (base64, as paraview_add_plugin does).
"""
import base64
import os
import re
import sqlite3
import sys
import xml.etree.ElementTree as ET
import zlib

from paraview import servermanager, simple

from flowrecon_testing.checks import fail


def qch_files(path):
    """{file name: bytes} of the help's single namespace and folder, and the titles."""
    db = sqlite3.connect(path)
    namespaces = [r[0] for r in db.execute("SELECT Name FROM NamespaceTable")]
    folders = [r[0] for r in db.execute("SELECT Name FROM FolderTable")]
    if namespaces != ["FlowRecon.org"] or folders != ["FlowRecon"]:
        fail("namespace %s, folder %s; ParaView's ? button expects FlowRecon.org/FlowRecon"
             % (namespaces, folders))
    files, titles = {}, {}
    for name, data, title in db.execute(
            "SELECT n.Name, d.Data, n.Title FROM FileNameTable n "
            "JOIN FileDataTable d ON n.FileId = d.Id"):
        if not name:
            continue
        # qCompress: 4-byte big-endian uncompressed size, then zlib
        files[name] = zlib.decompress(bytes(data)[4:]) if data else b""
        titles[name] = title
    return files, titles


def plugin_proxies(xml_dir):
    """(group, name, label) of the sources and filters, found by XPath rather than
    by the help generator's own walk, so that a proxy it skips shows here."""
    xml_files = sorted(f for f in os.listdir(xml_dir) if f.endswith(".xml"))
    return [(group, proxy.get("name"), proxy.get("label", proxy.get("name")))
            for fname in xml_files
            for group in ("sources", "filters")
            for proxy in ET.parse(os.path.join(xml_dir, fname)).getroot().iterfind(
                f".//ProxyGroup[@name='{group}']/*[@name]")]


def names_of(obj):
    """Block names and array names of a data object (recursing into multiblocks)."""
    names = set()
    if obj.IsA("vtkMultiBlockDataSet"):
        for i in range(obj.GetNumberOfBlocks()):
            meta = obj.GetMetaData(i)
            if meta is not None and meta.Has(obj.NAME()):
                names.add(meta.Get(obj.NAME()))
            if obj.GetBlock(i) is not None:
                names |= names_of(obj.GetBlock(i))
        return names
    attrs = [obj.GetFieldData()]
    if obj.IsA("vtkDataSet"):
        attrs += [obj.GetPointData(), obj.GetCellData()]
    if obj.IsA("vtkTable"):
        attrs.append(obj.GetRowData())
    for attr in attrs:
        for k in range(attr.GetNumberOfArrays()):
            names.add(attr.GetAbstractArray(k).GetName())
    return names


def output_names(data_dir):
    """{proxy name: every block and array name of all its output ports}."""
    reader = simple.FlowReconPointCloudReader(FileName=[os.path.join(data_dir, "torus.xyz")])
    fc = simple.FlowComplex(Input=reader)
    pipeline = {
        "FlowReconPointCloudReader": reader,
        "FlowComplex": fc,
        "FlowComplexSimplification": simple.FlowComplexSimplification(Input=fc),
        "PersistenceDiagram": simple.PersistenceDiagram(Input=fc),
    }
    pipeline["FlowReconstruction"] = simple.FlowReconstruction(
        Input=pipeline["FlowComplexSimplification"])
    result = {}
    for name, proxy in pipeline.items():
        names = set()
        for port in range(proxy.GetNumberOfOutputPorts()):
            names |= names_of(servermanager.Fetch(proxy, idx=port))
        result[name] = names
    return result


# A page may leave the names its filter passes on unchanged to the page of the filter
# they come from, if it links to it.
UPSTREAM = {"FlowComplexSimplification": "FlowComplex"}


def main():
    qch, plugin, xml_dir, data_dir = sys.argv[1:5]
    if qch in ("", "NO_HELP"):
        print("the plugin was built without its help (see the configure warning): skipped")
        sys.exit(77)
    if not os.path.exists(qch):
        fail("%s does not exist" % qch)
    files, titles = qch_files(qch)
    print("%s: %s" % (qch, sorted(files)))

    def text(name):
        return files[name].decode("utf-8")

    if "index.html" not in files or "<h1>" not in text("index.html"):
        fail("no overview index.html (the help window's home page)")
    pictures = {}
    for name in files:
        if name.endswith(".html"):
            pictures[name] = re.findall(r'<img src="([^"]+)"', text(name))
            for picture in pictures[name]:
                if picture not in files or not files[picture].startswith(b"\x89PNG"):
                    fail("%s shows %s, which is not a PNG in the help" % (name, picture))
    for page in ("index.html", "filters.FlowReconstruction.html"):
        if not pictures.get(page):
            fail("%s shows no picture" % page)

    proxies = plugin_proxies(xml_dir)
    if len(proxies) < 5:
        fail("only %d proxies in %s" % (len(proxies), xml_dir))
    arrays = output_names(data_dir)
    for group, name, label in proxies:
        page = "%s.%s.html" % (group, name)
        if page not in files:
            fail("no page %s for %s: the ? button would show ParaView's generic page"
                 % (page, label))
        body = text(page)
        if titles[page] != label or 'href="index.html"' not in body:
            fail("%s: title %r (expected %r) or no link to the overview" % (
                page, titles[page], label))
        if body.count("<html>") != 1:
            fail("%s holds %d pages (ParaView's CMake list split)" % (page, body.count("<html>")))
        names = set(arrays.get(name, ()))
        if name in UPSTREAM and 'href="filters.%s.html"' % UPSTREAM[name] in body:
            names -= arrays[UPSTREAM[name]]
        missing = sorted(n for n in names
                         if not re.search(r"(?<![A-Za-z0-9_])%s(?![A-Za-z0-9_])" % re.escape(n),
                                          body))
        if missing:
            fail("%s does not explain the output names %s" % (page, missing))
        print("%s: %s, %d bytes, pictures %s, explains %d output names" % (
            page, label, len(body), pictures[page], len(arrays.get(name, ()))))

    with open(qch, "rb") as f:
        encoded = base64.b64encode(f.read())
    with open(plugin, "rb") as f:
        library = f.read()
    # ProcessXML writes the base64 text as string literals of 80 characters (split into
    # several variables); every line is contiguous in the library
    lines = [encoded[i:i + 80] for i in range(0, len(encoded), 80)]
    absent = [k for k in list(range(0, len(lines), 25)) + [len(lines) - 1]
              if lines[k] not in library]
    if absent:
        fail("%s does not embed %s (%d of its base64 lines are missing)" % (
            plugin, qch, len(absent)))
    print("%s embeds the help (%d bytes of base64)" % (plugin, len(encoded)))
    print("PASS")


if __name__ == "__main__":
    main()
