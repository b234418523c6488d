"""ParaView opens point clouds directly, and CSV tables feed the filters.

    pvpython test_reader_proxy.py PLUGIN CLOUD.xyz WORKDIR

After LoadPlugin, OpenDataFile on .xyz, .pts and .pwn (CGAL's points with
normals, which ParaView has no reader for) files picks the plugin's reader
and yields one point per data line of the file (counted here independently);
so does a LAS 1.2 scan of the cloud written here (integers of 1e-6 from an
offset), whose points are those integers scaled back; a
CSV file read by ParaView's own CSV reader (a vtkTable) goes straight into Flow
Complex, without a Table To Points step, and gives the same node counts as the
.xyz file.
"""
import os
import struct
import sys

from paraview import servermanager
from paraview.simple import CSVReader, LoadPlugin, OpenDataFile


def main():
    plugin, cloud, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    LoadPlugin(plugin, ns=globals())
    lines = [l for l in open(cloud) if l.strip() and not l.startswith("#")]
    pts = os.path.join(work, "cloud.pts")
    with open(pts, "w") as f:  # .pts: a count line, then x y z per line
        f.write("%d\n" % len(lines))
        f.writelines(lines)
    pwn = os.path.join(work, "cloud.pwn")
    with open(pwn, "w") as f:  # .pwn: x y z nx ny nz per line
        f.writelines(" ".join(l.split()[:3]) + " 0 0 1\n" for l in lines)
    csv = os.path.join(work, "cloud.csv")
    with open(csv, "w") as f:
        f.write("x,y,z\n")
        f.writelines(",".join(l.split()[:3]) + "\n" for l in lines)

    counts = []
    for path in (cloud, pts, pwn):
        reader = OpenDataFile(path)
        assert reader.GetXMLName() == "FlowReconPointCloudReader", reader.GetXMLName()
        reader.UpdatePipeline()
        n = reader.GetDataInformation().GetNumberOfPoints()
        assert n == len(lines), (path, n, len(lines))
        fc = FlowComplex(Input=reader)
        fc.UpdatePipeline()
        counts.append(tuple(servermanager.Fetch(fc).GetFieldData()
                            .GetArray("NodeCountByIndex").GetTuple(0)))
    las = os.path.join(work, "cloud.las")
    xyz = [[float(c) for c in l.split()[:3]] for l in lines]
    ints = [[int(round((c - 1.0) / 1e-6)) for c in p] for p in xyz]
    head = bytearray(b"LASF" + bytes(20) + bytes([1, 2]) + bytes(227 - 26))
    struct.pack_into("<HIIBHI", head, 94, 227, 227, 0, 0, 20, len(ints))
    struct.pack_into("<6d", head, 131, 1e-6, 1e-6, 1e-6, 1.0, 1.0, 1.0)
    with open(las, "wb") as f:
        f.write(bytes(head) + b"".join(struct.pack("<3i", *p) + bytes(8) for p in ints))
    reader = OpenDataFile(las)
    assert reader.GetXMLName() == "FlowReconPointCloudReader", reader.GetXMLName()
    out = servermanager.Fetch(reader)
    assert out.GetNumberOfPoints() == len(ints), (out.GetNumberOfPoints(), len(ints))
    for i in (0, len(ints) // 2, len(ints) - 1):
        want = tuple(c * 1e-6 + 1.0 for c in ints[i])
        assert out.GetPoint(i) == want, (i, out.GetPoint(i), want)
    table = CSVReader(FileName=[csv])
    fc = FlowComplex(Input=table)
    fc.UpdatePipeline()
    counts.append(tuple(servermanager.Fetch(fc).GetFieldData()
                        .GetArray("NodeCountByIndex").GetTuple(0)))
    print("node counts (xyz, pts, pwn, csv):", counts)
    assert counts[0] == counts[1] == counts[2] == counts[3] and counts[0][0] == len(lines), counts
    print("PASS")


main()
