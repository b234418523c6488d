// Why vtkPointCloudReader keeps its own point parsers: each case
// runs a point reader this machine's libraries provide (CGAL 5.5's; VTK 9.2's
// PLY, OBJ, STL, simple-points, PTS and delimited-text readers) on a bad file that
// vtkPointCloudReader refuses or reads right (see TestPointCloudReader's
// TestWhatLibraryReadersMisread), and checks that the library still gets it
// wrong. A failed check here means the library was fixed:
// that format's parser may then be swapped for it without losing a test's
// meaning. The hang of CGAL's read_PLY on a large element without properties is
// not probed: telling a hang from slowness needs a clock.
// Usage: TestLibraryReaderDefects WORKDIR (files go to WORKDIR/LibraryReaders).

#include "Check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/STL.h>
#include <CGAL/IO/read_off_points.h>
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/IO/read_xyz_points.h>

#include "vtkCallbackCommand.h"
#include "vtkDelimitedTextReader.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPTSReader.h"
#include "vtkSTLReader.h"
#include "vtkPoints.h"
#include "vtkSimplePointsReader.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Polygons = std::vector<std::vector<std::size_t>>;

std::string Directory;

std::string Write(const std::string& name, const std::string& text)
{
  const std::string path = Directory + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

bool Is(const Point& p, double x, double y, double z)
{
  return p.x() == x && p.y() == y && p.z() == z;
}

// CGAL's readers report to std::cerr; the probes only look at what they return.
class QuietCerr
{
public:
  QuietCerr()
    : Saved(std::cerr.rdbuf(this->Sink.rdbuf()))
  {
  }
  ~QuietCerr() { std::cerr.rdbuf(this->Saved); }

private:
  std::ostringstream Sink;
  std::streambuf* Saved;
};

// True if `read` kills its process (a signal, or an exit other than 0 and 1),
// run in a child whose address space is limited to 2 GB.
bool Dies(const std::function<bool()>& read)
{
  std::cout.flush();
  const pid_t child = fork();
  if (child == 0)
  {
    const rlimit limit{ 2ull << 30, 2ull << 30 };
    setrlimit(RLIMIT_AS, &limit);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDERR_FILENO); // the child's last words (std::terminate's)
    QuietCerr quiet;
    _exit(read() ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) > 1);
}

