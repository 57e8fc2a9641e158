// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// What vtkNPRFeatureLines keeps per mesh: the mesh's edges with their faces, built once, and the
// passes each viewpoint makes over them. Private to NPR::Lines.
//
// Memory (the mesh's own points and cells are read where they are, vtkNPRMeshFaces): per face
// kept, a single-precision copy of its plane for the side-of-plane test (17 bytes) and its side
// for the last viewpoint (1), and its number in the input (4) only where the faces are
// renumbered; per edge, its two faces (8), its kind (1) and which edge of its first face it is
// (1); per point, its representative (4) only where coincident points were merged. About 33
// bytes a triangle in all (GetMemorySize()). The build's scratch peaks at about 60 bytes a
// triangle (the faces' edge uses bucketed by point, 8 bytes a use, is most of it).
#ifndef vtkNPRMeshAdjacency_h
#define vtkNPRMeshAdjacency_h

#include "vtkNPRMeshFaces.h"      // for vtkNPRMeshFaces
#include "vtkNPRSmoothContours.h" // for vtkNPRSmoothContours
#include "vtkType.h"              // for vtkIdType, vtkMTimeType

#include <atomic>  // for the build's buckets
#include <cstddef> // for size_t
#include <cstdint> // for the packed arrays
#include <vector>  // for the packed arrays

class vtkCellArray;
class vtkDataArray;
class vtkObject;
class vtkPoints;
class vtkPolyData;

class vtkNPRMeshAdjacency
{
public:
  // An edge's kind (bits of EdgeKinds).
  enum Kind : unsigned char
  {
    Boundary = 1,      // one face
    NonManifold = 2,   // more than two faces
    TwoFaces = 4,      // two faces: crease and silhouette tests
    SameDirection = 8, // the two faces traverse the edge the same way: flip the second
    Split = 16,        // two faces that reach it through different points (merged coordinates)
    Crease = 32,       // the faces' angle exceeds the last UpdateCreases() angle
  };

  // Whether the table was built from this input as it is now (its points and cells unchanged).
  bool IsCurrent(vtkPolyData* input, bool merge) const;
  // Builds the table; `self` reports errors and warnings.
  void Build(vtkPolyData* input, bool merge, vtkObject* self);

  vtkIdType GetNumberOfEdges() const { return static_cast<vtkIdType>(this->EdgeKinds.size()); }
  vtkIdType GetNumberOfFaces() const { return this->KeptFaces; }
  vtkIdType GetNumberOfDegenerateFaces() const { return this->DegenerateFaces; }
  vtkIdType GetNumberOfNonFiniteFaces() const { return this->NonFiniteFaces; }
  vtkIdType GetNumberOfUnsureFaces() const { return this->UnsureFaces; }
  vtkIdType GetNumberOfSkippedContourTriangles() const
  {
    return this->Contours.GetNumberOfSkippedTriangles();
  }
  // Bytes held between updates (the smooth contours' tables included, once made).
  size_t GetMemorySize() const;
  const vtkNPRMeshFaces& GetMesh() const { return this->Mesh; }

  // ---- Each viewpoint ----
  // Zeroes the counts of the last update (unsure faces, skipped contour triangles).
  void ClearViewCounts()
  {
    this->UnsureFaces = 0;
    this->Contours.ClearSkippedTriangles();
  }
  // The Crease bits for this angle (degrees), made again only when it changes.
  void UpdateCreases(double angle);
  // FaceSides and UnsureFaces for an eye (perspective) or a direction of projection (parallel).
  void ComputeFaceSides(bool parallel, const double view[3]);

  // What an update asks for, and its viewpoint.
  struct View
  {
    bool Parallel = false;
    double Eye[3] = { 0.0, 0.0, 0.0 };
    double Direction[3] = { 0.0, 0.0, -1.0 };
    bool Silhouettes = false;   // mesh silhouettes (FaceSides computed)
    bool SplitContours = false; // silhouettes at Split edges only (smooth contours; FaceSides)
    bool Creases = false;       // the Crease bits current (UpdateCreases)
    bool Boundaries = false, NonManifoldEdges = false;
  };
  // A typed edge of the output: Order sorts them as the faces first use them.
  struct TypedEdge
  {
    std::uint64_t Order; // the input number of its first face, then which edge of it
    std::uint32_t A, B;  // point ids, A < B (representatives when merging)
    unsigned char Type;  // FeatureType bits
    bool operator<(const TypedEdge& other) const { return this->Order < other.Order; }
  };
  // The edges with a type for this view, in the order the faces first use them.
  std::vector<TypedEdge> ClassifyEdges(const View& view) const;

