// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The speaker model as one ITK/VTK pipeline (docs/cpp-api.md, "C++ pipeline API"):
//   CT reader (itk::ImageFileReader) -> SubjectSurfacesFilter -> AtlasRegistrationFilter (plane + R)
//   -> LipsRefinementFilter (Q) -> MeshRepairFilter -> MuscleInferenceFilter (through Q∘R, an
//   itk::CompositeTransform) -> vtkXMLUnstructuredGridWriter,
// run by one Update() of the writer. Same stages and defaults as the FaceModelPipeline module, so
// the model is the module's model.vtu (ctest Examples.PipelineModelEqualsFaceModelPipeline).
//
//   FaceModelPipelineExample <ct.nrrd> <controlPoints.mrk.json> <atlas.vtu> <model.vtu>
#include "mmrepAtlasRegistrationFilter.h"
#include "mmrepLandmarkIO.h"
#include "mmrepLipsRefinementFilter.h"
#include "mmrepMeshRepairFilter.h"
#include "mmrepMuscleInferenceFilter.h"
#include "mmrepSubjectSurfacesFilter.h"

#include <itkCompositeTransform.h>
#include <itkImageFileReader.h>
#include <vtkCallbackCommand.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

namespace
{
// Prints "<filter>: 0%" / "100%" lines as the stages run, and keeps the first error of any stage,
// reader or writer (VTK's own messages name a source line first: the last line is the message).
std::string firstError;
void OnEvent(vtkObject* caller, unsigned long event, void*, void* callData)
{
  if (event == vtkCommand::ErrorEvent)
  {
    if (firstError.empty() && !caller->IsA("vtkExecutive")) // an executive only says its algorithm failed
    {
      std::string text = callData ? static_cast<const char*>(callData) : "unknown error";
      while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
      firstError = text.substr(text.find_last_of('\n') + 1);
    }
    return;
  }
  auto* filter = vtkAlgorithm::SafeDownCast(caller);
  if (filter->GetProgress() == 0 || filter->GetProgress() == 1)
    std::cout << filter->GetClassName() << ": " << (filter->GetProgress() == 1 ? "100%" : "0%") << std::endl;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 5)
  {
    std::cerr << "usage: " << argv[0] << " <ct> <controlPoints.mrk.json> <atlas.vtu> <model.vtu>" << std::endl;
    return 2;
  }
  const std::string output = argv[4];
  std::vector<mmrep::Landmark> controlPoints;
  try
  {
    controlPoints = mmrep::ReadLandmarks(argv[2]);
    const auto folder = std::filesystem::absolute(output).parent_path();
    if (!std::filesystem::is_directory(folder))
      throw std::runtime_error(output + ": the folder " + folder.string() + " does not exist");
  }
  catch (const std::exception& e)
  {
    std::cerr << argv[0] << ": error: " << e.what() << std::endl;
    return 1;
  }

  // The pipeline.
  auto ctReader = itk::ImageFileReader<mmrep::CTImage>::New();
  ctReader->SetFileName(argv[1]);
  vtkNew<mmrep::SubjectSurfacesFilter> surfaces;
  surfaces->SetInput(ctReader->GetOutput());

  vtkNew<vtkXMLUnstructuredGridReader> atlasReader;
  atlasReader->SetFileName(argv[3]);

  vtkNew<mmrep::AtlasRegistrationFilter> registration;
  registration->SetInputConnection(0, atlasReader->GetOutputPort());
  registration->SetInputConnection(1, surfaces->GetOutputPort(0)); // skin
  registration->SetInputConnection(2, surfaces->GetOutputPort(1)); // skull
  registration->SetControlPoints(controlPoints);
  registration->SetSymmetryMode("half-face"); // the module's default, as every option below

  vtkNew<mmrep::LipsRefinementFilter> refinement;
  refinement->SetInputConnection(0, registration->GetOutputPort());
  refinement->SetInputConnection(1, surfaces->GetOutputPort(0));
  refinement->SetElementQualityFloor(registration->GetElementQualityFloor());

  vtkNew<mmrep::MeshRepairFilter> repair;
  repair->SetInputConnection(0, refinement->GetOutputPort());
  repair->SetInputConnection(1, surfaces->GetOutputPort(0));
  repair->SetInputConnection(2, surfaces->GetOutputPort(1));
  repair->SetScaledJacobianThreshold(0.3);

  // Q∘R: itk::CompositeTransform applies the transform added last first.
  auto atlasToSubject = itk::CompositeTransform<double, 3>::New();
  atlasToSubject->AddTransform(refinement->GetTransform());
  atlasToSubject->AddTransform(registration->GetTransform());
  vtkNew<mmrep::MuscleInferenceFilter> muscles;
  muscles->SetInputConnection(0, atlasReader->GetOutputPort());
  muscles->SetInputConnection(1, repair->GetOutputPort());
  muscles->SetAtlasToSubjectTransform(atlasToSubject);

  // Written under a temporary name, renamed when complete: no partial model.
  const std::string partial = output + ".partial.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputConnection(muscles->GetOutputPort());
  writer->SetFileName(partial.c_str());

  vtkNew<vtkCallbackCommand> events;
  events->SetCallback(OnEvent);
  for (vtkAlgorithm* stage : std::initializer_list<vtkAlgorithm*>{surfaces, registration, refinement, repair, muscles})
    stage->AddObserver(vtkCommand::ProgressEvent, events);
  // Every error is reported once, below (observed, VTK prints nothing).
  for (vtkAlgorithm* a :
       std::initializer_list<vtkAlgorithm*>{atlasReader, surfaces, registration, refinement, repair, muscles, writer})
  {
    a->AddObserver(vtkCommand::ErrorEvent, events);
    a->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, events);
  }

  const bool written = writer->Write() == 1;
  if (!firstError.empty() || !written || !repair->GetReport().success)
  {
    std::remove(partial.c_str());
    std::cerr << argv[0] << ": error: "
              << (!firstError.empty() ? firstError
                  : !written          ? "cannot write " + output
                                      : "the repair could not bring every element to scaled Jacobian 0.3")
              << std::endl;
    return 1;
  }
  if (std::rename(partial.c_str(), output.c_str()) != 0)
  {
    std::remove(partial.c_str());
    std::cerr << argv[0] << ": error: cannot write " << output << std::endl;
    return 1;
  }
  const auto& r = repair->GetReport();
  std::cout << "Model: " << muscles->GetOutput()->GetNumberOfPoints() << " nodes, "
            << muscles->GetOutput()->GetNumberOfCells() << " cells; plane residual " << registration->GetPlaneResidual()
            << " mm; min scaled Jacobian " << r.minScaledJacobianAfter << "; " << muscles->GetReport().muscles
            << " muscles -> " << output << std::endl;
  return 0;
}
