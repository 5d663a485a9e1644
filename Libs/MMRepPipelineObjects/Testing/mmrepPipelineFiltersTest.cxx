// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The stage filters as VTK algorithms: the same results as the free functions they wrap (the
// surfaces, the repair), an independent truth for the muscle inference (an affine map keeps every
// track point's element and parametric coordinates), progress events that rise to 1, abort inside
// a long stage (empty output, the stage downstream says why), and errors as one-line ErrorEvents.
#include "mmrepAtlasRegistrationFilter.h"
#include "mmrepFEMeshIO.h"
#include "mmrepLandmarkIO.h"
#include "mmrepLipsRefinementFilter.h"
#include "mmrepMeshRepairFilter.h"
#include "mmrepMuscleInferenceFilter.h"
#include "mmrepSubjectSurfacesFilter.h"

#include <gtest/gtest.h>

#include <itkAffineTransform.h>
#include <itkImageFileReader.h>
#include <vtkCallbackCommand.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkTrivialProducer.h>
#include <vtkUnstructuredGrid.h>

#include <vector>

namespace
{
const std::string kCT = std::string(MMREP_SAMPLE_DATA) + "/cthead.nrrd";
const std::string kPoints = std::string(MMREP_SAMPLE_DATA) + "/cthead.ControlPoints.mrk.json";
const std::string kAtlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";

// Records a filter's progress values and error messages; aborts it past `abortAt`.
struct Recorder
{
  std::vector<double> progress;
  std::vector<std::string> errors;
  double abortAt = 2;
  vtkNew<vtkCallbackCommand> command;
  explicit Recorder(vtkAlgorithm* filter)
  {
    command->SetClientData(this);
    command->SetCallback([](vtkObject* caller, unsigned long event, void* self, void* data) {
      auto* r = static_cast<Recorder*>(self);
      auto* f = vtkAlgorithm::SafeDownCast(caller);
      if (event == vtkCommand::ErrorEvent)
        r->errors.emplace_back(static_cast<const char*>(data));
      else
      {
        r->progress.push_back(f->GetProgress());
        if (f->GetProgress() >= r->abortAt)
          f->AbortExecuteOn();
      }
    });
    filter->AddObserver(vtkCommand::ProgressEvent, command);
    filter->AddObserver(vtkCommand::ErrorEvent, command);
  }
};

vtkSmartPointer<vtkTrivialProducer> Producer(vtkDataObject* data)
{
  auto p = vtkSmartPointer<vtkTrivialProducer>::New();
  p->SetOutput(data);
  return p;
}

double MaxDistance(vtkPolyData* a, vtkPolyData* b)
{
  EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  double worst = 0;
  for (vtkIdType i = 0; i < std::min(a->GetNumberOfPoints(), b->GetNumberOfPoints()); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(p[c] - q[c]));
  }
  return worst;
}

TEST(PipelineFilters, SurfacesFromAnItkReaderEqualTheFreeFunctionAndReportProgress)
{
  auto reader = itk::ImageFileReader<mmrep::CTImage>::New();
  reader->SetFileName(kCT);
  vtkNew<mmrep::SubjectSurfacesFilter> surfaces;
  surfaces->SetInput(reader->GetOutput());
  surfaces->SetOpeningRadius(1);
  EXPECT_EQ(surfaces->GetOpeningRadius(), 1u);
  Recorder recorder(surfaces);
  surfaces->Update();
  ASSERT_TRUE(surfaces->GetStatus().error.empty()) << surfaces->GetStatus().error;

  const auto expected = mmrep::ExtractSubjectSurfaces(mmrep::ReadCTImage(kCT), mmrep::FaceModelOptions{});
  EXPECT_GT(surfaces->GetSkin()->GetNumberOfPoints(), 10000);
  EXPECT_EQ(MaxDistance(surfaces->GetSkin(), expected.skin), 0.0);
  EXPECT_EQ(MaxDistance(surfaces->GetSkull(), expected.skull), 0.0);
  EXPECT_EQ(surfaces->GetSkin()->GetNumberOfCells(), expected.skin->GetNumberOfCells());
  EXPECT_EQ(surfaces->GetThresholds().skin, expected.thresholds.skin);
  ASSERT_GE(recorder.progress.size(), 4u);
  EXPECT_EQ(recorder.progress.front(), 0.0);
  EXPECT_EQ(recorder.progress.back(), 1.0);
  for (std::size_t i = 1; i < recorder.progress.size(); ++i)
    EXPECT_GE(recorder.progress[i], recorder.progress[i - 1]);

  // An unreadable CT: one line naming the file, empty outputs.
  reader->SetFileName("/nonexistent/ct.nrrd");
  surfaces->Modified();
  surfaces->Update();
  ASSERT_EQ(recorder.errors.size(), 1u);
  EXPECT_NE(recorder.errors[0].find("/nonexistent/ct.nrrd"), std::string::npos) << recorder.errors[0];
  EXPECT_EQ(surfaces->GetSkin()->GetNumberOfPoints(), 0);
}