  // ---- Smooth contours ----
  // Facing, segments and skipped triangles (GetContours) for an eye (perspective) or a direction
  // of projection (parallel), from the input's point normals (vtkNPRSmoothContours::PointNormals).
  void ComputeContours(vtkDataArray* normals, bool parallel, const double view[3])
  {
    this->Contours.Compute(this->Mesh, normals, parallel, view);
  }
  const vtkNPRSmoothContours& GetContours() const { return this->Contours; }

private:
  struct Use; // one face's use of an edge, read back from the mesh
  // Build steps.
  void Reset(vtkPolyData* input, bool merge);
  std::vector<unsigned char> FindFinitePoints();
  void MergePoints(const std::vector<unsigned char>& finite);
  std::vector<std::uint32_t> OrderFaces(const std::vector<unsigned char>& finite);
  std::vector<std::uint64_t> KeyFaces(const std::vector<unsigned char>& finite);
  void FindEdges(const std::vector<std::uint32_t>& renumber);
  void MakeEdges(const std::vector<std::uint64_t>& uses, const std::atomic<std::uint32_t>* start,
    const std::vector<std::uint32_t>& renumber);
  void MakeEdge(size_t e, const Use& use0, const std::uint64_t* uses, size_t count,
    const std::vector<std::uint32_t>& renumber);
  void MakeFaceView(vtkIdType face, vtkIdType size, const vtkIdType* ids, const double unit[3]);
  void ReorderFaceViews();
  // Helpers.
  std::uint32_t Representative(vtkIdType id) const
  {
    return this->Representatives.empty() ? static_cast<std::uint32_t>(id)
                                         : this->Representatives[id];
  }
  bool SameCoordinates(std::uint32_t a, std::uint32_t b) const;
  std::uint32_t Source(std::uint32_t face) const // its number in the input
  {
    return this->FaceSource.empty() ? face : this->FaceSource[face];
  }
  Use ReadUse(std::uint64_t use) const;
  bool FaceNormal(std::uint32_t face, double unit[3]) const; // face: its number here
  double Angle(vtkIdType edge) const;                        // dihedral, degrees
  void EdgePoints(vtkIdType edge, std::uint32_t& a, std::uint32_t& b) const;
  vtkIdType EdgeLocal(vtkIdType edge) const
  {
    return this->EdgeLocal8.empty() ? this->EdgeLocal32[edge] : this->EdgeLocal8[edge];
  }
  unsigned char EdgeType(vtkIdType edge, const View& view) const;
  bool IsSilhouette(vtkIdType edge, const View& view) const;

  // What the table was built from.
  vtkPolyData* Input = nullptr;
  vtkPoints* Points = nullptr;
  vtkCellArray* Polys = nullptr;
  vtkCellArray* Strips = nullptr;
  vtkMTimeType InputTime = 0, PointsTime = 0, PointsDataTime = 0, PolysTime = 0, StripsTime = 0;
  bool Merged = true;
  bool Valid = false;
  vtkNPRMeshFaces Mesh;

  double Lower[3], Upper[3]; // the finite points' bounds
  double Centre[3] = { 0.0, 0.0, 0.0 };
  std::vector<std::uint32_t> Representatives; // empty: every point is its own
  // The oriented faces (KeptFaces), in the input's order where it is local, else by the cell of
  // their first points in a 2^FaceOrderBits grid (an edge's two faces are then near each other in
  // FaceSides whatever the input's order): each one's number in the input (FaceSource, empty
  // where the order is the input's), and for the side-of-plane test of each camera (instead of a
  // normal and a point in double per edge): its unit normal in float, its offset n.(q - c) for its
  // first point q relative to the mesh's centre c, and the power of two B that bounds the error
  // of the test, FaceSideTolerance * (B + |eye - c|), with B at least |offset| + |q - c| + the
  // face's size + how far its other points lie from the plane through q / FaceSideTolerance.
  vtkIdType KeptFaces = 0;
  std::vector<std::uint32_t> FaceSource; // empty: the input's order, every face kept
  std::vector<float> FaceNormals[3], FaceOffsets;
  std::vector<std::uint8_t> FaceBounds; // the bound's power of two, as a float's exponent bits
  // The edges, ordered by their first faces' numbers (so that the viewpoint pass reads FaceSides
  // in order), then as that face uses them: its two faces (the second 0 unless it has two or
  // more), its Kind bits, and which edge of its first face it is (EdgeLocal8, or EdgeLocal32
  // where a face has more than 256 points).
  std::vector<std::uint32_t> EdgeFaces;
  std::vector<unsigned char> EdgeKinds;
  std::vector<std::uint8_t> EdgeLocal8;
  std::vector<std::uint32_t> EdgeLocal32;
  double CreaseAngle = -1.0; // of the Crease bits; < 0: none computed
  vtkIdType DegenerateFaces = 0;
  vtkIdType NonFiniteFaces = 0;
  // Each face's side (SideFacing, SideUnsure bits) for the last viewpoint.
  std::vector<unsigned char> FaceSides;
  vtkIdType UnsureFaces = 0;

  // Smooth contours, made only when asked for.
  vtkNPRSmoothContours Contours;
};

#endif
// VTK-HeaderTest-Exclude: vtkNPRMeshAdjacency.h
