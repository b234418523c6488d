"""Writes the seed corpora of the fuzz targets into Testing/Fuzz/corpus.

Usage: /usr/bin/python3 Testing/Fuzz/make_corpus.py [FUZZ_STORED_COMPLEX]

point_cloud_reader: byte 0 picks the extension (.xyz .csv .ply .off .obj .vtk
.vtp .stl .las = 0..8), the rest is the file: the clouds of Testing/Data and
small clouds in every format (ASCII and binary PLY and STL, LAS 1.2 and 1.4,
legacy VTK ASCII and binary, VTK XML ASCII, raw appended, LZ4 and zlib
compressed).
core: byte 0 = flags (coordinate mode | eager << 2 | t_p choice << 3), byte 1 =
scale, then coordinates (see FuzzCore.cxx).
stored_complex: written by the fuzz_stored_complex binary itself
(FLOWRECON_FUZZ_WRITE_SEEDS), when its path is given.
"""
import math
import os
import random
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")
DATA = os.path.join(HERE, "..", "Data")
EXT = [".xyz", ".csv", ".ply", ".off", ".obj", ".vtk", ".vtp", ".stl", ".las"]


def put(target, name, data):
    d = os.path.join(CORPUS, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def reader_seed(name, ext, content):
    put("point_cloud_reader", name, bytes([EXT.index(ext)]) + content)


def small_cloud(n, seed):
    r = random.Random(seed)
    return [(r.random(), r.random(), r.random()) for _ in range(n)]


def reader_corpus():
    for f in sorted(os.listdir(DATA)):
        if f.endswith(".xyz"):
            reader_seed("data_" + f, ".xyz", open(os.path.join(DATA, f), "rb").read())
    pts = small_cloud(12, 1)
    xyz = "".join("%.17g %.17g %.17g\n" % p for p in pts)
    reader_seed("comment.xyz", ".xyz", ("# a comment\n// another\n\n" + xyz.replace(" ", ",", 3)).encode())
    reader_seed("header.csv", ".csv", ("x,y,z,w\n" + "".join("%r,%r,%r,1\n" % p for p in pts)).encode())
    reader_seed("points.csv", ".csv", ("id;Points:2;Points:0;Points:1\n" +
                                      "".join("%d;%r;%r;%r\n" % (i, p[2], p[0], p[1]) for i, p in enumerate(pts))).encode())
    reader_seed("noheader.csv", ".csv", "".join("%r\t%r\t%r\n" % p for p in pts).encode())
    head = ("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n" % len(pts))
    reader_seed("ascii.ply", ".ply", (head + "".join("%r %r %r 1 2 3\n" % p for p in pts) + "3 0 1 2\n").encode())
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\n"
            "property double y\nproperty double z\nproperty float nx\nproperty float ny\n"
            "property float nz\nend_header\n" % len(pts))
    body = b"".join(struct.pack("<3d3f", *p, 0, 0, 1) for p in pts)
    reader_seed("binary.ply", ".ply", head.encode() + body)
    head = ("ply\nformat binary_big_endian 1.0\nelement vertex %d\nproperty float x\n"
            "property float y\nproperty float z\nend_header\n" % len(pts))
    reader_seed("big_endian.ply", ".ply", head.encode() + b"".join(struct.pack(">3f", *p) for p in pts))
    reader_seed("cube.off", ".off", ("OFF\n# cube\n8 1 0\n" + "".join(
        "%d %d %d\n" % (i & 1, (i >> 1) & 1, (i >> 2) & 1) for i in range(8)) + "4 0 1 3 2\n").encode())
    reader_seed("colour.off", ".off", ("COFF\n%d 0 0\n" % len(pts) + "".join(
        "%r %r %r 255 0 0 255\n" % p for p in pts)).encode())
    reader_seed("mesh.obj", ".obj", ("# obj\no thing\n" + "".join("v %r %r %r\n" % p for p in pts) +
                                    "vn 0 0 1\nf 1 2 3\n").encode())
    tris = [pts[i:i + 3] for i in range(0, len(pts) - 2, 3)]
    reader_seed("ascii.stl", ".stl", ("solid cloud\n" + "".join(
        " facet normal 0 0 1\n  outer loop\n" + "".join("   vertex %r %r %r\n" % p for p in t) +
        "  endloop\n endfacet\n" for t in tris) + "endsolid cloud\n").encode())
    reader_seed("binary.stl", ".stl", b"solid binary".ljust(80) + struct.pack("<I", len(tris)) + b"".join(
        struct.pack("<12fH", 0, 0, 1, *[c for p in t for c in p], 0) for t in tris))
    for name, minor, fmt, length in (("v12.las", 2, 1, 28), ("v14.las", 4, 6, 30)):
        size = 375 if minor == 4 else 227
        head = bytearray(b"LASF" + bytes(20) + bytes([1, minor]) + bytes(size - 26))
        struct.pack_into("<HIIBHI", head, 94, size, size, 0, fmt, length, 0 if minor == 4 else len(pts))
        struct.pack_into("<6d", head, 131, 0.001, 0.001, 0.001, 10.0, 20.0, 30.0)
        if minor == 4:
            struct.pack_into("<Q", head, 247, len(pts))
        body = b"".join(struct.pack("<3i", *(int(c * 1000) for c in p)) + bytes(length - 12) for p in pts)
        reader_seed(name, ".las", bytes(head) + body)
    try:
        from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray
        from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
        from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    except ImportError:
        print("no vtkmodules: .vtk and .vtp seeds skipped (use /usr/bin/python3)")
        return
    poly = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    verts = vtkCellArray()
    scalars = vtkDoubleArray()
    scalars.SetName("Temperature")
    for i, p in enumerate(pts):
        points.InsertNextPoint(p)
        verts.InsertNextCell(1)
        verts.InsertCellPoint(i)
        scalars.InsertNextValue(i * 0.5)
    poly.SetPoints(points)
    poly.SetVerts(verts)
    poly.GetPointData().AddArray(scalars)
    with tempfile.TemporaryDirectory() as tmp:
        for name, binary in (("ascii.vtk", False), ("binary.vtk", True)):
            w = vtkPolyDataWriter()
            w.SetFileName(os.path.join(tmp, name))
            w.SetInputData(poly)
            if binary:
                w.SetFileTypeToBinary()
            w.Write()
            reader_seed(name, ".vtk", open(os.path.join(tmp, name), "rb").read())
        for name, mode, compressor in (("ascii.vtp", "ascii", None), ("raw.vtp", "appended", None),
                                       ("lz4.vtp", "appended", "lz4"), ("zlib.vtp", "binary", "zlib")):
            w = vtkXMLPolyDataWriter()
            w.SetFileName(os.path.join(tmp, name))
            w.SetInputData(poly)
            if mode == "ascii":
                w.SetDataModeToAscii()
            elif mode == "binary":
                w.SetDataModeToBinary()
            else:
                w.SetDataModeToAppended()
                w.EncodeAppendedDataOff()
            if compressor == "lz4":
                w.SetCompressorTypeToLZ4()
            elif compressor == "zlib":
                w.SetCompressorTypeToZLib()
            else:
                w.SetCompressorTypeToNone()
            w.Write()
            reader_seed(name, ".vtp", open(os.path.join(tmp, name), "rb").read())


