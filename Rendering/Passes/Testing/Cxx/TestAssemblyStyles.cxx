// SPDX-FileCopyrightText: Copyright (c) 2026 the vtkNPR developers
// SPDX-License-Identifier: BSD-3-Clause
// Actors inside a vtkAssembly or a vtkPropAssembly are styled as the same actors added directly.
// VTK draws an assembly's parts through its paths, each part with the path's composed matrix,
// so the passes' hooks see the part actor while the prop in the frame is the assembly (issue
// 36: the parts got no G-buffer, bands or ink, with a warning that the effect "does not compile
// with the shader of a vtkAssembly"). Each case renders a sphere and a box once as plain actors
// and then inside a flat assembly, nested assemblies, a prop assembly and an assembly with a user
// transform around a nested one (against plain actors with that user transform), and the sphere
// as the one level of a vtkLODProp3D (its drawn level: vtkNPRPropParts), and checks that
// every frame matches the plain one and that VTK printed no warning. The STYLE-mesh-edges cases
// show both actors' mesh edges (EdgeVisibilityOn, red): the drawing draws them through its own
// wireframe companions (vtkNPRMeshEdgesPass), which once left out an assembly's parts.
//
// usage: TestAssemblyStyles edges|toon-edges|sketch|drawing|toon|inked|STYLE-mesh-edges
// NPR_TEST_DUMP=prefix saves the frames as prefixSTYLE-GROUPING.png.
#include "nprTesting.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkImageData.h"
#include "vtkLODProp3D.h"
#include "vtkMatrix4x4.h"
#include "vtkNPRPass.h"
#include "vtkNPRToonPass.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropAssembly.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"

#include <cstdlib>
#include <string>

namespace
{
// How the two actors are added to the renderer.
enum Grouping
{
  Plain,            // directly
  Flat,             // as the parts of one vtkAssembly
  Nested,           // the sphere in an assembly in an assembly, with the box
  Props,            // as the parts of a vtkPropAssembly
  Transformed,      // the sphere in an assembly in an assembly with a user transform, with the box
  TransformedPlain, // directly, each with that user transform (what Transformed is compared with)
  LevelOfDetail     // the sphere as the one level of a vtkLODProp3D, the box directly
};
const char* const GroupingNames[] = { "plain", "assembly", "nested", "prop-assembly",
  "transformed-assembly", "transformed-plain", "lod-prop" };

vtkSmartPointer<vtkActor> NewActor(vtkAlgorithmOutput* port, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  return actor;
}

// The transform of the Transformed groupings: a turn and a shift.
vtkSmartPointer<vtkTransform> UserTransform()
{
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->Translate(0.1, -0.2, 0.0);
  transform->RotateZ(20.0);
  transform->RotateY(-15.0);
  return transform;
}

// A sphere and a box that overlap in the view (an internal silhouette and an object boundary),
// grouped as asked, seen at an angle; the camera depends on nothing but the style.
struct AssemblyScene : nprPassScene
{
  AssemblyScene(int style, Grouping grouping, bool meshEdges)
    : nprPassScene(240, 180)
  {
    this->Pass->SetStyle(style);
    this->Toon()->SetNumberOfBands(3);
    const double sphereCenter[3] = { -0.5, 0.0, 0.3 };
    auto sphereSource = nprSphereSource(0.6, 24, 16, sphereCenter);
    vtkNew<vtkCubeSource> boxSource;
    boxSource->SetCenter(0.5, 0.0, -0.2);
    const double blue[3] = { 0.6, 0.7, 0.9 };
    auto sphere = NewActor(sphereSource->GetOutputPort(), nprGrey);
    auto box = NewActor(boxSource->GetOutputPort(), blue);
    for (vtkActor* actor : { sphere.Get(), box.Get() })
    {
      actor->GetProperty()->SetEdgeVisibility(meshEdges);
      actor->GetProperty()->SetEdgeColor(0.9, 0.1, 0.1);
    }
    this->Add(grouping, sphere, box);
    nprLookAtOrigin(this->Camera(), Eye, 20.0);
    this->Renderer->ResetCameraClippingRange(-2, 2, -2, 2, -2, 2);
  }

