// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-fuzz-readers: a mutation fuzzer of vtkNPRModelReader over the committed seed files of every
// format, and the replay of seeds and crash reproducers as a regression test.
//
//   npr-fuzz-readers --seeds DIR --work DIR [--seconds S | --mutants N] [--seed K]
//                    [--crashes DIR] [--formats stl,obj,...] [--explore]
//   npr-fuzz-readers --replay DIR... [--valid DIR]
//
// Each input is read in a child process (fork), as npr-render reads a model (vtkNPRModelReader,
// then vtkNPRShadingNormals), with a 10 s alarm: a signal is a crash, the alarm a hang, any other
// non-zero exit a sanitizer report or a broken promise of the reader (an error with a non-empty
// output, or a success with no cell, a non-finite point, an index out of range); a read with
// nothing that can cover a pixel and no warning is a silent blank. Mutants are deterministic for
// a --seed: bit flips, interesting bytes and integers, insertions, deletions, truncations,
// splices with other seeds and, in text, numbers replaced by interesting ones; and the
// structured kinds: lines and tokens over 4096 bytes, deep nesting, numbers collapsed to one
// value or made huge or tiny, types retyped (a PLY's byte order too), counts and indices
// changed. A glTF mutant gets its .bin alongside, mutated one time in four. Every failing
// mutant is copied to --crashes. Exit status 1 when any was found, unless --explore.
#include "vtkCellArray.h"
#include "vtkLogger.h"
#include "vtkNPRModelReader.h"
#include "vtkNPRShadingNormals.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringOutputWindow.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace
{
const int HangSeconds = 10;

std::string ReadFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A mutant that cannot be written would be "rejected" as a missing file: stop instead.
void WriteFile(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) || !out.flush())
  {
    std::cerr << "npr-fuzz-readers: cannot write " << path << "\n";
    std::exit(2);
  }
}

// mkdir -p.
void MakeDirectories(const std::string& path)
{
  for (size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1))
  {
    mkdir(path.substr(0, slash).c_str(), 0755);
    if (slash == std::string::npos)
    {
      break;
    }
  }
}

std::vector<std::string> ListFiles(const std::string& dir)
{
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str()))
  {
    while (dirent* entry = readdir(d))
    {
      const std::string name = entry->d_name;
      struct stat status;
      if (name[0] != '.' && stat((dir + "/" + name).c_str(), &status) == 0 &&
        S_ISREG(status.st_mode))
      {
        names.push_back(name);
      }
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string Extension(const std::string& name)
{
  const size_t dot = name.find_last_of('.');
  std::string extension = dot == std::string::npos ? "" : name.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The output as the GPU gets it: each point in float, or none where a coordinate is not finite
// or beyond float's range.
std::vector<std::array<float, 3>> FloatPoints(vtkPolyData* output, std::vector<bool>& usable)
{
  const vtkIdType count = output->GetNumberOfPoints();
  std::vector<std::array<float, 3>> points(static_cast<size_t>(count));
  usable.assign(static_cast<size_t>(count), false);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    bool ok = true;
    for (int axis = 0; axis < 3; ++axis)
    {
      ok = ok && std::isfinite(p[axis]) && std::abs(p[axis]) <= FLT_MAX;
      points[static_cast<size_t>(i)][axis] = ok ? static_cast<float>(p[axis]) : 0.0f;
    }
    usable[static_cast<size_t>(i)] = ok;
  }
  return points;
}

// Whether anything of a read output could cover a pixel, judged apart from the reader's own
// checks, in float as the GPU draws: a vertex, a line between two distinct points or a polygon
// or strip triangle with an area, on usable points, whose bounds' diagonal npr-render's camera
// frames (1e-20 to 1e37, measured with cubes: 1.7e-22 and 8.7e37 drew nothing).
bool DrawsSomething(vtkPolyData* output)
{
  std::vector<bool> usable;
  const std::vector<std::array<float, 3>> points = FloatPoints(output, usable);
  double low[3] = { DBL_MAX, DBL_MAX, DBL_MAX }, high[3] = { -DBL_MAX, -DBL_MAX, -DBL_MAX };
  bool drawn = false;
  auto area = [&](const vtkIdType* t)
  {
    const std::array<float, 3>&a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    return u[1] * v[2] - u[2] * v[1] != 0 || u[2] * v[0] - u[0] * v[2] != 0 ||
      u[0] * v[1] - u[1] * v[0] != 0;
  };
  int kind = 0;
  for (vtkCellArray* cells :
    { output->GetVerts(), output->GetLines(), output->GetPolys(), output->GetStrips() })
  {
    vtkIdType size;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(size, ids);)
    {
      if (!std::all_of(ids, ids + size, [&](vtkIdType id) { return usable[id]; }))
      {
        continue;
      }
      for (vtkIdType k = 0; k < size; ++k)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          low[axis] = std::min<double>(low[axis], points[ids[k]][axis]);
          high[axis] = std::max<double>(high[axis], points[ids[k]][axis]);
        }
      }
      for (vtkIdType k = 1; kind == 1 && k < size; ++k)
      {
        drawn = drawn || points[ids[k - 1]] != points[ids[k]];
      }
      drawn = drawn || (kind == 0 && size > 0);
      // A polygon fanned from its first corner, a strip's triangles in order.
      for (vtkIdType k = 2; kind >= 2 && !drawn && k < size; ++k)
      {
        const vtkIdType t[3] = { ids[kind == 2 ? 0 : k - 2], ids[k - 1], ids[k] };
        drawn = area(t);
      }
    }
    ++kind;
  }
  const double diagonal = std::sqrt((high[0] - low[0]) * (high[0] - low[0]) +
    (high[1] - low[1]) * (high[1] - low[1]) + (high[2] - low[2]) * (high[2] - low[2]));
  return drawn && diagonal >= 1e-20 && diagonal <= 1e37;
}

