// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// How the mesh tables put things in spatial order: the Morton code of a point in a box, and the
// one sort they need, of keys whose high 32 bits are a code (a Morton code, a hash) and whose low
// 32 bits are an index, written in index order. A stable least-significant-digit radix sort on
// the code alone sorts them by the whole key in linear time (a pass of 16 bits for each 16 bits
// of code, with a second buffer of the keys' size, counting and moving on all cores), where a
// comparison sort took 22 passes at 5 million keys. Private to NPR::Lines.
#ifndef vtkNPRSpatialOrder_h
#define vtkNPRSpatialOrder_h

#include "vtkSMPTools.h" // for the passes

#include <algorithm> // for std::min
#include <cstdint>   // for std::uint64_t
#include <utility>   // for std::exchange
#include <vector>    // for the buckets

// The Morton code of point x in the box [low, high], `bits` bits an axis (at most 10): x's cell
// on each axis, the axes' bits interleaved (x lowest).
inline std::uint32_t vtkNPRMortonCode(
  const double x[3], const double low[3], const double high[3], int bits)
{
  std::uint32_t code = 0;
  const double cells = static_cast<double>(1u << bits);
  for (int k = 0; k < 3; ++k)
  {
    const double extent = high[k] - low[k];
    const double t = extent > 0.0 ? (x[k] - low[k]) / extent : 0.0;
    // Spread the cell's bits three apart: bit i goes to bit 3i.
    std::uint32_t cell =
      static_cast<std::uint32_t>(std::min(cells - 1.0, std::max(0.0, t * cells)));
    cell = (cell | (cell << 16)) & 0x030000ffu;
    cell = (cell | (cell << 8)) & 0x0300f00fu;
    cell = (cell | (cell << 4)) & 0x030c30c3u;
    cell = (cell | (cell << 2)) & 0x09249249u;
    code |= cell << k;
  }
  return code;
}

// Sorts `keys` (each code << 32 | index, indices increasing) by their codes, which are below
// 2^codeBits; keys of code 0xffffffff (none) come last.
inline void vtkNPRRadixSort(std::vector<std::uint64_t>& keys, int codeBits)
{
  const size_t count = keys.size();
  constexpr int DigitBits = 16;
  constexpr size_t Buckets = size_t(1) << DigitBits;
  // Contiguous chunks, with a count per bucket each, so that each chunk moves its keys in order.
  const size_t chunks = std::min<size_t>(16, std::max<size_t>(1, count / Buckets));
  const size_t chunkSize = (count + chunks - 1) / chunks;
  std::vector<std::uint64_t> other(count);
  std::vector<size_t> places(chunks * Buckets);
  // Digits up to bit codeBits (0 in a code, 1 in the keys of none): the ones above change
  // nothing.
  for (int shift = 32; shift < 33 + codeBits; shift += DigitBits)
  {
    std::fill(places.begin(), places.end(), 0);
    auto forEachChunk = [&](auto&& visit)
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(chunks),
        [&](vtkIdType first, vtkIdType last)
        {
          for (vtkIdType c = first; c < last; ++c)
          {
            size_t* chunkPlaces = places.data() + c * Buckets;
            const size_t end = std::min(count, static_cast<size_t>(c + 1) * chunkSize);
            for (size_t i = static_cast<size_t>(c) * chunkSize; i < end; ++i)
            {
              visit(chunkPlaces[(keys[i] >> shift) & (Buckets - 1)], keys[i]);
            }
          }
        });
    };
    forEachChunk([](size_t& counted, std::uint64_t) { ++counted; });
    // Where each chunk's keys of each bucket go: buckets in order, chunks in order within one.
    size_t place = 0;
    for (size_t b = 0; b < Buckets; ++b)
    {
      for (size_t c = 0; c < chunks; ++c)
      {
        place += std::exchange(places[c * Buckets + b], place);
      }
    }
    forEachChunk([&other](size_t& next, std::uint64_t key) { other[next++] = key; });
    keys.swap(other);
  }
}

#endif
// VTK-HeaderTest-Exclude: vtkNPRSpatialOrder.h
