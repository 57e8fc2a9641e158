// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRCoincidentPoints.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNPRIdBuffer.h"
#include "vtkNPRPointCoordinates.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

namespace
{
using Coordinates = std::array<double, 3>;

// A key of the point's coordinates, equal for equal coordinates: 0 and -0 alike, as
// vtkMergePoints compares them.
uint64_t HashCoordinates(const Coordinates& p)
{
  uint64_t hash = 0x9e3779b97f4a7c15ULL;
  for (double value : p)
  {
    value = value == 0.0 ? 0.0 : value;
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    hash ^= bits + 0x9e3779b97f4a7c15ULL + (hash << 6) + (hash >> 2);
    hash ^= hash >> 31;
    hash *= 0xbf58476d1ce4e5b9ULL;
  }
  return hash ^ (hash >> 29);
}

// For every point, the lowest-numbered point with exactly its coordinates: the points sorted
// by key on every core, then each run of equal keys split by coordinates (distinct points share
// a key only by a rare collision, so a run holds few groups however many points it has).
std::vector<vtkIdType> FindRepresentatives(vtkPoints* points)
{
  const vtkIdType count = points->GetNumberOfPoints();
  const vtkNPRPointCoordinates data(points->GetData());
  std::vector<std::pair<uint64_t, vtkIdType>> keys(static_cast<size_t>(count));
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      Coordinates p;
      for (vtkIdType i = begin; i < end; ++i)
      {
        data.Get(i, p.data());
        keys[static_cast<size_t>(i)] = { HashCoordinates(p), i };
      }
    });
  vtkSMPTools::Sort(keys.begin(), keys.end());

  std::vector<vtkIdType> representative(static_cast<size_t>(count));
  std::vector<std::pair<Coordinates, vtkIdType>> groups;
  for (size_t start = 0; start < keys.size();)
  {
    size_t end = start + 1;
    while (end < keys.size() && keys[end].first == keys[start].first)
    {
      ++end;
    }
    groups.clear();
    for (size_t k = start; k < end; ++k) // in increasing point order: the first is the lowest
    {
      const vtkIdType id = keys[k].second;
      Coordinates p;
      data.Get(id, p.data());
      auto group = groups.begin();
      while (group != groups.end() &&
        !(group->first[0] == p[0] && group->first[1] == p[1] && group->first[2] == p[2]))
      {
        ++group;
      }
      if (group == groups.end())
      {
        groups.push_back({ p, id });
        group = groups.end() - 1;
      }
      representative[static_cast<size_t>(id)] = group->second;
    }
    start = end;
  }
  return representative;
}

// Output point numbers in the order the cells first use the merged points, with the input point
// of each one's first use (its coordinates and point data).
class Renumbering
{
public:
  explicit Renumbering(std::vector<vtkIdType> representative)
    : Representative(std::move(representative))
    , Numbers(this->Representative.size(), -1)
  {
  }

  // The output number of input point id, -1 for a point that does not exist.
  vtkIdType Map(vtkIdType id)
  {
    if (id < 0 || id >= static_cast<vtkIdType>(this->Representative.size()))
    {
      return -1;
    }
    vtkIdType& number = this->Numbers[static_cast<size_t>(this->Representative[id])];
    if (number < 0)
    {
      number = static_cast<vtkIdType>(this->FirstUse.size());
      this->FirstUse.push_back(id);
    }
    return number;
  }

  std::vector<vtkIdType> FirstUse;

private:
  std::vector<vtkIdType> Representative;
  std::vector<vtkIdType> Numbers;
};

enum CellKind
{
  Verts,
  Lines,
  Polys,
  Strips
};

// The cells kept of one kind and the input cell each came from (kept only for cell data).
struct KeptCells
{
  bool KeepSources = true;
  vtkNPRIdBuffer Offsets;
  vtkNPRIdBuffer Connectivity;
  std::vector<vtkIdType> Sources;

  KeptCells() { this->Offsets.Append(0); }

  // Room for what one kind of cells keeps at most: no growth as they are added.
  void Reserve(vtkIdType cells, vtkIdType ids)
  {
    this->Offsets.Reserve(cells);
    this->Connectivity.Reserve(ids);
    this->Sources.reserve(
      this->KeepSources ? this->Sources.size() + static_cast<size_t>(cells) : 0);
  }

  void Add(const vtkIdType* ids, size_t size, vtkIdType source)
  {
    this->Connectivity.Append(ids, static_cast<vtkIdType>(size));
    this->Offsets.Append(this->Connectivity.Size());
    if (this->KeepSources)
    {
      this->Sources.push_back(source);
    }
  }

  vtkSmartPointer<vtkCellArray> Build()
  {
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(this->Offsets.Finish(), this->Connectivity.Finish());
    return cells;
  }
};

// Renumbers the cells of one kind into kept, by vtkCleanPolyData's rules: repeated consecutive
// points (and a polygon's or strip's closing repeat) removed, a cell kept as its own kind with
// enough points left, as the smaller kind only when it had no more points to begin with.
bool MergeCells(vtkCellArray* cells, CellKind kind, Renumbering& numbers, vtkIdType& cellId,
  std::array<KeptCells, 4>& kept)
{
  kept[kind].Reserve(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  static const size_t fewest[4] = { 1, 2, 3, 4 };
  std::vector<vtkIdType> merged;
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(size, ids); ++cellId)
  {
    merged.clear();
    for (vtkIdType k = 0; k < size; ++k)
    {
      const vtkIdType number = numbers.Map(ids[k]);
      if (number < 0)
      {
        return false;
      }
      if (kind == Verts || merged.empty() || number != merged.back())
      {
        merged.push_back(number);
      }
    }
    size_t left = merged.size();
    if (left > (kind == Polys ? 2u : 1u) && (kind == Polys || kind == Strips) &&
      merged.front() == merged.back())
    {
      --left;
    }
    if (left >= fewest[kind])
    {
      kept[kind].Add(merged.data(), left, cellId);
    }
    else if (left >= 1 && left == static_cast<size_t>(size))
    {
      kept[left - 1].Add(merged.data(), left, cellId);
    }
  }
  return true;
}

