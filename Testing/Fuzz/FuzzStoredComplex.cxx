// libFuzzer target: saved flow complexes (.vtm + pieces), read back as
// `flowrecon reconstruct COMPLEX.vtm` and `flowrecon diagram COMPLEX.vtm` do.
//
// A .vtm names several files, which a fuzzer cannot mutate together, so one
// file of a valid saved complex is substituted at a time. At start-up the
// target computes the flow complexes of 7 and of 20 fixed points and writes six
// templates into a temporary directory:
//   0  ASCII, unsimplified, with stable and unstable manifolds
//   1  ASCII, simplified (t_p = 1.5, so it has cancelled pairs, Owner arrays and
//      a PersistencePairs block)
//   2  ASCII, unsimplified, without stable manifolds (the reconstruction draws
//      them from the stored samples, which must match the stored nodes)
//   3  appended raw binary, LZ4 compressed: what `flowrecon complex` writes
//   4  ASCII, with deferred patches (Defer Patches Above 2.5, ParaView's way)
//      on a ring of 20 points, whose saddles across the ring are far above its
//      Gabriel edges: the Deferred and DeferralRatio arrays
//   5  template 4 simplified at t_p 1.5: the pairs' odd lowers and direct owners
//      (PairLowerOffsets, PairLowers, PairOwnerOffsets, PairOwners)
// Input layout: byte 0 picks the template and the file of it (file 0 is the
// .vtm, then the pieces in name order): below 128, template byte & 3 and file
// (byte >> 2) modulo its number of files; from 128, template 4 + (byte & 1) and
// file ((byte & 127) >> 1) modulo its number of files. The remaining bytes
// replace that file. Then, as the CLI does: vtkXMLMultiBlockDataReader reads
// the .vtm in a child process (VTK 9.2's reader crashes on some corrupt files;
// the CLI's child goes on with the command, this target reads again here,
// where libFuzzer counts coverage); non-finite points are refused;
// FromMultiBlock and SimplificationFromMultiBlock convert it (these are
// fuzzed directly); the
// persistence diagram of an unsimplified complex is computed, its deferred
// patches walked first (`diagram`); an
// unsimplified complex is simplified at t_p = 1.1 by vtkFlowComplexSimplification
// and vtkFlowReconstruction runs at t_r = 2 (`reconstruct`). Any outcome but a
// crash, a sanitizer report, a hang or a huge allocation is fine.
//
// FLOWRECON_FUZZ_WRITE_SEEDS=DIR makes the target write one seed per file of
// every template into DIR and exit (that is how corpus/stored_complex was made).
#include "DeferredPatches.h"
#include "FlowComplexConversion.h"
#include "IsolatedRead.h"
#include "Persistence.h"
#include "PointCloudParsing.h"
#include "Simplification.h"
#include "VtkMessageCapture.h"
#include "vtkFlowComplex.h"
#include "vtkFlowComplexSimplification.h"
#include "vtkFlowReconstruction.h"

#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkLogger.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkSmartPointer.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
struct Template
{
  std::string Vtm;                  ///< path of the .vtm
  std::vector<std::string> Files;   ///< the .vtm, then its pieces in name order
  std::vector<std::string> Content; ///< their valid bytes
};

std::string Root;
std::vector<Template> Templates;

