// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// The bytes of a stream from its position on, read a megabyte at a time: a binary body walked
// value by value through the stream itself took seconds on a 5M-triangle PLY. Private to the
// module (the PLY check and the binary PLY reader).
#ifndef vtkNPRChunkedInput_h
#define vtkNPRChunkedInput_h

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <istream>
#include <vector>

class vtkNPRChunkedInput
{
public:
  explicit vtkNPRChunkedInput(std::istream& in)
    : In(in)
  {
  }

  // The next size bytes (at most a megabyte), valid until the next call; null when the stream
  // ends first.
  const unsigned char* Take(size_t size)
  {
    if (this->Position + size > this->End && !this->Refill(size))
    {
      return nullptr;
    }
    this->Position += size;
    return this->Buffer.data() + this->Position - size;
  }

  // Skips up to size bytes; returns how many there were.
  uint64_t Skip(uint64_t size)
  {
    const uint64_t buffered = std::min<uint64_t>(size, this->End - this->Position);
    this->Position += static_cast<size_t>(buffered);
    uint64_t skipped = buffered;
    while (skipped < size && this->In)
    {
      const uint64_t step = std::min<uint64_t>(size - skipped, uint64_t(1) << 30);
      this->In.ignore(static_cast<std::streamsize>(step));
      skipped += static_cast<uint64_t>(this->In.gcount());
    }
    return skipped;
  }

private:
  bool Refill(size_t needed)
  {
    const size_t left = this->End - this->Position;
    std::memmove(this->Buffer.data(), this->Buffer.data() + this->Position, left);
    this->In.read(reinterpret_cast<char*>(this->Buffer.data() + left),
      static_cast<std::streamsize>(this->Buffer.size() - left));
    this->Position = 0;
    this->End = left + static_cast<size_t>(this->In.gcount());
    return this->End >= needed;
  }

  std::istream& In;
  std::vector<unsigned char> Buffer = std::vector<unsigned char>(1 << 20);
  size_t Position = 0;
  size_t End = 0;
};

#endif