vtkSmartPointer<vtkIdList> ToIdList(const std::vector<vtkIdType>& ids)
{
  auto list = vtkSmartPointer<vtkIdList>::New();
  list->SetNumberOfIds(static_cast<vtkIdType>(ids.size()));
  std::copy(ids.begin(), ids.end(), list->GetPointer(0));
  return list;
}

vtkSmartPointer<vtkIdList> Sequence(size_t count)
{
  auto list = vtkSmartPointer<vtkIdList>::New();
  list->SetNumberOfIds(static_cast<vtkIdType>(count));
  for (size_t i = 0; i < count; ++i)
  {
    list->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
  }
  return list;
}

// to[i] = from[firstUse[i]] for xyz tuples of one plain array type, on every core.
template <typename ArrayT>
bool GatherCoordinates(
  vtkDataArray* fromArray, vtkDataArray* toArray, const std::vector<vtkIdType>& firstUse)
{
  ArrayT* from = ArrayT::FastDownCast(fromArray);
  ArrayT* to = ArrayT::FastDownCast(toArray);
  if (!from || !to || from->GetNumberOfComponents() != 3 || firstUse.empty())
  {
    return false;
  }
  const auto* source = from->GetPointer(0);
  auto* target = to->GetPointer(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(firstUse.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::copy_n(source + 3 * firstUse[static_cast<size_t>(i)], 3, target + 3 * i);
      }
    });
  return true;
}

// The merged points: coordinates and point data of each one's first use. The coordinates are
// gathered on every core (float and double arrays without a virtual call a point); id lists (a
// copy of firstUse and a sequence, 128 MB at 16M triangles) are made only for point data, which a
// scan's file seldom has.
void WritePoints(vtkPolyData* input, const std::vector<vtkIdType>& firstUse, vtkPolyData* output)
{
  const vtkIdType count = static_cast<vtkIdType>(firstUse.size());
  vtkDataArray* from = input->GetPoints()->GetData();
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(count);
  vtkDataArray* to = points->GetData();
  if (!GatherCoordinates<vtkFloatArray>(from, to, firstUse) &&
    !GatherCoordinates<vtkDoubleArray>(from, to, firstUse))
  {
    vtkSMPTools::For(0, count,
      [&](vtkIdType begin, vtkIdType end)
      {
        double p[3];
        for (vtkIdType i = begin; i < end; ++i)
        {
          from->GetTuple(firstUse[static_cast<size_t>(i)], p);
          to->SetTuple(i, p);
        }
      });
  }
  output->SetPoints(points);
  if (input->GetPointData()->GetNumberOfArrays() > 0)
  {
    vtkPointData* pointData = output->GetPointData();
    pointData->CopyAllocate(input->GetPointData(), count);
    pointData->CopyData(input->GetPointData(), ToIdList(firstUse), Sequence(firstUse.size()));
  }
}

// The kept cells, and their cell data in vtkPolyData's order: vertices, lines, polygons, strips.
void WriteCells(vtkPolyData* input, std::array<KeptCells, 4>& kept, vtkPolyData* output)
{
  output->SetVerts(kept[Verts].Build());
  output->SetLines(kept[Lines].Build());
  output->SetPolys(kept[Polys].Build());
  output->SetStrips(kept[Strips].Build());
  if (input->GetCellData()->GetNumberOfArrays() == 0)
  {
    return;
  }
  std::vector<vtkIdType> sources;
  for (const KeptCells& cells : kept)
  {
    sources.insert(sources.end(), cells.Sources.begin(), cells.Sources.end());
  }
  vtkCellData* cellData = output->GetCellData();
  cellData->CopyAllOn(vtkDataSetAttributes::COPYTUPLE);
  cellData->CopyAllocate(input->GetCellData(), static_cast<vtkIdType>(sources.size()));
  cellData->CopyData(input->GetCellData(), ToIdList(sources), Sequence(sources.size()));
}
}

std::string vtkNPRCoincidentPoints::Merge(vtkPolyData* input, vtkPolyData* output)
{
  output->Initialize();
  if (!input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    return "";
  }
  auto numbers = std::make_unique<Renumbering>(FindRepresentatives(input->GetPoints()));
  std::array<KeptCells, 4> kept;
  for (KeptCells& cells : kept)
  {
    cells.KeepSources = input->GetCellData()->GetNumberOfArrays() > 0;
  }
  vtkIdType cellId = 0;
  const std::pair<vtkCellArray*, CellKind> kinds[] = { { input->GetVerts(), Verts },
    { input->GetLines(), Lines }, { input->GetPolys(), Polys }, { input->GetStrips(), Strips } };
  for (const auto& cells : kinds)
  {
    if (cells.first && !MergeCells(cells.first, cells.second, *numbers, cellId, kept))
    {
      return "cell " + std::to_string(cellId) + " names a point past the " +
        std::to_string(input->GetNumberOfPoints()) + " points";
    }
  }
  const std::vector<vtkIdType> firstUse = std::move(numbers->FirstUse);
  numbers.reset(); // its maps, 128 MB at 16M triangles, go before the points are written
  WritePoints(input, firstUse, output);
  WriteCells(input, kept, output);
  return "";
}
