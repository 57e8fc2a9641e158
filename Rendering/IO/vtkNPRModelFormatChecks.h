// Structural checks run before VTK's own readers, which trust their input: vtkPLYReader reads
// past the end of a truncated file (and crashes), vtkSTLReader takes any bytes as binary STL.
// Each returns "" for a well-formed file, else what is wrong with it.
#ifndef vtkNPRModelFormatChecks_h
#define vtkNPRModelFormatChecks_h

#include <string>

namespace vtkNPRModelFormatChecks
{
std::string CheckPLY(const std::string& fileName);
std::string CheckSTL(const std::string& fileName);
}

#endif
