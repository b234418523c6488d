#include "OutputFiles.h"

#include "CliError.h"
#include "Interrupt.h"
#include "ProgressLine.h"
#include "VtkMessageCapture.h"

#include "vtkDataArray.h"
#include "vtkTable.h"
#include "vtkXMLWriter.h"
#include <vtksys/SystemTools.hxx>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace flowrecon::cli
{

namespace
{

// "PATH: cannot write (why)". VTK's writers report a full disk like any failed
// write; errno, reset before writing, tells it.
Error WriteFailure(const std::string& path, const std::string& why)
{
  return Failure(
    path + ": cannot write (" + (errno == ENOSPC ? "no space left on device" : why) + ")");
}

std::ofstream OpenText(const std::string& path)
{
  errno = 0;
  std::ofstream out(path);
  if (!out)
  {
    throw WriteFailure(path, errno ? std::strerror(errno) : "cannot open");
  }
  out << std::setprecision(17);
  return out;
}

// Text is written when the buffer fills and here: a full disk shows here.
void CloseText(std::ofstream& out, const std::string& path)
{
  out.close();
  if (!out)
  {
    throw WriteFailure(path, errno ? std::strerror(errno) : "write error");
  }
}

} // namespace

std::string ExtensionOf(const std::string& path)
{
  return vtksys::SystemTools::LowerCase(std::filesystem::path(path).extension().string());
}

void RequireDirectory(const std::string& path)
{
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!directory.empty() && !std::filesystem::is_directory(directory, error))
  {
    throw Failure(path + ": directory '" + directory.string() + "' does not exist");
  }
}

void WriteXML(vtkXMLWriter* writer, vtkDataObject* data, const std::string& path)
{
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToLZ4();
  writer->AddObserver(vtkCommand::ProgressEvent, ProgressLine::Make()); // Ctrl-C
  RunMessages().Clear();
  errno = 0;
  const int written = writer->Write();
  if (InterruptRequested())
  {
    std::error_code error;
    std::filesystem::remove(path, error);
    throw Interrupted();
  }
  if (!written || writer->GetErrorCode() != 0)
  {
    const std::string error = RunMessages().FirstError();
    throw WriteFailure(path, error.empty() ? "unknown error" : error);
  }
}

// Not vtkDelimitedTextWriter: VTK 9.2's writes 6 significant digits (measured:
// 0.1 + 0.2 written as 0.3; 1004 of 1008 doubles did not round-trip), with no
// precision setting, and opens its stream inside WriteTable, out of a subclass's reach.
void WriteCsv(vtkTable* table, const std::vector<const char*>& columns, const std::string& header,
  const std::string& path)
{
  std::vector<vtkDataArray*> arrays;
  for (const char* name : columns)
  {
    arrays.push_back(vtkDataArray::SafeDownCast(table->GetColumnByName(name)));
    if (!arrays.back())
    {
      throw Failure(path + ": no column " + name + " to write");
    }
  }
  std::ofstream csv = OpenText(path);
  csv << header << "\n";
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    for (std::size_t k = 0; k < arrays.size(); ++k)
    {
      csv << (k ? "," : "");
      const int type = arrays[k]->GetDataType();
      if (type != VTK_DOUBLE && type != VTK_FLOAT)
      {
        csv << static_cast<long long>(arrays[k]->GetComponent(r, 0));
      }
      else
      {
        csv << arrays[k]->GetComponent(r, 0);
      }
    }
    csv << "\n";
  }
  CloseText(csv, path);
}

void WriteDiagramCsv(const std::vector<PersistencePair>& pairs, const std::string& path)
{
  // As ostream << setprecision(17) would write them (printf's %.17g), faster.
  std::ofstream csv = OpenText(path);
  csv << "dimension,birth,death\n";
  std::string text;
  char number[32];
  auto append = [&](double value) {
    const auto end =
      std::to_chars(number, number + sizeof number, value, std::chars_format::general, 17).ptr;
    text.append(number, end);
  };
  for (const auto& p : pairs)
  {
    text += std::to_string(p.Dimension);
    text += ',';
    append(p.BirthValue);
    text += ',';
    if (std::isinf(p.DeathValue))
    {
      text += "inf";
    }
    else
    {
      append(p.DeathValue);
    }
    text += '\n';
    if (text.size() > (1 << 20))
    {
      csv.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  csv.write(text.data(), static_cast<std::streamsize>(text.size()));
  CloseText(csv, path);
}

} // namespace flowrecon::cli
