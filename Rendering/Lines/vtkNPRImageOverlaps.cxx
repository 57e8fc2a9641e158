// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNPRImageOverlaps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace
{
// A cell with more triangles than this marks them all (the pairs would cost its square).
constexpr size_t CrowdedCell = 256;
// Grid entries beyond this many per triangle: everything marked (huge triangles over every cell).
constexpr size_t EntriesPerTriangle = 64;
// Within this (pixels) of separation two triangles only touch.
constexpr double Touching = 1e-7;

struct Box
{
  double Low[2], High[2];
};

Box BoxOf(const vtkNPRImageTriangle& t)
{
  return { { std::min({ t.X[0], t.X[1], t.X[2] }), std::min({ t.Y[0], t.Y[1], t.Y[2] }) },
    { std::max({ t.X[0], t.X[1], t.X[2] }), std::max({ t.Y[0], t.Y[1], t.Y[2] }) } };
}

// Whether the two triangles' interiors overlap: no edge normal of either separates them.
bool InteriorsOverlap(const vtkNPRImageTriangle& a, const vtkNPRImageTriangle& b)
{
  for (const vtkNPRImageTriangle* t : { &a, &b })
  {
    for (int k = 0; k < 3; ++k)
    {
      const double nx = t->Y[k] - t->Y[(k + 1) % 3], ny = t->X[(k + 1) % 3] - t->X[k];
      const double length = std::hypot(nx, ny);
      if (!(length > 0.0))
      {
        continue;
      }
      double range[2][2];
      int r = 0;
      for (const vtkNPRImageTriangle* u : { &a, &b })
      {
        range[r][0] = range[r][1] = (nx * u->X[0] + ny * u->Y[0]) / length;
        for (int c = 1; c < 3; ++c)
        {
          const double d = (nx * u->X[c] + ny * u->Y[c]) / length;
          range[r][0] = std::min(range[r][0], d);
          range[r][1] = std::max(range[r][1], d);
        }
        ++r;
      }
      if (range[0][1] <= range[1][0] + Touching || range[1][1] <= range[0][0] + Touching)
      {
        return false;
      }
    }
  }
  return true;
}

// The grid: cells of the triangles' box, about one triangle a cell.
struct Grid
{
  double Origin[2], CellSize[2];
  int Size;
  void CellRange(const Box& box, int range[4]) const
  {
    for (int axis = 0; axis < 2; ++axis)
    {
      range[axis] = this->Cell(box.Low[axis], axis);
      range[2 + axis] = this->Cell(box.High[axis], axis);
    }
  }
  int Cell(double x, int axis) const
  {
    const double c = std::floor((x - this->Origin[axis]) / this->CellSize[axis]);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(this->Size - 1)));
  }
};

// The triangles' boxes and the box of them all; false when one is unprojected or not finite.
bool BoxTriangles(
  const std::vector<vtkNPRImageTriangle>& triangles, std::vector<Box>& boxes, Box& all)
{
  boxes.resize(triangles.size());
  all = { { 1e300, 1e300 }, { -1e300, -1e300 } };
  for (size_t i = 0; i < triangles.size(); ++i)
  {
    boxes[i] = BoxOf(triangles[i]);
    const bool finite = std::isfinite(boxes[i].Low[0]) && std::isfinite(boxes[i].Low[1]) &&
      std::isfinite(boxes[i].High[0]) && std::isfinite(boxes[i].High[1]);
    if (triangles[i].Unprojected || !finite)
    {
      return false;
    }
    for (int axis = 0; axis < 2; ++axis)
    {
      all.Low[axis] = std::min(all.Low[axis], boxes[i].Low[axis]);
      all.High[axis] = std::max(all.High[axis], boxes[i].High[axis]);
    }
  }
  return true;
}

