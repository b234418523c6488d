"""Copies a flow complex written by `flowrecon complex` and corrupts copies of it.

Usage: CorruptXML.py COMPLEX.vtm OUTDIR

Writes OUTDIR/COMPLEX.vtm (with its folder), whose StableManifolds piece has
its last cell offset raised by 2^32 (64-bit offsets, as older versions wrote
them) or to about 2^31 (32-bit ones), and OUTDIR/cloud.vtp, a copy of the
CriticalPoints piece with its last vertex offset raised the same way. VTK 9.2's
reader sizes the connectivity by that offset: 32 or 8 GB. The pieces are LZ4
compressed, but an LZ4 block always ends with 5 literal bytes, so the high
bytes of the last offset can be edited in place. And OUTDIR/noprimary.vtm, the
.vtm with its <vtkMultiBlockDataSet> element renamed.
"""
import os
import re
import shutil
import struct
import sys


def raise_last_offset(path, section):
    data = bytearray(open(path, "rb").read())
    appended = data.index(b"<AppendedData")
    header = bytes(data[:appended])
    match = re.search(
        rb"<" + section + rb">.*?<DataArray type=\"(Int32|Int64)\"[^>]*Name=\"offsets\"[^>]*offset=\"\s*(\d+)",
        header, re.S)
    if not match:
        sys.exit(path + ": no Int32 or Int64 offsets in <" + section.decode() + ">")
    wide = match.group(1) == b"Int64"
    start = data.index(b"_", appended) + 1 + int(match.group(2))
    if b'header_type="UInt32"' not in header or b"vtkLZ4DataCompressor" not in header:
        sys.exit(path + ": expected UInt32 headers and LZ4 compression")
    blocks = struct.unpack_from("<I", data, start)[0]
    sizes = struct.unpack_from("<%dI" % blocks, data, start + 12)
    end = start + 12 + 4 * blocks + sum(sizes)
    if wide:
        if data[end - 4:end] != b"\0\0\0\0":
            sys.exit(path + ": the last offset is not below 2^32")
        data[end - 4] = 1  # byte 4 of the little-endian Int64
    else:
        if data[end - 1] != 0:
            sys.exit(path + ": the last offset is not below 2^24")
        data[end - 1] = 0x7F  # the top byte of the little-endian Int32
    open(path, "wb").write(data)


source, outdir = sys.argv[1], sys.argv[2]
name = os.path.splitext(os.path.basename(source))[0]
shutil.rmtree(outdir, ignore_errors=True)
os.makedirs(outdir)
shutil.copy(source, outdir)
shutil.copytree(os.path.join(os.path.dirname(source), name), os.path.join(outdir, name))
raise_last_offset(os.path.join(outdir, name, name + "_2.vtu"), b"Cells")
cloud = os.path.join(outdir, "cloud.vtp")
shutil.copy(os.path.join(outdir, name, name + "_0.vtp"), cloud)
raise_last_offset(cloud, b"Verts")
# A .vtm whose <vtkMultiBlockDataSet> element lost its name (a fuzzer's find):
# VTK 9.2's reader dereferenced the missing element (SEGV at 0xbc).
vtm = open(os.path.join(outdir, name + ".vtm")).read()
if "<vtkMultiBlockDataSet>" not in vtm:
    sys.exit(source + ": expected a <vtkMultiBlockDataSet> element")
# The field data goes: VTK's parser reads a file in blocks and refuses one of
# several blocks on its own ("junk after document element", also one line), so
# the null element is reached only when the file fits one block.
vtm = re.sub(r"\s*<FieldData>.*?</FieldData>", "", vtm, flags=re.S)
open(os.path.join(outdir, "noprimary.vtm"), "w").write(
    vtm.replace("<vtkMultiBlockDataSet>", "<AppendedDatakDataSet>", 1))