// What the child found: 0 read, 10 rejected with an error, 3 a broken promise of the reader,
// 4 a silent blank (read without an error or a warning, but nothing of it can be drawn).
int ReadInChild(const std::string& path, std::string& problem)
{
  vtkNew<vtkNPRModelReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* output = reader->GetOutput();
  if (*reader->GetErrorMessage())
  {
    if (output->GetNumberOfCells() != 0 ||
      std::string(reader->GetErrorMessage()).find('\n') != std::string::npos)
    {
      problem = "an error with a non-empty output or on several lines";
      return 3;
    }
    return 10;
  }
  const vtkIdType points = output->GetNumberOfPoints();
  if (output->GetNumberOfCells() == 0 || points == 0)
  {
    problem = "success with no cell";
    return 3;
  }
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    if (!std::isfinite(p[0] + p[1] + p[2]))
    {
      problem = "success with a non-finite point";
      return 3;
    }
  }
  for (vtkCellArray* cells :
    { output->GetVerts(), output->GetLines(), output->GetPolys(), output->GetStrips() })
  {
    vtkIdType size;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(size, ids);)
    {
      for (vtkIdType k = 0; k < size; ++k)
      {
        if (ids[k] < 0 || ids[k] >= points)
        {
          problem = "success with a point index out of range";
          return 3;
        }
      }
    }
  }
  if (!DrawsSomething(output) && !*reader->GetWarningMessage())
  {
    problem = "silent blank: read without an error or a warning, but nothing can be drawn";
    return 4;
  }
  vtkNew<vtkNPRShadingNormals> normals; // what npr-render does next
  normals->SetInputData(output);
  normals->Update();
  return 0;
}

enum class Outcome
{
  Rejected,
  Read,
  Crash,
  Hang,
  Report,
  SilentBlank
};

// Reads the file in a child process; problem says what went wrong.
Outcome Run(const std::string& path, std::string& problem)
{
  std::cout.flush();
  const pid_t child = fork();
  if (child == 0)
  {
    alarm(HangSeconds);
    std::string childProblem;
    const int status = ReadInChild(path, childProblem);
    if (status == 3 || status == 4)
    {
      std::cerr << "npr-fuzz-readers: " << path << ": " << childProblem << "\n";
    }
    _exit(status);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    problem = signal == SIGALRM ? "hang (> 10 s)" : std::string("signal ") + strsignal(signal);
    return signal == SIGALRM ? Outcome::Hang : Outcome::Crash;
  }
  if (WEXITSTATUS(status) == 10)
  {
    return Outcome::Rejected;
  }
  if (WEXITSTATUS(status) == 4)
  {
    problem = "a silent blank (nothing drawable, no error or warning)";
    return Outcome::SilentBlank;
  }
  if (WEXITSTATUS(status) != 0)
  {
    problem = "exit status " + std::to_string(WEXITSTATUS(status)) +
      (WEXITSTATUS(status) == 3 ? " (the reader's promise broken)" : " (a sanitizer report?)");
    return Outcome::Report;
  }
  return Outcome::Read;
}

class Mutator
{
public:
  Mutator(uint64_t seed, const std::vector<std::string>& pool)
    : Random(seed)
    , Pool(pool)
  {
  }

  size_t Below(size_t n) { return n ? std::uniform_int_distribution<size_t>(0, n - 1)(Random) : 0; }