  void Add(Grouping grouping, vtkActor* sphere, vtkActor* box)
  {
    vtkNew<vtkAssembly> assembly;
    switch (grouping)
    {
      case Plain:
      case TransformedPlain:
        if (grouping == TransformedPlain)
        {
          sphere->SetUserTransform(UserTransform());
          box->SetUserTransform(UserTransform());
        }
        this->Renderer->AddActor(sphere);
        this->Renderer->AddActor(box);
        return;
      case Nested:
      case Transformed:
      {
        vtkNew<vtkAssembly> inner;
        inner->AddPart(sphere);
        assembly->AddPart(inner);
        assembly->AddPart(box);
        assembly->SetUserTransform(grouping == Transformed ? UserTransform() : nullptr);
        break;
      }
      case LevelOfDetail:
      {
        vtkNew<vtkLODProp3D> levels;
        levels->AddLOD(sphere->GetMapper(), sphere->GetProperty(), 0.0);
        this->Renderer->AddViewProp(levels);
        this->Renderer->AddActor(box);
        return;
      }
      case Props:
      {
        vtkNew<vtkPropAssembly> props;
        props->AddPart(sphere);
        props->AddPart(box);
        this->Renderer->AddViewProp(props);
        return;
      }
      default:
        assembly->AddPart(sphere);
        assembly->AddPart(box);
    }
    this->Renderer->AddViewProp(assembly);
  }

  static constexpr double Eye[3] = { 2.0, 2.5, 5.0 };
};
constexpr double AssemblyScene::Eye[3];

// Two frames of the scene (the second one is compared: the first builds the shaders); VTK's
// warnings counted.
vtkSmartPointer<vtkImageData> RenderFrame(
  int style, Grouping grouping, bool meshEdges, const std::string& name)
{
  AssemblyScene scene(style, grouping, meshEdges);
  scene.Render();
  vtkSmartPointer<vtkImageData> image = scene.Render();
  if (const char* dump = std::getenv("NPR_TEST_DUMP")) // a look at the frame
  {
    nprSavePNG(image, std::string(dump) + name + "-" + GroupingNames[grouping] + ".png");
  }
  return image;
}

// The frames of the groupings against those of the plain actors: at most 0.01 % of the pixels (4)
// more than 16 apart in a channel. They come out identical on llvmpipe; parts drawn with one
// object id between them (no object boundary) differed in 9 pixels of the edges' frame.
int TestAssemblies(int style, const char* styleName, bool meshEdges = false)
{
  const std::string name = std::string(styleName) + (meshEdges ? "-mesh-edges" : "");
  auto* output = nprCountingOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  const int warningsBefore = output ? output->Warnings : 0;
  vtkSmartPointer<vtkImageData> plain = RenderFrame(style, Plain, meshEdges, name);
  vtkSmartPointer<vtkImageData> transformedPlain =
    RenderFrame(style, TransformedPlain, meshEdges, name);
  nprImageTolerance tolerance;
  tolerance.MaxDifferingFraction = 0.0001;
  for (Grouping grouping : { Flat, Nested, Props, Transformed, LevelOfDetail })
  {
    vtkImageData* reference = grouping == Transformed ? transformedPlain : plain;
    const nprImageDifference difference =
      nprCompareImages(RenderFrame(style, grouping, meshEdges, name), reference, tolerance);
    std::cout << name << " " << GroupingNames[grouping] << ": " << difference.DifferingPixels
              << " pixels differ from the plain actors' frame (at most " << difference.MaxDifference
              << " in a channel)\n";
    NPR_CHECK(
      difference.SizeMatches && difference.DifferingFraction <= tolerance.MaxDifferingFraction,
      name << " " << GroupingNames[grouping] << ": " << difference.DifferingPixels
           << " pixels differ from the plain actors' frame");
  }
  const nprImageDifference moved = nprCompareImages(transformedPlain, plain, tolerance);
  NPR_CHECK(moved.DifferingFraction > 0.01, name << ": the user transform moved nothing");
  const int warnings = output ? output->Warnings - warningsBefore : 0;
  NPR_CHECK(output, "no counting output window");
  NPR_CHECK(warnings == 0, name << ": VTK warned " << warnings << " times");
  return nprTestResult();
}
NPR_TEST_CASE("edges", [] { return TestAssemblies(vtkNPRPass::EDGES, "edges"); });
NPR_TEST_CASE("toon-edges", [] { return TestAssemblies(vtkNPRPass::TOON_EDGES, "toon-edges"); });
NPR_TEST_CASE("sketch", [] { return TestAssemblies(vtkNPRPass::SKETCH, "sketch"); });
NPR_TEST_CASE("drawing", [] { return TestAssemblies(vtkNPRPass::DRAWING, "drawing"); });
NPR_TEST_CASE("toon", [] { return TestAssemblies(vtkNPRPass::TOON, "toon"); });
NPR_TEST_CASE("inked", [] { return TestAssemblies(vtkNPRPass::INKED, "inked"); });
NPR_TEST_CASE(
  "drawing-mesh-edges", [] { return TestAssemblies(vtkNPRPass::DRAWING, "drawing", true); });
NPR_TEST_CASE("edges-mesh-edges", [] { return TestAssemblies(vtkNPRPass::EDGES, "edges", true); });
NPR_TEST_CASE("inked-mesh-edges", [] { return TestAssemblies(vtkNPRPass::INKED, "inked", true); });
}
