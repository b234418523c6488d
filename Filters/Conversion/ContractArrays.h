// The data contract's blocks and arrays (docs/data-contract.md): finding a named block,
// making a named array, reading a required one. Shared by every conversion.
#ifndef ContractArrays_h
#define ContractArrays_h

#include "FlowComplex.h" // Id, Point3

#include "vtkDataArray.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>
#include <iterator>
#include <string>
#include <vector>

class vtkDataObject;
class vtkFieldData;
class vtkMultiBlockDataSet;
class vtkPoints;

namespace flowrecon
{

/// A new, empty array of type A named `name` (the arrays of the data contract).
template <class A>
vtkSmartPointer<A> NamedArray(const char* name, int components = 1)
{
  auto a = vtkSmartPointer<A>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  return a;
}

/// An array of type A named `name` with one value per item of `items`, `value(item)`
/// (a member pointer or a function): a column of the data contract from the core's
/// records.
template <class A, class Items, class Value>
vtkSmartPointer<A> Column(const char* name, const Items& items, Value value)
{
  auto a = NamedArray<A>(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(std::size(items)));
  vtkIdType k = 0;
  for (const auto& item : items)
  {
    a->SetValue(k++, static_cast<typename A::ValueType>(std::invoke(value, item)));
  }
  return a;
}

/// The block named `name` of `input`, or nullptr.
vtkDataObject* NamedBlock(vtkMultiBlockDataSet* input, const char* name);

/// The array `name` of `data` with `components` components and `n` tuples, else
/// nullptr with a one-line `error` naming `block`.
vtkDataArray* RequiredArray(vtkFieldData* data, const char* block, const char* name,
  int components, vtkIdType n, std::string& error);

/// Component `component` of tuple `i` as an id.
inline Id IdValue(vtkDataArray* a, vtkIdType i, int component = 0)
{
  return static_cast<Id>(a->GetComponent(i, component));
}

/// Double-precision points with the coordinates of `pts`.
vtkSmartPointer<vtkPoints> MakePoints(const std::vector<Point3>& pts);

} // namespace flowrecon

#endif
