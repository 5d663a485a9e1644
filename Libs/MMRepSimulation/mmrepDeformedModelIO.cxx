// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The deformed model as a .vtu (see mmrepDeformedModelIO.h).
#include "mmrepDeformedModelIO.h"

#include "mmrepFEMeshIO.h"

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

namespace mmrep::simulation
{

void WriteDeformedModel(const FEMesh& mesh, const ActivationResult& result, const std::string& path)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = ToVTK(DeformedMesh(mesh, result));
  vtkNew<vtkDoubleArray> u, magnitude;
  u->SetName("Displacement");
  u->SetNumberOfComponents(3);
  u->SetNumberOfTuples(static_cast<vtkIdType>(mesh.nodes.size()));
  magnitude->SetName("DisplacementMagnitude");
  magnitude->SetNumberOfValues(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
  {
    u->SetTuple(static_cast<vtkIdType>(i), result.displacements[i].data());
    magnitude->SetValue(static_cast<vtkIdType>(i), result.displacements[i].norm());
  }
  grid->GetPointData()->AddArray(u);
  grid->GetPointData()->AddArray(magnitude);
  grid->GetPointData()->SetActiveVectors("Displacement");
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  if (writer->Write() != 1)
    throw std::runtime_error("cannot write output model '" + path + "'");
}

} // namespace mmrep::simulation