  std::string Mutate(std::string data, bool text)
  {
    const int rounds = 1 + static_cast<int>(this->Below(4));
    for (int r = 0; r < rounds; ++r)
    {
      // One round in three a structured kind (issue 36), else a byte-level or text one.
      this->Below(3) ? this->MutateOnce(data, text) : this->MutateStructure(data, text);
    }
    return data;
  }

private:
  void MutateOnce(std::string& data, bool text)
  {
    static const uint32_t integers[] = { 0, 1, 2, 3, 0x7f, 0x80, 0xff, 0xffff, 0x7fffffff,
      0x80000000, 0xffffffff, 0x7fc00000 /* float NaN */, 0x7f800000 /* float Inf */ };
    const size_t size = data.size();
    switch (this->Below(text ? 10 : 8))
    {
      case 0: // flip a bit
        if (size)
        {
          data[this->Below(size)] ^= static_cast<char>(1 << this->Below(8));
        }
        break;
      case 1: // an interesting byte
        if (size)
        {
          static const char bytes[] = { 0, '\xff', '\x7f', '\x80', ' ', '\n', '-', '/', '0', '9',
            '.', ',', '"', '{', '[' };
          data[this->Below(size)] = bytes[this->Below(sizeof(bytes))];
        }
        break;
      case 2: // an interesting 32-bit integer, little-endian
        if (size >= 4)
        {
          const uint32_t value = integers[this->Below(sizeof(integers) / sizeof(integers[0]))];
          std::memcpy(&data[this->Below(size - 3)], &value, 4);
        }
        break;
      case 3: // insert random bytes or a copy of a chunk
        this->Insert(data);
        break;
      case 4: // delete a chunk
        if (size)
        {
          const size_t from = this->Below(size);
          data.erase(from, 1 + this->Below(std::min<size_t>(size - from, 64)));
        }
        break;
      case 5: // truncate
        data.resize(this->Below(size + 1));
        break;
      case 6: // splice in a piece of another seed
        this->Splice(data);
        break;
      case 7: // overwrite a chunk with a chunk of itself
        if (size > 2)
        {
          const size_t from = this->Below(size), to = this->Below(size);
          const size_t n = 1 + this->Below(std::min(size - std::max(from, to), size_t(32)));
          data.replace(to, n, data.substr(from, n));
        }
        break;
      default: // text: a number replaced by an interesting one, or a line repeated
        this->MutateText(data);
        break;
    }
  }

  void Insert(std::string& data)
  {
    const size_t size = data.size();
    const size_t at = this->Below(size + 1);
    if (size && this->Below(2))
    {
      const size_t from = this->Below(size);
      data.insert(at, data.substr(from, 1 + this->Below(std::min<size_t>(size - from, 64))));
    }
    else
    {
      std::string bytes(1 + this->Below(8), '\0');
      for (char& c : bytes)
      {
        c = static_cast<char>(this->Below(256));
      }
      data.insert(at, bytes);
    }
  }

  void Splice(std::string& data)
  {
    const size_t size = data.size();
    const std::string& other = this->Pool[this->Below(this->Pool.size())];
    if (!other.empty())
    {
      const size_t from = this->Below(other.size());
      const size_t at = this->Below(size + 1);
      data.replace(at, this->Below(std::min<size_t>(size - at, 64) + 1),
        other.substr(from, 1 + this->Below(std::min<size_t>(other.size() - from, 128))));
    }
  }

  // A number replaced by an interesting one, or a line repeated or removed.
  void MutateText(std::string& data)
  {
    static const char* numbers[] = { "0", "-1", "1", "2", "3", "7", "8", "9", "255", "256", "65535",
      "65536", "2147483647", "2147483648", "-2147483648", "4294967295", "4294967296",
      "9223372036854775807", "99999999999999999999", "1e308", "-1e308", "1e-320", "nan", "inf",
      "-inf", "-0", "0.5", "1e9", "" };
    const size_t size = data.size();
    if (size && this->Below(4))
    {
      size_t at = this->Below(size);
      const size_t digit = data.find_first_of("0123456789", at);
      if (digit == std::string::npos)
      {
        return;
      }
      size_t start = digit;
      while (start > 0 && std::strchr("0123456789.-+eE", data[start - 1]))
      {
        --start;
      }
      size_t end = digit;
      while (end < size && std::strchr("0123456789.-+eE", data[end]))
      {
        ++end;
      }
      data.replace(start, end - start, numbers[this->Below(sizeof(numbers) / sizeof(char*))]);
    }
    else if (size)
    {
      const size_t start = data.rfind('\n', this->Below(size));
      const size_t from = start == std::string::npos ? 0 : start + 1;
      const size_t end = data.find('\n', from);
      const std::string line = data.substr(from, end == std::string::npos ? end : end - from + 1);
      this->Below(2) ? data.insert(from, line) : data.erase(from, line.size());
    }
  }

