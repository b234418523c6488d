#!/usr/bin/env python3
"""Build the HTML pages of the FlowRecon plugin's help (Plugin/CMakeLists.txt runs this).

    make_help.py --xmlpatterns X --xsl-dir D --help-dir H --out OUT --stamp S
                 --xml A.xml [B.xml ...] [--picture P.png ...]

One page per proxy, named <group>.<name>.html as ParaView's "?" button looks it up
(qthelp://FlowRecon.org/FlowRecon/<group>.<name>.html): the page ParaView 5.11 makes
from the server-manager XML (its own XSL stylesheets in D, run with xmlpatterns X),
followed by the fragment H/sections/<group>.<name>.html (outputs and arrays in the
paper's terms, pictures) and a link to the overview H/index.html, which is copied as
the help's home page with the pictures P.

Why not ParaView's own generation alone: paraview_client_documentation (5.11) splits
its HTML output into pages with a CMake list, and an unbalanced ']' in a documentation
text (FlowReconstruction.xml: "for t_r in (Threshold_k, Threshold_k+1]") makes CMake
stop splitting there, so the following proxies get no page of their own. The pages
written here replace ParaView's in the help (paraview_add_plugin's DOCUMENTATION_DIR is
copied over them before qhelpgenerator runs).

Fails (non-zero exit, nothing half-written is kept as up to date) when a proxy has no
page, a fragment names no proxy, or a page refers to a missing picture or page.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET


def fail(message):
    sys.stderr.write("make_help.py: %s\n" % message)
    sys.exit(1)


def run(cmd):
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    if result.returncode != 0:
        fail("%s failed (%d): %s" % (" ".join(cmd), result.returncode,
                                     result.stderr.decode(errors="replace")))
    return result.stdout.decode("utf-8")


def proxies_of(xml_files):
    """(group, name, label) of every source, reader and filter the XML files define: the
    proxies a user creates, whose panel has the "?" button."""
    found = []
    for path in xml_files:
        root = ET.parse(path).getroot()
        for group in root.iter("ProxyGroup"):
            if group.get("name") not in ("sources", "filters"):
                continue
            for proxy in group:
                if proxy.get("name"):
                    found.append((group.get("name"), proxy.get("name"),
                                  proxy.get("label", proxy.get("name"))))
    return found


def rst_markup(page):
    """The markup ParaView 5.11 applies to its generated pages (bold, italics, paragraphs)."""
    page = re.sub(r"\*\*([^*]+)\*\*", r"<b>\1</b>", page)
    page = re.sub(r"\*([^*]+)\*", r"<em>\1</em>", page)
    return page.replace("\n\n", "\n<p>\n")


NAV = ('<p><a href="index.html">FlowRecon help</a>: the pipeline, the outputs and their '
       'arrays in the terms of Cazals &amp; Cohen-Steiner, <i>Reconstructing 3D compact '
       'sets</i> (2009).</p>\n')


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--xmlpatterns", required=True)
    parser.add_argument("--xsl-dir", required=True)
    parser.add_argument("--help-dir", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--stamp", required=True)
    parser.add_argument("--xml", nargs="+", required=True)
    parser.add_argument("--picture", nargs="*", default=[])
    args = parser.parse_args()

    if os.path.exists(args.stamp):
        os.remove(args.stamp)
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    os.makedirs(args.out)
    work = args.out + ".work"
    os.makedirs(work, exist_ok=True)

    # 1. ParaView's pages, as paraview_client_documentation makes them
    xsl = lambda name: os.path.join(args.xsl_dir, name)  # noqa: E731
    merged = "<xml>\n" + "".join(
        run([args.xmlpatterns, xsl("paraview_servermanager_convert_xml.xsl"), path])
        for path in args.xml) + "</xml>\n"
    merged_path = os.path.join(work, "FlowRecon_doc.xml")
    with open(merged_path, "w", encoding="utf-8") as f:
        f.write(merged)
    indexed_path = os.path.join(work, "FlowRecon_doc_index.xml")
    run([args.xmlpatterns, "-output", indexed_path,
         xsl("paraview_servermanager_convert_categoryindex.xsl"), merged_path])
    html = run([args.xmlpatterns, xsl("paraview_servermanager_convert_html.xsl"), indexed_path])
    pages = {}
    for chunk in re.split(r"(?<=</html>)\s*(?=<html>)", html.strip()):
        match = re.search(r'<meta name="filename" contents="([^"]*)"', chunk)
        if not match:
            fail("a generated page has no file name")
        pages[match.group(1)] = rst_markup(chunk)

    # 2. every proxy has its page; add the FlowRecon fragment and the link to the overview
    proxies = proxies_of(args.xml)
    sections = os.path.join(args.help_dir, "sections")
    fragments = {f for f in os.listdir(sections) if f.endswith(".html")}
    for group, name, label in proxies:
        filename = "%s.%s.html" % (group, name)
        if filename not in pages:
            fail("no page %s for the proxy %s (%s)" % (filename, name, label))
        page = pages[filename]
        page = page.replace("<body>", "<body>\n" + NAV, 1)
        if filename in fragments:
            with open(os.path.join(sections, filename), encoding="utf-8") as f:
                page = page.replace("</body>", f.read() + "\n</body>", 1)
            fragments.discard(filename)
        pages[filename] = page
    if fragments:
        fail("fragments for no proxy: %s" % sorted(fragments))

    for filename, page in pages.items():
        with open(os.path.join(args.out, filename), "w", encoding="utf-8") as f:
            f.write(page + "\n")
    shutil.copy(os.path.join(args.help_dir, "index.html"), args.out)
    for picture in args.picture:
        shutil.copy(picture, args.out)

    # 3. links and pictures resolve inside the help
    present = set(os.listdir(args.out))
    for filename in sorted(f for f in present if f.endswith(".html")):
        with open(os.path.join(args.out, filename), encoding="utf-8") as f:
            text = f.read()
        for target in re.findall(r'(?:src|href)="([^"#:]+)(?:#[^"]*)?"', text):
            if target not in present:
                fail("%s refers to %s, which is not in the help" % (filename, target))
    with open(args.stamp, "w") as f:
        f.write("\n".join(sorted(present)) + "\n")
    print("make_help.py: %d pages, %d pictures in %s" % (
        len([f for f in present if f.endswith(".html")]), len(args.picture), args.out))


if __name__ == "__main__":
    main()
