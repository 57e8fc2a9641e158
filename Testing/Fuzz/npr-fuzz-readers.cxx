// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// npr-fuzz-readers: a mutation fuzzer of vtkNPRModelReader over the committed seed files of every
// format, and the replay of seeds and crash reproducers as a regression test.
//
//   npr-fuzz-readers --seeds DIR --work DIR [--seconds S | --mutants N] [--seed K]
//                    [--crashes DIR] [--formats stl,obj,...]
//   npr-fuzz-readers --replay DIR... [--valid DIR]
//
// Each input is read in a child process (fork), as npr-render reads a model (vtkNPRModelReader,
// then vtkNPRShadingNormals), with a 10 s alarm: a signal is a crash, the alarm a hang, any other
// non-zero exit a sanitizer report or a broken promise of the reader (an error with a non-empty
// output, or a success with nothing drawable: no cell, a non-finite point, an index out of
// range). Mutants are deterministic for a --seed: bit flips, interesting bytes and integers,
// insertions, deletions, truncations, splices with other seeds and, in text, numbers replaced
// by interesting ones. A glTF mutant gets its .bin alongside, mutated one time in four.
// Every crashing or hanging mutant is copied to --crashes. Exit status 1 when any was found.
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

// What the child found: 0 read, 10 rejected with an error, 3 a broken promise of the reader.
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
  Report
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
    if (status == 3)
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
      this->MutateOnce(data, text);
    }
    return data;
  }

private:
  void MutateOnce(std::string& data, bool text)
  {
    static const char* numbers[] = { "0", "-1", "1", "2", "3", "7", "8", "9", "255", "256", "65535",
      "65536", "2147483647", "2147483648", "-2147483648", "4294967295", "4294967296",
      "9223372036854775807", "99999999999999999999", "1e308", "-1e308", "1e-320", "nan", "inf",
      "-inf", "-0", "0.5", "1e9", "" };
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
      {
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
        break;
      }
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
      {
        const std::string& other = this->Pool[this->Below(this->Pool.size())];
        if (!other.empty())
        {
          const size_t from = this->Below(other.size());
          const size_t at = this->Below(size + 1);
          data.replace(at, this->Below(std::min<size_t>(size - at, 64) + 1),
            other.substr(from, 1 + this->Below(std::min<size_t>(other.size() - from, 128))));
        }
        break;
      }
      case 7: // overwrite a chunk with a chunk of itself
        if (size > 2)
        {
          const size_t from = this->Below(size), to = this->Below(size);
          const size_t n = 1 + this->Below(std::min(size - std::max(from, to), size_t(32)));
          data.replace(to, n, data.substr(from, n));
        }
        break;
      default: // text: a number replaced by an interesting one, or a line repeated
        if (size && this->Below(4))
        {
          size_t at = this->Below(size);
          const size_t digit = data.find_first_of("0123456789", at);
          if (digit == std::string::npos)
          {
            break;
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
          const std::string line =
            data.substr(from, end == std::string::npos ? end : end - from + 1);
          this->Below(2) ? data.insert(from, line) : data.erase(from, line.size());
        }
        break;
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
  long long Mutants = 0, Read = 0, Rejected = 0, Crashes = 0, Hangs = 0, Reports = 0;
};

int Usage()
{
  std::cerr << "usage: npr-fuzz-readers --seeds DIR --work DIR [--seconds S | --mutants N] "
               "[--seed K] [--crashes DIR] [--formats LIST]\n"
               "       npr-fuzz-readers --replay DIR... [--valid DIR]\n";
  return 2;
}
}