  // The kinds that reach past the checks of single bytes: lines and tokens longer than VTK's
  // 4096-byte buffers, deep nesting, numbers replaced all alike (collapsed, huge, tiny),
  // retyped or swapped properties and a PLY's byte order, counts and indices changed.
  void MutateStructure(std::string& data, bool text)
  {
    switch (this->Below(6))
    {
      case 0:
        this->LongLine(data);
        break;
      case 1:
        this->DeepNesting(data);
        break;
      case 2:
        text ? this->CollapseNumbers(data) : this->RepeatWord(data);
        break;
      case 3:
        text ? this->ExtremeNumbers(data) : this->ExtremeWords(data);
        break;
      case 4:
        this->Retype(data);
        break;
      default:
        this->ChangeCount(data);
        break;
    }
  }

  // A line of 4097 to 20000 bytes inserted at a line start, headed by the first word of some
  // line (comment, element, mtllib, v, ...), or a token of that length inside a line.
  void LongLine(std::string& data)
  {
    const size_t length = 4097 + this->Below(16000);
    const size_t at = this->LineStart(data, this->Below(data.size() + 1));
    if (this->Below(2))
    {
      static const char fill[] = { 'a', '0', ' ', '9', '.', '/' };
      data.insert(this->Below(data.size() + 1), std::string(length, fill[this->Below(6)]));
      return;
    }
    const size_t word = this->LineStart(data, this->Below(data.size() + 1));
    const size_t wordEnd = std::min(data.find_first_of(" \n", word), data.size());
    data.insert(at, data.substr(word, wordEnd - word) + " " + std::string(length, 'x') + "\n");
  }

  // 65 to 20,000 nested XML elements or JSON arrays (the checks refuse more than 64 and 200),
  // unclosed one time in two.
  void DeepNesting(std::string& data)
  {
    const size_t depth = this->Below(2) ? 65 + this->Below(200) : 1000 + this->Below(19000);
    const bool xml = data.find('<') != std::string::npos;
    const size_t found = data.find(xml ? '>' : '[', this->Below(data.size() + 1));
    const size_t at = found == std::string::npos ? data.size() : found + 1;
    std::string nest, close;
    for (size_t i = 0; i < depth; ++i)
    {
      nest += xml ? "<DataArray>" : "[";
      close += xml ? "</DataArray>" : "]";
    }
    data.insert(at, nest + (this->Below(2) ? close : ""));
  }

  // Every number of a run of lines replaced by one value (every point at one spot, every face
  // degenerate), all of them or those with a fraction, or the three of vertex-like lines.
  void CollapseNumbers(std::string& data)
  {
    const size_t from = this->LineStart(data, this->Below(data.size() + 1));
    const size_t to = this->Below(4) ? data.size() : from + this->Below(data.size() - from + 1);
    const std::string value = this->Below(2) ? "0" : this->NumberAt(data, this->Below(data.size()));
    const size_t which = this->Below(3);
    ReplaceNumbers(data, from, to,
      [&](const std::string& number, int column)
      {
        const bool fraction = number.find_first_of(".eE") != std::string::npos;
        return which == 0 || (which == 1 && fraction) || (which == 2 && column < 3) ? value
                                                                                    : number;
      });
  }

  // Numbers of a run of lines made huge, past float's range, or tiny (denormal).
  void ExtremeNumbers(std::string& data)
  {
    static const char* extremes[] = { "1e38", "3.4e38", "-3.5e38", "1e39", "1e300", "-1e300",
      "1e-40", "1e-45", "1e-300", "123456789012345678901234567890" };
    const size_t from = this->LineStart(data, this->Below(data.size() + 1));
    const size_t to = from + this->Below(data.size() - from + 1);
    const bool same = this->Below(2);
    const char* fixed = extremes[this->Below(sizeof(extremes) / sizeof(char*))];
    ReplaceNumbers(data, from, to,
      [&](const std::string& number, int)
      {
        return number.find_first_of(".eE") == std::string::npos && this->Below(2)
          ? number
          : std::string(same ? fixed : extremes[this->Below(sizeof(extremes) / sizeof(char*))]);
      });
  }

  // Binary: a run of 4-byte words made one word (every coordinate equal).
  void RepeatWord(std::string& data)
  {
    if (data.size() < 8)
    {
      return;
    }
    const size_t from = this->Below(data.size() - 4) & ~size_t(3);
    const std::string word = data.substr(from, 4);
    const size_t to = std::min(data.size() - 4, from + 4 * this->Below(data.size() / 4));
    for (size_t at = from; at <= to; at += 4)
    {
      data.replace(at, 4, word);
    }
  }