def core_seed(name, mode, eager, tp, scale, coords):
    flags = mode | (eager << 2) | (tp << 3)
    if mode == 0:
        body = bytes(int(c) & 7 for c in coords)
    elif mode == 1:
        body = bytes(int(c) & 255 for c in coords)
    elif mode == 2:
        body = b"".join(struct.pack("<H", int(c * 65536) & 0xFFFF) for c in coords)
    else:
        body = b"".join(struct.pack("<d", c) for c in coords)
    put("core", name, bytes([flags, scale & 255]) + body)


def core_corpus():
    flat = lambda pts: [c for p in pts for c in p]
    tetra = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
    core_seed("tetrahedron", 1, 1, 0, 0, flat(tetra))
    core_seed("grid4", 0, 0, 2, 0, flat([(i, j, k) for i in range(4) for j in range(4) for k in range(4)]))
    core_seed("grid_eager", 0, 1, 1, 0, flat([(i, j, k) for i in range(3) for j in range(3) for k in range(2)]))
    r = random.Random(7)
    cube = [(r.random(), r.random(), r.random()) for _ in range(40)]
    core_seed("cube40", 2, 0, 2, 0, flat(cube))
    core_seed("cube40_eager", 2, 1, 0, 0, flat(cube[:30]))
    sphere = []
    for i in range(48):
        z = 1 - 2 * (i + 0.5) / 48
        t = math.pi * (1 + 5 ** 0.5) * i
        s = math.sqrt(1 - z * z)
        sphere.append((s * math.cos(t), s * math.sin(t), z))
    core_seed("sphere48", 3, 0, 2, 0, flat(sphere))
    core_seed("sphere_eager", 3, 1, 3, 0, flat(sphere[:32]))
    core_seed("sphere_huge", 3, 0, 2, 125, flat(sphere[:20]))     # x 2^1040 -> inf
    core_seed("sphere_tiny", 3, 0, 2, -124, flat(sphere[:20]))    # x 2^-1000, near denormals
    torus = []
    for i in range(60):
        u, v = 2 * math.pi * r.random(), 2 * math.pi * r.random()
        torus.append(((1 + 0.35 * math.cos(v)) * math.cos(u), (1 + 0.35 * math.cos(v)) * math.sin(u),
                      0.35 * math.sin(v)))
    core_seed("torus60", 3, 0, 2, 0, flat(torus))
    dup = [(r.randrange(-3, 4), r.randrange(-3, 4), r.randrange(-3, 4)) for _ in range(20)]
    core_seed("duplicates", 1, 0, 2, 0, flat(dup + dup[:10]))
    core_seed("coplanar", 1, 0, 0, 0, flat([(i, j, 0) for i in range(3) for j in range(3)]))
    core_seed("nan", 3, 0, 0, 0, flat(tetra) + [float("nan"), 0.0, 0.0])


def main():
    reader_corpus()
    core_corpus()
    if len(sys.argv) > 1:
        d = os.path.join(CORPUS, "stored_complex")
        os.makedirs(d, exist_ok=True)
        subprocess.run([sys.argv[1]], env=dict(os.environ, FLOWRECON_FUZZ_WRITE_SEEDS=d), check=True)


if __name__ == "__main__":
    main()