std::string ReadAll(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteAll(const std::string& path, const char* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
}

Template WriteTemplate(vtkDataObject* complex, const std::string& name, bool ascii)
{
  Template t;
  const fs::path dir = fs::path(Root) / name;
  fs::create_directories(dir);
  t.Vtm = (dir / "complex.vtm").string();
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetFileName(t.Vtm.c_str());
  writer->SetInputData(complex);
  if (ascii)
  {
    writer->SetDataModeToAscii();
  }
  else
  {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToLZ4();
  }
  if (!writer->Write())
  {
    std::fprintf(stderr, "FuzzStoredComplex: cannot write %s\n", t.Vtm.c_str());
    std::abort();
  }
  std::vector<std::string> pieces;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
  {
    if (entry.is_regular_file() && entry.path() != fs::path(t.Vtm))
    {
      pieces.push_back(entry.path().string());
    }
  }
  std::sort(pieces.begin(), pieces.end());
  t.Files.push_back(t.Vtm);
  t.Files.insert(t.Files.end(), pieces.begin(), pieces.end());
  for (const std::string& f : t.Files)
  {
    t.Content.push_back(ReadAll(f));
  }
  return t;
}

void MakeTemplates()
{
  // Seven points in general position: a tetrahedron holding its circumcentre (a
  // maximum) and three points outside; every index occurs, pairs cancel at 1.5.
  const double xyz[7][3] = { { 1, 1.02, 0.97 }, { 1.01, -1, -0.98 }, { -0.99, 1, -1.03 },
    { -1.02, -0.97, 1 }, { 2.5, 0.3, 0.2 }, { 0.1, 2.6, -0.3 }, { -0.2, 0.3, 2.7 } };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);

  auto complexOf = [&](bool stable) {
    vtkNew<vtkFlowComplex> fc;
    fc->SetInputData(cloud);
    fc->SetComputeStableManifolds(stable);
    fc->SetComputeUnstableManifolds(true);
    fc->Update();
    vtkSmartPointer<vtkMultiBlockDataSet> out = fc->GetOutput();
    return out;
  };
  const vtkSmartPointer<vtkMultiBlockDataSet> plain = complexOf(true);
  vtkNew<vtkFlowComplexSimplification> simplification;
  simplification->SetInputData(plain);
  simplification->SetPersistenceThreshold(1.5);
  simplification->AutomaticPersistenceThresholdOff();
  simplification->Update();
  Templates.push_back(WriteTemplate(plain, "ascii", true));
  Templates.push_back(WriteTemplate(simplification->GetOutputDataObject(0), "simplified", true));
  Templates.push_back(WriteTemplate(complexOf(false), "nostable", true));
  Templates.push_back(WriteTemplate(plain, "binary", false));

  // A ring of 20 points (radius about 1, unevenly spaced and a little off its
  // plane, so that it is in general position): its saddles across the ring are
  // about six times its longest Gabriel edge's value.
  vtkNew<vtkPoints> ringPoints;
  ringPoints->SetDataTypeToDouble();
  for (int k = 0; k < 20; ++k)
  {
    const double a = 2 * 3.14159265358979 * (k + 0.05 * std::sin(1.7 * k)) / 20;
    const double r = 1 + 0.01 * std::cos(3.1 * k);
    ringPoints->InsertNextPoint(r * std::cos(a), r * std::sin(a), 0.03 * std::sin(2.3 * k + 0.4));
  }
  vtkNew<vtkPolyData> ring;
  ring->SetPoints(ringPoints);
  vtkNew<vtkFlowComplex> deferred;
  deferred->SetInputData(ring);
  deferred->SetDeferPatchesAbove(2.5);
  deferred->Update();
  vtkMultiBlockDataSet* withDeferred = deferred->GetOutput();
  auto* nodes = vtkPolyData::SafeDownCast(flowrecon::NamedBlock(withDeferred, "CriticalPoints"));
  vtkDataArray* flags = nodes ? nodes->GetPointData()->GetArray("Deferred") : nullptr;
  if (!flags || flags->GetRange()[1] != 1)
  {
    std::fprintf(stderr, "FuzzStoredComplex: the ring template has no deferred patch\n");
    std::abort();
  }
  vtkNew<vtkFlowComplexSimplification> deferredSimplified;
  deferredSimplified->SetInputData(withDeferred);
  deferredSimplified->SetPersistenceThreshold(1.5);
  deferredSimplified->AutomaticPersistenceThresholdOff();
  deferredSimplified->Update();
  Templates.push_back(WriteTemplate(withDeferred, "deferred", true));
  Templates.push_back(
    WriteTemplate(deferredSimplified->GetOutputDataObject(0), "deferred_simplified", true));
}

void RemoveRoot()
{
  std::error_code error;
  fs::remove_all(Root, error);
}

// The CLI refuses a stored complex with a non-finite point.
bool FinitePoints(vtkMultiBlockDataSet* data)
{
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(data->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    for (vtkIdType id = 0; leaf && id < leaf->GetNumberOfPoints(); ++id)
    {
      double p[3];
      leaf->GetPoint(id, p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        return false;
      }
    }
  }
  return true;
}