struct VtkErrors
{
  int Count = 0;
  vtkNew<vtkCallbackCommand> Observer;
  explicit VtkErrors(vtkObject* reader)
  {
    this->Observer->SetClientData(&this->Count);
    this->Observer->SetCallback(
      [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
    reader->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
};

const std::string AsciiPlyHeader = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                   "property float y\nproperty float z\nend_header\n";

void CgalXyz()
{
  QuietCerr quiet;
  std::vector<Point> p;
  // "3x" is read as 3.
  CHECK(CGAL::IO::read_XYZ(Write("trailing.xyz", "1 2 3x\n"), std::back_inserter(p)) &&
    p.size() == 1 && Is(p[0], 1, 2, 3));
  // "1.2.3 4" is read as (1.2, 0.3, 4).
  p.clear();
  CHECK(CGAL::IO::read_XYZ(Write("dots.xyz", "1.2.3 4\n"), std::back_inserter(p)) &&
    p.size() == 1 && Is(p[0], 1.2, 0.3, 4));
  // A first line it cannot parse is taken for a point count: that point is
  // lost, without an error.
  p.clear();
  CHECK(CGAL::IO::read_XYZ(Write("hex.xyz", "0x10 2 3\n4 5 6\n"), std::back_inserter(p)) &&
    p.size() == 1 && Is(p[0], 4, 5, 6));
}

void CgalOff()
{
  QuietCerr quiet;
  std::vector<Point> p;
  // Three vertices announced, two given: accepted.
  CHECK(CGAL::IO::read_OFF(Write("truncated.off", "OFF\n3 0 0\n0 0 0\n1 1 1\n"),
          std::back_inserter(p)) &&
    p.size() == 2);
  // The polygon soup reader reads "1.2.3 4 5" as (1.2, 0.3, 4).
  p.clear();
  Polygons polygons;
  CHECK(CGAL::IO::read_OFF(Write("dots.off", "OFF\n2 0 0\n0 0 0\n1.2.3 4 5\n"), p, polygons) &&
    p.size() == 2 && Is(p[1], 1.2, 0.3, 4));
}

void CgalObj()
{
  QuietCerr quiet;
  std::vector<Point> p;
  Polygons polygons;
  // A cloud (vertices without faces) is refused.
  CHECK(!CGAL::IO::read_OBJ(Write("cloud.obj", "v 1 2 3\nv 4 5 6\n"), p, polygons));
  // "1.2.3 4 5" is read as (1.2, 0.3, 4).
  p.clear();
  polygons.clear();
  CHECK(CGAL::IO::read_OBJ(Write("dots.obj", "v 1 2 3\nv 1.2.3 4 5\nf 1 2 1\n"), p, polygons) &&
    p.size() == 2 && Is(p[1], 1.2, 0.3, 4));
}

void CgalPly()
{
  std::vector<Point> p;
  const auto read = [&p](const std::string& path) {
    p.clear();
    return CGAL::IO::read_PLY(path, std::back_inserter(p));
  };
  // Integer coordinates crash it.
  const std::string ints = Write("int.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty int y\n"
    "property int z\nend_header\n1 2 -3\n");
  CHECK(Dies([&] { return read(ints); }));
  // A list's announced length is allocated before it is read (8 GB here).
  const std::string list = Write("huge_list.ply",
    "ply\nformat binary_little_endian 1.0\nelement info 1\nproperty list uint int ids\n"
    "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
    "end_header\n\xff\xff\xff\x7f" +
      std::string(12, '\0'));
  CHECK(Dies([&] { return read(list); }));

  QuietCerr quiet;
  // An unknown property type is skipped, and the rest misread.
  CHECK(read(Write("int64.ply",
          "ply\nformat ascii 1.0\nelement vertex 1\nproperty int64 id\nproperty float x\n"
          "property float y\nproperty float z\nend_header\n9 1 2 3\n")) &&
    p.size() == 1 && !Is(p[0], 1, 2, 3));
  // A missing z is read as 0.
  CHECK(read(Write("noz.ply",
          "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
          "end_header\n1 2\n")) &&
    p.size() == 1 && Is(p[0], 1, 2, 0));
  // "1.2.3" is read as 1.2, then 0.3 (each rounded to float, see below).
  CHECK(read(Write("dots.ply", AsciiPlyHeader + "1 2 3\n4 5 6\n1.2.3 8 9\n")) && p.size() == 3 &&
    Is(p[2], static_cast<double>(1.2f), static_cast<double>(0.3f), 8));
  // A header line it does not know is ignored.
  CHECK(read(Write("header_line.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nbogus line\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n1 2 3\n")));
  // The text of a float property is rounded to float.
  CHECK(read(Write("float_text.ply",
          "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
          "property float z\nend_header\n0.1 0.2 0.3\n")) &&
    p.size() == 1 && p[0].x() == static_cast<double>(0.1f));
}

// A binary STL of one triangle with these vertices (9 floats), announcing
// `announced` triangles; little-endian, as the format is.
std::string BinaryStl(const std::array<float, 9>& vertices, std::uint32_t announced)
{
  std::string bytes(80, ' ');
  const auto append = [&bytes](std::uint32_t bits) {
    for (int k = 0; k < 4; ++k)
    {
      bytes += static_cast<char>((bits >> (8 * k)) & 0xff);
    }
  };
  const auto appendFloat = [&append](float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    append(bits);
  };
  append(announced);
  for (const float f : { 0.0f, 0.0f, 1.0f })
  {
    appendFloat(f);
  }
  for (const float f : vertices)
  {
    appendFloat(f);
  }
  return bytes + std::string(2, '\0');
}

const std::string DotsStl = "solid d\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                            "vertex 0 1.2.3 0\nendloop\nendfacet\nendsolid d\n";

void CgalStl()
{
  QuietCerr quiet;
  using Triangles = std::vector<std::array<int, 3>>;
  std::vector<std::array<double, 3>> p;
  Triangles t;
  // "1.2.3 0" is read as (1.2, 0.3), the 0 skipped as an unknown word.
  std::ifstream dots(Write("dots.stl", DotsStl), std::ios::binary);
  CHECK(CGAL::IO::read_STL(dots, p, t) && p.size() == 3 && p[2][1] == 1.2 && p[2][2] == 0.3);
  // A NaN breaks its map's ordering: a binary triangle with one NaN keeps 2 of
  // its 3 distinct vertices, and the read succeeds.
  p.clear();
  t.clear();
  std::ifstream nan(
    Write("nan.stl", BinaryStl({ std::nanf(""), 0, 0, 1, 0, 0, 0, 1, 0 }, 1)), std::ios::binary);
  CHECK(CGAL::IO::read_STL(nan, p, t) && p.size() == 2);
}

void VtkStl()
{
  {
    vtkNew<vtkSTLReader> reader;
    VtkErrors errors(reader);
    // Two triangles announced, one given: read without an error.
    reader->SetFileName(Write("truncated.stl", BinaryStl({ 0, 0, 0, 1, 0, 0, 0, 1, 0 }, 2)).c_str());
    reader->Update();
    CHECK(errors.Count == 0 && reader->GetOutput()->GetNumberOfPoints() == 3);
  }
  {
    vtkNew<vtkSTLReader> reader;
    VtkErrors errors(reader);
    // "1.2.3 0" is read as (1.2, 0.3) in float, without an error.
    reader->SetFileName(Write("dots.stl", DotsStl).c_str());
    reader->Update();
    vtkPolyData* out = reader->GetOutput();
    CHECK(errors.Count == 0 && out->GetNumberOfPoints() == 3);
    if (out->GetNumberOfPoints() == 3)
    {
      CHECK(out->GetPoint(2)[1] == static_cast<double>(1.2f) && out->GetPoint(2)[2] == static_cast<double>(0.3f));
    }
  }
}

void VtkObj()
{
  vtkNew<vtkOBJReader> reader;
  VtkErrors errors(reader);
  reader->SetFileName(Write("word.obj", "v 1 2 3\nv 4 five 6\n").c_str());
  reader->Update();
  // "five" is read as 0, without an error.
  vtkPolyData* out = reader->GetOutput();
  CHECK(errors.Count == 0 && out->GetNumberOfPoints() == 2);
  if (out->GetNumberOfPoints() == 2)
  {
    CHECK(out->GetPoint(1)[1] == 0);
  }
}

void VtkPly()
{
  {
    vtkNew<vtkPLYReader> reader;
    VtkErrors errors(reader);
    reader->SetFileName(Write("word.ply", AsciiPlyHeader + "1 2 3\n4 5 x\n7 8 9\n").c_str());
    reader->Update();
    // "x" is read as 0, without an error.
    vtkPolyData* out = reader->GetOutput();
    CHECK(errors.Count == 0 && out->GetNumberOfPoints() == 3);
    if (out->GetNumberOfPoints() == 3)
    {
      CHECK(out->GetPoint(1)[2] == 0);
    }
  }
  // A truncated ASCII file kills the process.
  const std::string cut = Write("truncated.ply", AsciiPlyHeader + "1 2 3\n4 5");
  CHECK(Dies([&cut] {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(cut.c_str());
    reader->Update();
    return reader->GetOutput()->GetNumberOfPoints() == 3;
  }));
  // Two vertices with a list each, the second cut inside its z: accepted, with
  // a warning in VTK's log, not an error of the reader.
  const auto big = [](float f) {
    std::string s(4, '\0');
    const auto* b = reinterpret_cast<const unsigned char*>(&f);
    for (int i = 0; i < 4; ++i)
    {
      s[i] = static_cast<char>(b[3 - i]);
    }
    return s;
  };
  vtkNew<vtkPLYReader> reader;
  VtkErrors errors(reader);
  reader->SetFileName(Write("truncated_binary.ply",
    "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float x\n"
    "property float y\nproperty float z\nproperty list uchar int ids\nend_header\n" +
      big(1) + big(2) + big(3) + "\x01" + std::string(4, '\0') + big(4) + big(5) + "\x40")
                        .c_str());
  reader->Update();
  CHECK(errors.Count == 0 && reader->GetOutput()->GetNumberOfPoints() == 2);
}

// VTK's own readers of xyz and pts files.
void VtkXyzPts()
{
  vtkNew<vtkSimplePointsReader> xyz;
  VtkErrors xyzErrors(xyz);
  xyz->SetFileName(Write("trailing_simple.xyz", "1 2 3x\n4 5 6\n").c_str());
  xyz->Update();
  // "3x" is read as 3 and the rest of the file is lost, without an error.
  CHECK(xyzErrors.Count == 0 && xyz->GetOutput()->GetNumberOfPoints() == 1 &&
    xyz->GetOutput()->GetPoint(0)[2] == 3);

  vtkNew<vtkPTSReader> pts;
  VtkErrors ptsErrors(pts);
  pts->SetFileName(Write("word.pts", "2\n1 2 3\n4 five 6\n").c_str());
  pts->Update();
  // One point, without an error: x from the line with "five", y and z left
  // from the line before.
  CHECK(ptsErrors.Count == 0 && pts->GetOutput()->GetNumberOfPoints() == 1 &&
    pts->GetOutput()->GetPoint(0)[0] == 4 && pts->GetOutput()->GetPoint(0)[1] == 2);
}

void VtkDelimitedText()
{
  vtkNew<vtkDelimitedTextReader> reader;
  VtkErrors errors(reader);
  reader->SetFileName(Write("rows.csv", "x,y,z\n1,2,3\n\n# note\n4,five,6\n").c_str());
  reader->SetHaveHeaders(true);
  reader->DetectNumericColumnsOn();
  reader->Update();
  // The comment is a row and the blank line is not: "five" is in row 2 of the
  // table, on line 5 of the file.
  vtkTable* table = reader->GetOutput();
  CHECK(errors.Count == 0 && table->GetNumberOfRows() == 3 && table->GetNumberOfColumns() == 3);
  if (table->GetNumberOfRows() == 3 && table->GetNumberOfColumns() == 3)
  {
    CHECK(table->GetValue(1, 0).ToString() == "# note");
    CHECK(table->GetValue(2, 1).ToString() == "five");
  }
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestLibraryReaderDefects WORKDIR\n";
    return EXIT_FAILURE;
  }
  Directory = std::string(argv[1]) + "/LibraryReaders";
  std::filesystem::create_directories(Directory);
  CgalXyz();
  CgalOff();
  CgalObj();
  CgalPly();
  CgalStl();
  VtkObj();
  VtkPly();
  VtkStl();
  VtkXyzPts();
  VtkDelimitedText();
  return check::Finish("TestLibraryReaderDefects");
}