  // Binary: a run of 4-byte words made float 1e38, Inf, denormal or a big-endian 1.0.
  void ExtremeWords(std::string& data)
  {
    static const uint32_t words[] = { 0x7e967699 /* 1e38 */, 0x7f7fffff /* FLT_MAX */,
      0x00000001 /* denormal */, 0x0000803f /* 1.0 big-endian */, 0x7f800000 /* Inf */ };
    if (data.size() < 8)
    {
      return;
    }
    const uint32_t value = words[this->Below(sizeof(words) / sizeof(words[0]))];
    const size_t from = this->Below(data.size() - 4) & ~size_t(3);
    const size_t to = std::min(data.size() - 4, from + 4 * this->Below(64));
    for (size_t at = from; at <= to; at += 4)
    {
      std::memcpy(&data[at], &value, 4);
    }
  }

  // A type word retyped within its family (PLY property types and formats, VTP and legacy VTK
  // types, glTF component types and `normalized`), or two PLY property lines swapped.
  void Retype(std::string& data)
  {
    static const std::vector<std::vector<std::string>> families = {
      { "char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8",
        "int32", "float32", "float64" },
      { "ascii", "binary_little_endian", "binary_big_endian" },
      { "Int8", "UInt8", "Int16", "Int32", "UInt32", "Int64", "Float32", "Float64", "String" },
      { "5120", "5121", "5122", "5123", "5125", "5126", "5130" }, { "false", "true" },
      { "SCALAR", "VEC2", "VEC3", "VEC4", "MAT4" }
    };
    if (this->Below(4) == 0 && this->SwapPropertyLines(data))
    {
      return;
    }
    const std::vector<std::string>& family = families[this->Below(families.size())];
    const size_t start = this->Below(data.size() + 1);
    for (size_t k = 0; k < family.size(); ++k)
    {
      const std::string& word = family[(start + k) % family.size()];
      size_t at = data.find(word, start);
      at = at == std::string::npos ? data.find(word) : at;
      if (at != std::string::npos)
      {
        data.replace(at, word.size(), family[this->Below(family.size())]);
        return;
      }
    }
  }

  bool SwapPropertyLines(std::string& data)
  {
    std::vector<size_t> lines;
    for (size_t at = data.find("\nproperty "); at != std::string::npos && lines.size() < 64;
         at = data.find("\nproperty ", at + 1))
    {
      lines.push_back(at + 1);
    }
    if (lines.size() < 2)
    {
      return false;
    }
    size_t a = lines[this->Below(lines.size())], b = lines[this->Below(lines.size())];
    if (a > b)
    {
      std::swap(a, b);
    }
    const size_t aEnd = data.find('\n', a) + 1, bEnd = data.find('\n', b) + 1;
    if (a == b || bEnd == 0)
    {
      return false;
    }
    const std::string first = data.substr(a, aEnd - a), second = data.substr(b, bEnd - b);
    data.replace(b, second.size(), first);
    data.replace(a, first.size(), second);
    return true;
  }

  // A count after its keyword (PLY `element`, legacy `POINTS`/`POLYGONS`, VTP `NumberOf*`,
  // glTF `count`/`byteOffset`/`byteLength`, a binary STL's triangle count) or an index changed:
  // one more or fewer, doubled, zero, huge, or the vertex count (an index one past the last).
  void ChangeCount(std::string& data)
  {
    static const char* keywords[] = { "element vertex ", "element face ", "POINTS ", "POLYGONS ",
      "CELLS ", "NumberOfPoints=\"", "NumberOfPolys=\"",
      "\"count\": ", "\"byteOffset\": ", "\"byteLength\": ", "\"indices\": ", "\"POSITION\": " };
    if (data.size() >= 134 && (data.size() - 84) % 50 == 0 && data.compare(0, 5, "solid") != 0)
    {
      const uint32_t count = static_cast<uint32_t>(this->Below(3)) + (data.size() - 84) / 50;
      std::memcpy(&data[80], &count, 4); // a binary STL's header
      return;
    }
    const std::string vertices =
      this->NumberAfter(data, this->Below(2) ? "element vertex " : "POINTS ");
    const char* keyword = keywords[this->Below(sizeof(keywords) / sizeof(char*))];
    size_t at = data.find(keyword);
    at = at == std::string::npos || this->Below(3) == 0 ? this->Below(data.size())
                                                        : at + std::strlen(keyword);
    const std::string number = this->NumberAt(data, at);
    const unsigned long long value = std::strtoull(number.c_str(), nullptr, 10); // wraps
    const std::string replacements[] = { std::to_string(value + 1), std::to_string(value - 1),
      std::to_string(value * 2), "0", "4294967297", vertices.empty() ? "8" : vertices };
    const size_t digit = data.find_first_of("0123456789", at);
    if (digit != std::string::npos)
    {
      const size_t end = data.find_first_not_of("0123456789", digit);
      data.replace(digit, (end == std::string::npos ? data.size() : end) - digit,
        replacements[this->Below(6)]);
    }
  }