TEST(PipelineFilters, RegistrationAbortsInsideRAndTheStageDownstreamSaysWhy)
{
  auto reader = itk::ImageFileReader<mmrep::CTImage>::New();
  reader->SetFileName(kCT);
  vtkNew<mmrep::SubjectSurfacesFilter> surfaces;
  surfaces->SetInput(reader->GetOutput());
  auto atlas = mmrep::ToVTK(mmrep::ReadFEMesh(kAtlas));
  auto atlasProducer = Producer(atlas);
  vtkNew<mmrep::AtlasRegistrationFilter> registration;
  registration->SetInputConnection(0, atlasProducer->GetOutputPort());
  registration->SetInputConnection(1, surfaces->GetOutputPort(0));
  registration->SetInputConnection(2, surfaces->GetOutputPort(1));
  registration->SetControlPoints(mmrep::ReadLandmarks(kPoints));
  Recorder recorder(registration);
  recorder.abortAt = 0.3; // past the plane (0.15): inside RegisterAtlas's levels
  vtkNew<mmrep::LipsRefinementFilter> refinement;
  refinement->SetInputConnection(0, registration->GetOutputPort());
  refinement->SetInputConnection(1, surfaces->GetOutputPort(0));
  Recorder downstream(refinement);
  refinement->Update();

  EXPECT_TRUE(registration->GetStatus().aborted);
  EXPECT_TRUE(registration->GetStatus().error.empty());
  EXPECT_EQ(registration->GetOutput()->GetNumberOfPoints(), 0);
  ASSERT_FALSE(recorder.progress.empty());
  EXPECT_LT(recorder.progress.back(), 0.5); // stopped at the next progress step
  EXPECT_TRUE(registration->GetTransform()->GetElasticTransforms().empty());
  ASSERT_EQ(downstream.errors.size(), 1u);
  EXPECT_NE(downstream.errors[0].find("registered mesh (input 0) is missing or empty"), std::string::npos)
    << downstream.errors[0];
  EXPECT_EQ(downstream.errors[0].find('\n'), std::string::npos);
  EXPECT_EQ(refinement->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(PipelineFilters, RegistrationRefusesMissingControlPointsInOneLine)
{
  auto atlas = mmrep::ToVTK(mmrep::ReadFEMesh(kAtlas));
  auto atlasProducer = Producer(atlas);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<mmrep::AtlasRegistrationFilter> registration;
  registration->SetInputConnection(0, atlasProducer->GetOutputPort());
  registration->SetInputConnection(1, sphere->GetOutputPort());
  registration->SetInputConnection(2, sphere->GetOutputPort());
  auto points = mmrep::ReadLandmarks(kPoints);
  const std::string dropped = points.back().name;
  points.pop_back();
  registration->SetControlPoints(points);
  registration->SetMapSpacing(2.0);
  EXPECT_EQ(registration->GetMapSpacing(), 2.0);
  registration->SetSymmetryMode("averaged");
  EXPECT_EQ(registration->GetSymmetryMode(), "averaged");
  EXPECT_FALSE(registration->GetRegistrationOptions().halfFace);
  Recorder recorder(registration);
  registration->Update();
  ASSERT_EQ(recorder.errors.size(), 1u);
  EXPECT_NE(recorder.errors[0].find("'" + dropped + "' is missing"), std::string::npos) << recorder.errors[0];
  EXPECT_EQ(recorder.errors[0].find('\n'), std::string::npos);
  EXPECT_EQ(registration->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_FALSE(registration->GetStatus().error.empty());
}

TEST(PipelineFilters, RepairEqualsRepairMeshAndItsOptionsAreMembers)
{
  // The atlas with a column of hypodermis squashed: elements below the threshold to repair.
  auto mesh = mmrep::ReadFEMesh(kAtlas);
  const auto& inner = mesh.nodeSets.at("inner");
  const auto& skin = mesh.nodeSets.at("skin");
  for (std::size_t k = 0; k < 20; ++k)
  {
    const auto n = static_cast<std::size_t>(inner[k * 37]);
    mesh.nodes[n] = 0.3 * mesh.nodes[n] + 0.7 * mesh.nodes[static_cast<std::size_t>(skin[k * 53])];
  }
  auto input = mmrep::ToVTK(mesh);
  auto producer = Producer(input);
  vtkNew<mmrep::MeshRepairFilter> repair;
  repair->SetInputConnection(0, producer->GetOutputPort());
  const auto before = repair->GetMTime();
  repair->SetScaledJacobianThreshold(0.35);
  repair->SetMaximumSweeps(60);
  EXPECT_GT(repair->GetMTime(), before);
  EXPECT_EQ(repair->GetScaledJacobianThreshold(), 0.35);
  EXPECT_EQ(repair->GetMaximumSweeps(), 60);
  Recorder recorder(repair);
  repair->Update();
  ASSERT_TRUE(repair->GetStatus().error.empty()) << repair->GetStatus().error;

  mmrep::RepairOptions options;
  options.scaledJacobianThreshold = 0.35;
  options.maximumSweeps = 60;
  auto expected = mesh;
  const auto report = mmrep::RepairMesh(expected, options);
  ASSERT_GT(report.belowThresholdBefore, 0u);
  EXPECT_EQ(repair->GetReport().belowThresholdBefore, report.belowThresholdBefore);
  EXPECT_EQ(repair->GetReport().success, report.success);
  EXPECT_EQ(repair->GetReport().movedNodes, report.movedNodes);
  const auto out = mmrep::FromVTK(repair->GetOutput());
  ASSERT_EQ(out.nodes.size(), expected.nodes.size());
  for (std::size_t i = 0; i < out.nodes.size(); ++i)
    ASSERT_EQ(out.nodes[i], expected.nodes[i]) << i;
  EXPECT_EQ(recorder.progress.back(), 1.0);
}

TEST(PipelineFilters, MusclesThroughAnAffineItkTransformKeepTheirElementsAndParametricCoordinates)
{
  const auto atlasMesh = mmrep::ReadFEMesh(kAtlas);
  auto transform = itk::AffineTransform<double, 3>::New();
  itk::AffineTransform<double, 3>::MatrixType m;
  m(0, 0) = 1.05;
  m(0, 1) = 0.02;
  m(0, 2) = -0.01;
  m(1, 0) = -0.03;
  m(1, 1) = 0.97;
  m(1, 2) = 0.04;
  m(2, 0) = 0.01;
  m(2, 1) = -0.02;
  m(2, 2) = 1.02;
  transform->SetMatrix(m);
  itk::AffineTransform<double, 3>::OutputVectorType t;
  t[0] = 3;
  t[1] = -2;
  t[2] = 5;
  transform->SetTranslation(t);
  // The subject: the atlas's solid nodes through the map, its muscle nodes left where they were.
  auto subject = atlasMesh;
  std::vector<char> muscleNode(subject.nodes.size(), 0);
  for (const auto& [name, track] : subject.muscles)
    for (auto n : track.nodes)
      muscleNode[static_cast<std::size_t>(n)] = 1;
  auto apply = [&](const mmrep::Point3& x) {
    const auto y = transform->TransformPoint(itk::Point<double, 3>(x.data()));
    return mmrep::Point3(y[0], y[1], y[2]);
  };
  for (std::size_t i = 0; i < subject.nodes.size(); ++i)
    if (!muscleNode[i])
      subject.nodes[i] = apply(subject.nodes[i]);
  auto atlasGrid = mmrep::ToVTK(atlasMesh);
  auto subjectGrid = mmrep::ToVTK(subject);
  auto a = Producer(atlasGrid), s = Producer(subjectGrid);
  vtkNew<mmrep::MuscleInferenceFilter> muscles;
  muscles->SetInputConnection(0, a->GetOutputPort());
  muscles->SetInputConnection(1, s->GetOutputPort());
  muscles->SetAtlasToSubjectTransform(transform);
  muscles->Update();
  ASSERT_TRUE(muscles->GetStatus().error.empty()) << muscles->GetStatus().error;
  const auto out = mmrep::FromVTK(muscles->GetOutput());
  EXPECT_EQ(muscles->GetReport().muscles, atlasMesh.muscles.size());
  std::size_t points = 0;
  for (const auto& [name, track] : atlasMesh.muscles)
  {
    const auto& inferred = out.muscles.at(name);
    for (std::size_t k = 0; k < track.nodes.size(); ++k, ++points)
    {
      const auto n = static_cast<std::size_t>(track.nodes[k]);
      EXPECT_LE((out.nodes[n] - apply(atlasMesh.nodes[n])).norm(), 1e-9) << name;
      EXPECT_EQ(inferred.embedding[k].element, track.embedding[k].element) << name << " " << k;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(inferred.embedding[k].pcoords[c], track.embedding[k].pcoords[c], 1e-6) << name << " " << k;
    }
  }
  EXPECT_GT(points, 100u);

  // Without a transform: one line, empty output.
  muscles->SetAtlasToSubjectTransform(nullptr);
  Recorder recorder(muscles);
  muscles->Update();
  ASSERT_EQ(recorder.errors.size(), 1u);
  EXPECT_NE(recorder.errors[0].find("SetAtlasToSubjectTransform"), std::string::npos);
  EXPECT_EQ(muscles->GetOutput()->GetNumberOfPoints(), 0);
}

} // namespace
