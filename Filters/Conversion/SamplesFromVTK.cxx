#include "SamplesFromVTK.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtksys/SystemTools.hxx"

#include <cmath>

namespace flowrecon
{

bool ExtractSamples(vtkDataObject* input, std::vector<Point3>& points, std::string& error)
{
  points.clear();
  if (auto* ds = vtkDataSet::SafeDownCast(input))
  {
    const vtkIdType n = ds->GetNumberOfPoints();
    points.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      ds->GetPoint(i, points[i].data());
    }
    return true;
  }
  if (auto* table = vtkTable::SafeDownCast(input))
  {
    vtkDataArray* cols[3] = { nullptr, nullptr, nullptr };
    const char* names[3][3] = { { "x", "points:0", "coordsx" }, { "y", "points:1", "coordsy" },
      { "z", "points:2", "coordsz" } };
    std::vector<vtkDataArray*> numeric;
    for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
    {
      auto* arr = vtkDataArray::SafeDownCast(table->GetColumn(c));
      if (!arr || arr->GetNumberOfComponents() != 1)
      {
        continue;
      }
      numeric.push_back(arr);
      const std::string name = vtksys::SystemTools::LowerCase(arr->GetName() ? arr->GetName() : "");
      for (int k = 0; k < 3; ++k)
      {
        for (const char* candidate : names[k])
        {
          if (!cols[k] && name == candidate)
          {
            cols[k] = arr;
          }
        }
      }
    }
    if (!(cols[0] && cols[1] && cols[2]))
    {
      if (numeric.size() < 3)
      {
        error = "the table has fewer than three numeric columns";
        return false;
      }
      std::copy(numeric.begin(), numeric.begin() + 3, cols);
    }
    const vtkIdType n = table->GetNumberOfRows();
    points.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        points[i][k] = cols[k]->GetComponent(i, 0);
      }
    }
    return true;
  }
  error = std::string("unsupported input type ") + (input ? input->GetClassName() : "(none)");
  return false;
}

} // namespace flowrecon