int main(int argc, char* argv[])
{
  std::string seeds, work, crashes, valid, formatList = "stl,obj,ply,vtp,vtk,gltf,glb,off";
  std::vector<std::string> replay;
  double seconds = 0;
  long long mutantsPerFormat = 0;
  uint64_t seed = 1;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--seeds" && hasValue)
    {
      seeds = argv[++i];
    }
    else if (arg == "--work" && hasValue)
    {
      work = argv[++i];
    }
    else if (arg == "--crashes" && hasValue)
    {
      crashes = argv[++i];
    }
    else if (arg == "--seconds" && hasValue)
    {
      seconds = std::atof(argv[++i]);
    }
    else if (arg == "--mutants" && hasValue)
    {
      mutantsPerFormat = std::atoll(argv[++i]);
    }
    else if (arg == "--seed" && hasValue)
    {
      seed = std::strtoull(argv[++i], nullptr, 10);
    }
    else if (arg == "--formats" && hasValue)
    {
      formatList = argv[++i];
    }
    else if (arg == "--valid" && hasValue)
    {
      valid = argv[++i];
    }
    else if (arg == "--replay")
    {
      while (i + 1 < argc && argv[i + 1][0] != '-')
      {
        replay.push_back(argv[++i]);
      }
    }
    else
    {
      return Usage();
    }
  }
  // The children's VTK messages are expected (rejected files): keep them off the log.
  vtkNew<vtkStringOutputWindow> quiet;
  vtkOutputWindow::SetInstance(quiet);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);

  if (!replay.empty() || !valid.empty())
  {
    // Regression: every seed reads without error, every reproducer neither crashes nor hangs.
    int failures = 0, files = 0;
    if (!valid.empty())
    {
      replay.push_back(valid);
    }
    for (const std::string& dir : replay)
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
        bool ok = outcome == Outcome::Read || (outcome == Outcome::Rejected && dir != valid);
        if (outcome == Outcome::Rejected && dir == valid)
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
  if (seeds.empty() || work.empty() || (seconds <= 0 && mutantsPerFormat <= 0))
  {
    return Usage();
  }

  // Seeds by format; every seed's bytes also feed the splices.
  std::map<std::string, std::vector<Seed>> byFormat;
  std::vector<std::string> pool;
  for (const std::string& name : ListFiles(seeds))
  {
    const std::string extension = Extension(name);
    if (extension == "bin" || extension == "md")
    {
      continue;
    }
    Seed s{ name, ReadFile(seeds + "/" + name), "", "" };
    if (extension == "gltf")
    {
      const size_t uri = s.Data.find("\"uri\": \"");
      const size_t end = uri == std::string::npos ? uri : s.Data.find('"', uri + 8);
      if (uri != std::string::npos && s.Data.compare(uri + 8, 5, "data:") != 0)
      {
        s.Companion = s.Data.substr(uri + 8, end - uri - 8);
        s.CompanionData = ReadFile(seeds + "/" + s.Companion);
      }
    }
    pool.push_back(s.Data);
    byFormat[extension].push_back(s);
  }
  std::vector<std::string> formats;
  for (size_t start = 0; start <= formatList.size();)
  {
    const size_t comma = std::min(formatList.find(',', start), formatList.size());
    formats.push_back(formatList.substr(start, comma - start));
    start = comma + 1;
  }
  MakeDirectories(work);
  if (!crashes.empty())
  {
    MakeDirectories(crashes);
  }

  Counts total;
  int failedFormats = 0;
  const auto begin = std::chrono::steady_clock::now();
  for (size_t f = 0; f < formats.size(); ++f)
  {
    const std::string& format = formats[f];
    const std::vector<Seed>& candidates = byFormat[format];
    if (candidates.empty())
    {
      std::cerr << "npr-fuzz-readers: no seed of format '" << format << "' in " << seeds << "\n";
      return 2;
    }
    // A mutator per format, so that a format's mutants do not depend on how many the formats
    // before it ran in their time: mutant k of a format is the same in every run of a --seed.
    Mutator mutator(seed * 1000003u + f, pool);
    const std::string dir = work + "/" + format;
    MakeDirectories(dir);
    // Every seed, unmutated, must read where the mutants are written: else nothing is fuzzed.
    for (const Seed& s : candidates)
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
        return 2;
      }
    }
    const bool text = format != "glb";
    Counts counts;
    const auto formatStart = std::chrono::steady_clock::now();
    auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - formatStart).count();
    };
    while (mutantsPerFormat > 0 ? counts.Mutants < mutantsPerFormat
                                : elapsed() < seconds / static_cast<double>(formats.size()))
    {
      const Seed& s = candidates[mutator.Below(candidates.size())];
      const std::string path = dir + "/mutant." + format;
      WriteFile(path, mutator.Mutate(s.Data, text));
      if (!s.Companion.empty())
      {
        WriteFile(dir + "/" + s.Companion,
          mutator.Below(4) ? s.CompanionData : mutator.Mutate(s.CompanionData, false));
      }
      std::string problem;
      const Outcome outcome = Run(path, problem);
      ++counts.Mutants;
      counts.Read += outcome == Outcome::Read;
      counts.Rejected += outcome == Outcome::Rejected;
      counts.Crashes += outcome == Outcome::Crash;
      counts.Hangs += outcome == Outcome::Hang;
      counts.Reports += outcome == Outcome::Report;
      if (outcome == Outcome::Crash || outcome == Outcome::Hang || outcome == Outcome::Report)
      {
        const std::string name =
          format + "-" + std::to_string(seed) + "-" + std::to_string(counts.Mutants) + "." + format;
        std::cout << "npr-fuzz-readers: " << format << ": " << problem << " on a mutant of "
                  << s.Name << (crashes.empty() ? "" : ", saved as " + crashes + "/" + name)
                  << std::endl;
        if (!crashes.empty())
        {
          WriteFile(crashes + "/" + name, ReadFile(path));
          if (!s.Companion.empty())
          {
            WriteFile(crashes + "/" + name + "." + s.Companion, ReadFile(dir + "/" + s.Companion));
          }
        }
      }
    }
    std::cout << "fuzz: " << format << ": " << counts.Mutants << " mutants in "
              << static_cast<int>(elapsed() + 0.5) << " s (" << counts.Read << " read, "
              << counts.Rejected << " rejected), crashes " << counts.Crashes << ", hangs "
              << counts.Hangs << ", reports " << counts.Reports << std::endl;
    failedFormats += counts.Crashes + counts.Hangs + counts.Reports > 0;
    total.Mutants += counts.Mutants;
    total.Crashes += counts.Crashes;
    total.Hangs += counts.Hangs;
    total.Reports += counts.Reports;
  }
  std::cout << "fuzz: " << total.Mutants << " mutants of " << formats.size() << " formats in "
            << static_cast<int>(
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() +
                 0.5)
            << " s (seed " << seed << "), crashes " << total.Crashes << ", hangs " << total.Hangs
            << ", reports " << total.Reports << "; " << formats.size() - failedFormats << " of "
            << formats.size() << " formats passed" << std::endl;
  return failedFormats ? 1 : 0;
}