// The grid's cells' triangles: cell c's are Members[First[c], First[c + 1]), counted then filled
// (one array, no vector a cell). False when they would exceed EntriesPerTriangle a triangle.
struct CellLists
{
  std::vector<std::uint32_t> First, Members;
  bool Fill(const Grid& grid, const std::vector<Box>& boxes)
  {
    const size_t cells = static_cast<size_t>(grid.Size) * grid.Size;
    this->First.assign(cells + 1, 0);
    size_t entries = 0;
    for (const Box& box : boxes)
    {
      int r[4];
      grid.CellRange(box, r);
      for (int y = r[1]; y <= r[3]; ++y)
      {
        for (int x = r[0]; x <= r[2]; ++x)
        {
          ++this->First[static_cast<size_t>(y) * grid.Size + x + 1];
        }
      }
      entries += static_cast<size_t>(r[2] - r[0] + 1) * (r[3] - r[1] + 1);
      if (entries > EntriesPerTriangle * boxes.size())
      {
        return false;
      }
    }
    for (size_t c = 0; c < cells; ++c)
    {
      this->First[c + 1] += this->First[c];
    }
    this->Members.resize(entries);
    std::vector<std::uint32_t> next(this->First.begin(), this->First.end() - 1);
    for (size_t i = 0; i < boxes.size(); ++i)
    {
      int r[4];
      grid.CellRange(boxes[i], r);
      for (int y = r[1]; y <= r[3]; ++y)
      {
        for (int x = r[0]; x <= r[2]; ++x)
        {
          this->Members[next[static_cast<size_t>(y) * grid.Size + x]++] =
            static_cast<std::uint32_t>(i);
        }
      }
    }
    return true;
  }
};

// Marks the pairs of one cell that overlap; each pair once, in the cell of the low corner of
// their boxes' common part. A crowded cell marks all its triangles.
void MarkCell(size_t c, const CellLists& lists, const Grid& grid,
  const std::vector<vtkNPRImageTriangle>& triangles, const std::vector<Box>& boxes,
  std::vector<char>& marks)
{
  const std::uint32_t* begin = lists.Members.data() + lists.First[c];
  const size_t count = lists.First[c + 1] - lists.First[c];
  if (count > CrowdedCell)
  {
    std::for_each(begin, begin + count, [&](std::uint32_t i) { marks[i] = 1; });
    return;
  }
  for (size_t a = 0; a < count; ++a)
  {
    for (size_t b = a + 1; b < count; ++b)
    {
      const std::uint32_t i = begin[a], j = begin[b];
      const Box &p = boxes[i], &q = boxes[j];
      if ((marks[i] && marks[j]) || p.High[0] <= q.Low[0] || q.High[0] <= p.Low[0] ||
        p.High[1] <= q.Low[1] || q.High[1] <= p.Low[1])
      {
        continue;
      }
      const int cx = grid.Cell(std::max(p.Low[0], q.Low[0]), 0);
      const int cy = grid.Cell(std::max(p.Low[1], q.Low[1]), 1);
      if (static_cast<size_t>(cy) * grid.Size + cx == c &&
        InteriorsOverlap(triangles[i], triangles[j]))
      {
        marks[i] = marks[j] = 1;
      }
    }
  }
}
}

std::vector<char> vtkNPRMarkImageOverlaps(const std::vector<vtkNPRImageTriangle>& triangles)
{
  const size_t n = triangles.size();
  std::vector<Box> boxes;
  Box all;
  if (!BoxTriangles(triangles, boxes, all))
  {
    return std::vector<char>(n, 1); // an image unbounded: every triangle may be under it
  }
  std::vector<char> marks(n, 0);
  if (n < 2)
  {
    return marks;
  }
  Grid grid; // about one triangle a cell
  grid.Size = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(n)), 1.0, 2048.0));
  for (int axis = 0; axis < 2; ++axis)
  {
    grid.Origin[axis] = all.Low[axis];
    grid.CellSize[axis] = std::max((all.High[axis] - all.Low[axis]) / grid.Size, 1e-12);
  }
  CellLists lists;
  if (!lists.Fill(grid, boxes))
  {
    return std::vector<char>(n, 1); // huge triangles over every cell
  }
  for (size_t c = 0; c + 1 < lists.First.size(); ++c)
  {
    MarkCell(c, lists, grid, triangles, boxes, marks);
  }
  return marks;
}