  // The start of the line that holds the byte at `at`.
  static size_t LineStart(const std::string& data, size_t at)
  {
    const size_t newline = at == 0 ? std::string::npos : data.rfind('\n', at - 1);
    return newline == std::string::npos ? 0 : newline + 1;
  }

  // The number that starts at or after `at` ("1" when there is none).
  static std::string NumberAt(const std::string& data, size_t at)
  {
    const size_t digit = data.find_first_of("0123456789", at);
    if (digit == std::string::npos)
    {
      return "1";
    }
    const size_t end = data.find_first_not_of("0123456789.-+eE", digit);
    return data.substr(digit, (end == std::string::npos ? data.size() : end) - digit);
  }

  static std::string NumberAfter(const std::string& data, const std::string& keyword)
  {
    const size_t at = data.find(keyword);
    return at == std::string::npos ? "" : NumberAt(data, at + keyword.size());
  }

  // Each number token in [from, to) (not a word's digits, as in Float32) replaced by what
  // `replace` gives for it and its column on the line.
  template <typename Replace>
  static void ReplaceNumbers(std::string& data, size_t from, size_t to, Replace replace)
  {
    int column = 0;
    for (size_t at = from; at < std::min(to, data.size());)
    {
      const char c = data[at];
      const bool starts = (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.') &&
        (at == 0 || !std::isalnum(static_cast<unsigned char>(data[at - 1])));
      if (c == '\n')
      {
        column = 0;
      }
      if (!starts)
      {
        ++at;
        continue;
      }
      size_t end = data.find_first_not_of("0123456789.-+eE", at);
      end = end == std::string::npos ? data.size() : end;
      const std::string number = data.substr(at, end - at);
      const std::string replacement = replace(number, column++);
      data.replace(at, number.size(), replacement);
      at += std::max<size_t>(replacement.size(), 1);
      to += replacement.size() - number.size();
    }
  }

  std::mt19937_64 Random;
  const std::vector<std::string>& Pool;
};

struct Seed
{
  std::string Name;
  std::string Data;
  std::string Companion; // a glTF's .bin, by the name its JSON gives
  std::string CompanionData;
};

struct Counts
{
  long long Mutants = 0, Read = 0, Rejected = 0, Crashes = 0, Hangs = 0, Reports = 0,
            SilentBlanks = 0;
};

int Usage()
{
  std::cerr << "usage: npr-fuzz-readers --seeds DIR --work DIR [--seconds S | --mutants N] "
               "[--seed K] [--crashes DIR] [--formats LIST] [--explore]\n"
               "       npr-fuzz-readers --replay DIR... [--valid DIR]\n";
  return 2;
}

struct FuzzOptions
{
  std::string Seeds, Work, Crashes, Valid, Formats = "stl,obj,ply,vtp,vtk,gltf,glb,off";
  std::vector<std::string> Replay;
  double Seconds = 0;
  long long MutantsPerFormat = 0;
  uint64_t Seed = 1;
  bool Explore = false; // a fresh seed's campaign: print the findings, exit 0
};

// The option that takes the next argument as its value; false if arg is none of them.
bool ParseValue(const std::string& arg, const char* value, FuzzOptions& options)
{
  if (arg == "--seeds")
  {
    options.Seeds = value;
  }
  else if (arg == "--work")
  {
    options.Work = value;
  }
  else if (arg == "--crashes")
  {
    options.Crashes = value;
  }
  else if (arg == "--seconds")
  {
    options.Seconds = std::atof(value);
  }
  else if (arg == "--mutants")
  {
    options.MutantsPerFormat = std::atoll(value);
  }
  else if (arg == "--seed")
  {
    options.Seed = std::strtoull(value, nullptr, 10);
  }
  else if (arg == "--formats")
  {
    options.Formats = value;
  }
  else if (arg == "--valid")
  {
    options.Valid = value;
  }
  else
  {
    return false;
  }
  return true;
}

// False on an unknown argument or a missing value.
bool ParseFuzzOptions(int argc, char* argv[], FuzzOptions& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--explore")
    {
      options.Explore = true;
    }
    else if (arg == "--replay")
    {
      while (i + 1 < argc && argv[i + 1][0] != '-')
      {
        options.Replay.push_back(argv[++i]);
      }
    }
    else if (i + 1 >= argc || !ParseValue(arg, argv[i + 1], options))
    {
      return false;
    }
    else
    {
      ++i;
    }
  }
  return true;
}