void ReadAsTheCliDoes(const std::string& vtm)
{
  const auto read = [&vtm](vtkXMLMultiBlockDataReader* reader) {
    reader->SetFileName(vtm.c_str());
    flowrecon::reader::UpdateCaptured(vtm, reader, "VTK XML");
  };
  try
  {
    flowrecon::reader::ReadIsolated(vtm, "VTK XML", [&read]() {
      read(vtkNew<vtkXMLMultiBlockDataReader>());
      return std::string();
    });
  }
  catch (const flowrecon::reader::ReadError&)
  {
    return; // refused with one line
  }
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  try
  {
    read(reader);
  }
  catch (const flowrecon::reader::ReadError&)
  {
    std::fprintf(stderr, "FuzzStoredComplex: read in a child, refused here\n");
    std::abort();
  }
  vtkMultiBlockDataSet* data = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  vtkDataObject* criticalPoints = flowrecon::NamedBlock(data, "CriticalPoints");
  if (!criticalPoints || !criticalPoints->GetFieldData()->GetArray("NodeCountByIndex"))
  {
    return; // not a flow complex: the CLI reads it as a point cloud
  }
  if (!FinitePoints(data))
  {
    return; // refused with one line
  }
  auto* points = vtkPolyData::SafeDownCast(criticalPoints);
  const bool simplified = points && points->GetPointData()->GetArray("Cancelled");

  // The conversions, directly.
  flowrecon::FlowComplex fc;
  std::string error;
  if (flowrecon::FromMultiBlock(data, fc, error))
  {
    flowrecon::SimplificationResult s;
    flowrecon::SimplificationFromMultiBlock(
      data, static_cast<flowrecon::Id>(fc.Nodes.size()), s, error);
    if (!simplified)
    {
      // flowrecon diagram
      try
      {
        flowrecon::WalkEveryDeferredPatch(fc, flowrecon::Progress(), "");
        flowrecon::ComputePersistence(fc.Nodes, fc.Arcs);
      }
      catch (const std::exception&)
      {
        // an error the CLI reports; not a crash
      }
    }
  }

  // flowrecon reconstruct (the filters call the conversions again).
  vtkSmartPointer<vtkDataObject> input = data;
  vtkNew<vtkFlowComplexSimplification> simplification;
  if (!simplified)
  {
    simplification->SetInputData(data);
    simplification->SetPersistenceThreshold(1.1);
    simplification->AutomaticPersistenceThresholdOff();
    if (!simplification->GetExecutive()->Update())
    {
      return;
    }
    input = simplification->GetOutputDataObject(0);
  }
  vtkNew<vtkFlowReconstruction> reconstruction;
  reconstruction->SetInputData(input);
  reconstruction->SetReconstructionThreshold(2.0);
  reconstruction->AutomaticReconstructionThresholdOff();
  reconstruction->SetMaximumThreshold(2.0);
  reconstruction->GetExecutive()->Update();
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  static tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  vtkObject::GlobalWarningDisplayOff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/fuzz-complex-XXXXXX";
  if (!mkdtemp(&pattern[0]))
  {
    std::perror("mkdtemp");
    std::abort();
  }
  Root = pattern;
  std::atexit(RemoveRoot);
  MakeTemplates();
  if (const char* seeds = std::getenv("FLOWRECON_FUZZ_WRITE_SEEDS"))
  {
    fs::create_directories(seeds);
    for (std::size_t t = 0; t < Templates.size(); ++t)
    {
      for (std::size_t f = 0; f < Templates[t].Files.size(); ++f)
      {
        const std::string name = fs::path(Templates[t].Files[f]).filename().string();
        std::string seed(1, static_cast<char>(t < 4 ? t | (f << 2) : 128 | (t - 4) | (f << 1)));
        seed += Templates[t].Content[f];
        const std::string path = (fs::path(seeds) / (std::to_string(t) + "-" +
          (f == 0 ? std::string("vtm") : name))).string();
        WriteAll(path, seed.data(), seed.size());
      }
    }
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const bool deferred = data[0] >= 128;
  Template& t = Templates[deferred ? 4 + (data[0] & 1) : data[0] & 3];
  const std::size_t file = (deferred ? (data[0] & 127) >> 1 : data[0] >> 2) % t.Files.size();
  WriteAll(t.Files[file], reinterpret_cast<const char*>(data + 1), size - 1);
  ReadAsTheCliDoes(t.Vtm);
  WriteAll(t.Files[file], t.Content[file].data(), t.Content[file].size());
  return 0;
}