// Regression: every seed in --valid reads without error, every reproducer neither crashes nor
// hangs. Returns the exit status.
int Replay(const FuzzOptions& options)
{
  std::vector<std::string> dirs = options.Replay;
  if (!options.Valid.empty())
  {
    dirs.push_back(options.Valid);
  }
  int failures = 0, files = 0;
  for (const std::string& dir : dirs)
  {
    for (const std::string& name : ListFiles(dir))
    {
      if (Extension(name) == "bin" || Extension(name) == "md")
      {
        continue;
      }
      ++files;
      const std::string path = dir + "/" + name;
      std::string problem;
      const Outcome outcome = Run(path, problem);
      const bool seed = dir == options.Valid;
      const bool ok = outcome == Outcome::Read || (outcome == Outcome::Rejected && !seed);
      if (outcome == Outcome::Rejected && seed)
      {
        problem = "a seed is rejected";
      }
      std::cout << (ok ? "ok: " : "FAILED: ") << path << (ok ? "" : ": " + problem) << "\n";
      failures += !ok;
    }
  }
  std::cout << files - failures << " passed, " << failures << " failed\n";
  return failures || !files ? 1 : 0;
}

// The seeds by format (extension); every seed's bytes also go to pool, for the splices.
std::map<std::string, std::vector<Seed>> LoadSeeds(
  const std::string& dir, std::vector<std::string>& pool)
{
  std::map<std::string, std::vector<Seed>> byFormat;
  for (const std::string& name : ListFiles(dir))
  {
    const std::string extension = Extension(name);
    if (extension == "bin" || extension == "md")
    {
      continue;
    }
    Seed s{ name, ReadFile(dir + "/" + name), "", "" };
    if (extension == "gltf")
    {
      const size_t uri = s.Data.find("\"uri\": \"");
      const size_t end = uri == std::string::npos ? uri : s.Data.find('"', uri + 8);
      if (uri != std::string::npos && s.Data.compare(uri + 8, 5, "data:") != 0)
      {
        s.Companion = s.Data.substr(uri + 8, end - uri - 8);
        s.CompanionData = ReadFile(dir + "/" + s.Companion);
      }
    }
    pool.push_back(s.Data);
    byFormat[extension].push_back(s);
  }
  return byFormat;
}

std::vector<std::string> SplitFormats(const std::string& list)
{
  std::vector<std::string> formats;
  for (size_t start = 0; start <= list.size();)
  {
    const size_t comma = std::min(list.find(',', start), list.size());
    formats.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return formats;
}

// Every seed, unmutated, must read where the mutants are written: else nothing is fuzzed.
bool SeedsRead(const std::vector<Seed>& seeds, const std::string& dir, const std::string& format)
{
  for (const Seed& s : seeds)
  {
    WriteFile(dir + "/seed." + format, s.Data);
    if (!s.Companion.empty())
    {
      WriteFile(dir + "/" + s.Companion, s.CompanionData);
    }
    std::string problem;
    if (Run(dir + "/seed." + format, problem) != Outcome::Read)
    {
      std::cerr << "npr-fuzz-readers: the seed " << s.Name << " does not read from " << dir
                << (problem.empty() ? "" : ": " + problem) << "\n";
      return false;
    }
  }
  return true;
}

void Count(Outcome outcome, Counts& counts)
{
  ++counts.Mutants;
  counts.Read += outcome == Outcome::Read;
  counts.Rejected += outcome == Outcome::Rejected;
  counts.Crashes += outcome == Outcome::Crash;
  counts.Hangs += outcome == Outcome::Hang;
  counts.Reports += outcome == Outcome::Report;
  counts.SilentBlanks += outcome == Outcome::SilentBlank;
}

// A mutant that crashed, hung, reported or drew a silent blank: said, and kept in --crashes.
void KeepFinding(const FuzzOptions& options, const std::string& format, const std::string& dir,
  const Seed& s, const std::string& problem, long long mutant)
{
  const std::string name =
    format + "-" + std::to_string(options.Seed) + "-" + std::to_string(mutant) + "." + format;
  const std::string& crashes = options.Crashes;
  std::cout << "npr-fuzz-readers: " << format << ": " << problem << " on a mutant of " << s.Name
            << (crashes.empty() ? "" : ", saved as " + crashes + "/" + name) << std::endl;
  if (!crashes.empty())
  {
    WriteFile(crashes + "/" + name, ReadFile(dir + "/mutant." + format));
    if (!s.Companion.empty())
    {
      WriteFile(crashes + "/" + name + "." + s.Companion, ReadFile(dir + "/" + s.Companion));
    }
  }
}

// One format's campaign: --mutants mutants, or its share of --seconds.
Counts FuzzFormat(const FuzzOptions& options, const std::string& format,
  const std::vector<Seed>& seeds, Mutator& mutator, const std::string& dir, double seconds)
{
  const bool text = format != "glb";
  Counts counts;
  const auto formatStart = std::chrono::steady_clock::now();
  auto elapsed = [&]
  { return std::chrono::duration<double>(std::chrono::steady_clock::now() - formatStart).count(); };
  while (
    options.MutantsPerFormat > 0 ? counts.Mutants < options.MutantsPerFormat : elapsed() < seconds)
  {
    const Seed& s = seeds[mutator.Below(seeds.size())];
    const std::string path = dir + "/mutant." + format;
    WriteFile(path, mutator.Mutate(s.Data, text));
    if (!s.Companion.empty())
    {
      WriteFile(dir + "/" + s.Companion,
        mutator.Below(4) ? s.CompanionData : mutator.Mutate(s.CompanionData, false));
    }
    std::string problem;
    const Outcome outcome = Run(path, problem);
    Count(outcome, counts);
    if (outcome != Outcome::Read && outcome != Outcome::Rejected)
    {
      KeepFinding(options, format, dir, s, problem, counts.Mutants);
    }
  }
  std::cout << "fuzz: " << format << ": " << counts.Mutants << " mutants in "
            << static_cast<int>(elapsed() + 0.5) << " s (" << counts.Read << " read, "
            << counts.Rejected << " rejected), crashes " << counts.Crashes << ", hangs "
            << counts.Hangs << ", reports " << counts.Reports << ", silent blanks "
            << counts.SilentBlanks << std::endl;
  return counts;
}

// Every format of --formats in turn; returns the exit status.
int Fuzz(const FuzzOptions& options)
{
  std::vector<std::string> pool;
  std::map<std::string, std::vector<Seed>> byFormat = LoadSeeds(options.Seeds, pool);
  const std::vector<std::string> formats = SplitFormats(options.Formats);
  MakeDirectories(options.Work);
  if (!options.Crashes.empty())
  {
    MakeDirectories(options.Crashes);
  }
  Counts total;
  int failedFormats = 0;
  const auto begin = std::chrono::steady_clock::now();
  for (size_t f = 0; f < formats.size(); ++f)
  {
    const std::string& format = formats[f];
    const std::vector<Seed>& seeds = byFormat[format];
    if (seeds.empty())
    {
      std::cerr << "npr-fuzz-readers: no seed of format '" << format << "' in " << options.Seeds
                << "\n";
      return 2;
    }
    // A mutator per format, so that a format's mutants do not depend on how many the formats
    // before it ran in their time: mutant k of a format is the same in every run of a --seed.
    Mutator mutator(options.Seed * 1000003u + f, pool);
    const std::string dir = options.Work + "/" + format;
    MakeDirectories(dir);
    if (!SeedsRead(seeds, dir, format))
    {
      return 2;
    }
    const Counts counts = FuzzFormat(
      options, format, seeds, mutator, dir, options.Seconds / static_cast<double>(formats.size()));
    failedFormats += counts.Crashes + counts.Hangs + counts.Reports + counts.SilentBlanks > 0;
    total.Mutants += counts.Mutants;
    total.Crashes += counts.Crashes;
    total.Hangs += counts.Hangs;
    total.Reports += counts.Reports;
    total.SilentBlanks += counts.SilentBlanks;
  }
  std::cout << "fuzz: " << total.Mutants << " mutants of " << formats.size() << " formats in "
            << static_cast<int>(
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() +
                 0.5)
            << " s (seed " << options.Seed << "), crashes " << total.Crashes << ", hangs "
            << total.Hangs << ", reports " << total.Reports << ", silent blanks "
            << total.SilentBlanks << "; " << formats.size() - failedFormats << " of "
            << formats.size()
            << (options.Explore ? " formats without findings (--explore: findings do not fail)"
                                : " formats passed")
            << std::endl;
  return failedFormats && !options.Explore ? 1 : 0;
}
}

int main(int argc, char* argv[])
{
  FuzzOptions options;
  if (!ParseFuzzOptions(argc, argv, options))
  {
    return Usage();
  }
  // The children's VTK messages are expected (rejected files): keep them off the log.
  vtkNew<vtkStringOutputWindow> quiet;
  vtkOutputWindow::SetInstance(quiet);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  if (!options.Replay.empty() || !options.Valid.empty())
  {
    return Replay(options);
  }
  if (options.Seeds.empty() || options.Work.empty() ||
    (options.Seconds <= 0 && options.MutantsPerFormat <= 0))
  {
    return Usage();
  }
  return Fuzz(options);
}
