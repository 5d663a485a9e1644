// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// FEMesh <-> vtkUnstructuredGrid. The grid holds the whole model so a .vtu/.vtk file round-trips
// exactly; naming scheme (also in README.md), where <name> is the set/muscle name with every byte
// outside [A-Za-z0-9_-] written as %XX (so '.', '%', spaces and non-ASCII survive any VTK format):
//   points                                   vtkDoubleArray, node i = point i (bit-exact doubles)
//   cells                                    element i = cell i, VTK_LINE/TETRA/HEXAHEDRON/WEDGE
//   cell data   "Layer"                      int: TissueLayer value (0 none, 1 epidermis, 2 dermis, 3 hypodermis)
//   point data  "MMRep.Mirror"               int: mirror partner of each node (FEMesh::mirror), when known
//   field data  "MMRep.Version"              int: 1
//               "MMRep.NodeSet.<name>"       int: node indices, in set order
//               "MMRep.ElementSet.<name>"    int: element indices, in set order
//               "MMRep.Muscle.<name>.Nodes"  int: track nodes; ".Cables" int: cable elements;
//               ".EmbeddingElements" int and ".EmbeddingPCoords" double x3: embedding per track node;
//               ".MaximumForce" double, one value: the fibre's maximum force in N (absent in older
//               files: MuscleTrack::kDefaultMaximumForce)
//               "MMRep.LandmarkNames"        string; "MMRep.LandmarkPositions" double x3 (same order)
// For viewing only (ignored when reading, field data is authoritative):
//   point data  "NodeSet.<name>"             uint8 mask, 1 for the set's nodes
//   cell data   "ElementSet.<name>"          uint8 mask, 1 for the set's elements
// A grid without these arrays (any plain VTK mesh of lines, tetrahedra, hexahedra, wedges) reads
// as a mesh without sets, muscles or landmarks, all elements in layer "none".
#include "mmrepFEMeshIO.h"

#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mmrep
{
namespace
{

const std::string kPrefix = "MMRep.";
const std::string kMirrorArray = kPrefix + "Mirror";

std::string EncodeName(const std::string& name)
{
  std::string out;
  for (unsigned char c : name)
  {
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')
      out += static_cast<char>(c);
    else
    {
      char hex[4];
      std::snprintf(hex, sizeof(hex), "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

std::string DecodeName(const std::string& encoded)
{
  std::string out;
  for (std::size_t i = 0; i < encoded.size(); ++i)
  {
    if (encoded[i] != '%')
    {
      out += encoded[i];
      continue;
    }
    if (i + 2 >= encoded.size() || !std::isxdigit(static_cast<unsigned char>(encoded[i + 1])) ||
        !std::isxdigit(static_cast<unsigned char>(encoded[i + 2])))
      throw std::runtime_error("field data array name '" + encoded + "' has a bad %-escape");
    out += static_cast<char>(std::stoi(encoded.substr(i + 1, 2), nullptr, 16));
    i += 2;
  }
  return out;
}

vtkSmartPointer<vtkIntArray> IntArray(const std::string& name, const std::vector<std::int32_t>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  return array;
}

vtkSmartPointer<vtkUnsignedCharArray> Mask(const std::string& name, vtkIdType size,
                                           const std::vector<std::int32_t>& ids)
{
  auto array = vtkSmartPointer<vtkUnsignedCharArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfValues(size);
  array->FillValue(0);
  for (auto id : ids)
    array->SetValue(id, 1);
  return array;
}

std::vector<std::int32_t> ReadInts(vtkAbstractArray* abstract)
{
  auto* array = vtkDataArray::SafeDownCast(abstract);
  if (!array || array->GetNumberOfComponents() != 1)
    throw std::runtime_error("data array '" + std::string(abstract->GetName()) +
                             "' must be a numeric array with one component");
  std::vector<std::int32_t> values(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double v = array->GetComponent(i, 0);
    if (!(v == std::floor(v)) || v < std::numeric_limits<std::int32_t>::min() ||
        v > std::numeric_limits<std::int32_t>::max())
      throw std::runtime_error("data array '" + std::string(array->GetName()) + "' holds " + std::to_string(v) +
                               ", not an index");
    values[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(v);
  }
  return values;
}

vtkDataArray* Vectors(vtkAbstractArray* abstract)
{
  auto* array = vtkDataArray::SafeDownCast(abstract);
  if (!array || array->GetNumberOfComponents() != 3)
    throw std::runtime_error("data array '" + std::string(abstract->GetName()) +
                             "' must be a numeric array with three components");
  return array;
}

bool StartsWith(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

// Cells as elements (the four FE cell types only), with their layers.
void ReadElements(vtkUnstructuredGrid* grid, FEMesh& mesh)
{
  vtkDataArray* layers = grid->GetCellData()->GetArray("Layer");
  if (layers && (layers->GetNumberOfComponents() != 1 || layers->GetNumberOfTuples() != grid->GetNumberOfCells()))
    throw std::runtime_error("cell data 'Layer' must have one value per cell");
  vtkNew<vtkIdList> ids;
  mesh.elements.resize(static_cast<std::size_t>(grid->GetNumberOfCells()));
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i)
  {
    Element& e = mesh.elements[static_cast<std::size_t>(i)];
    const int type = grid->GetCellType(i);
    if (type != VTK_LINE && type != VTK_TETRA && type != VTK_HEXAHEDRON && type != VTK_WEDGE)
      throw std::runtime_error("cell " + std::to_string(i) + " is a " + vtkCellTypes::GetClassNameFromTypeId(type) +
                               "; only lines, tetrahedra, hexahedra and wedges are FE elements");
    e.type = static_cast<ElementType>(type);
    grid->GetCellPoints(i, ids);
    if (ids->GetNumberOfIds() != NodeCount(e.type))
      throw std::runtime_error("cell " + std::to_string(i) + " has " + std::to_string(ids->GetNumberOfIds()) +
                               " points for a " + ElementTypeName(e.type));
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      e.nodes[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(ids->GetId(k));
    if (layers)
    {
      const double layer = layers->GetComponent(i, 0);
      if (!(layer == 0 || layer == 1 || layer == 2 || layer == 3))
        throw std::runtime_error("cell " + std::to_string(i) + " has layer " + std::to_string(layer) +
                                 " (expected 0 to 3)");
      e.layer = static_cast<TissueLayer>(static_cast<int>(layer));
    }
  }
}

// Points -> nodes (finite coordinates) and the mirror map.
void ReadNodes(vtkUnstructuredGrid* grid, FEMesh& mesh)
{
  const vtkIdType pointCount = grid->GetNumberOfPoints();
  if (pointCount > std::numeric_limits<std::int32_t>::max())
    throw std::runtime_error("too many points (" + std::to_string(pointCount) + ")");
  mesh.nodes.resize(static_cast<std::size_t>(pointCount));
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    grid->GetPoint(i, mesh.nodes[static_cast<std::size_t>(i)].data());
    if (!mesh.nodes[static_cast<std::size_t>(i)].allFinite())
      throw std::runtime_error("point " + std::to_string(i) + " has a NaN or infinite coordinate");
  }

  if (vtkAbstractArray* mirror = grid->GetPointData()->GetAbstractArray(kMirrorArray.c_str()))
  {
    if (mirror->GetNumberOfTuples() != pointCount)
      throw std::runtime_error("point data '" + kMirrorArray + "' must have one value per point");
    mesh.mirror = ReadInts(mirror);
  }
}

// The landmark arrays (names and positions, both or neither) -> landmarks.
void ReadLandmarks(vtkStringArray* names, vtkAbstractArray* namesArray, vtkDataArray* landmarkPositions, FEMesh& mesh)
{
  if (!namesArray && !landmarkPositions)
    return;
  if (!names || !landmarkPositions || names->GetNumberOfValues() != landmarkPositions->GetNumberOfTuples())
    throw std::runtime_error("landmark names and positions do not match");
  for (vtkIdType k = 0; k < names->GetNumberOfValues(); ++k)
  {
    Landmark landmark;
    landmark.name = names->GetValue(k);
    landmarkPositions->GetTuple(k, landmark.position.data());
    if (!landmark.position.allFinite())
      throw std::runtime_error("landmark '" + landmark.name + "' has a NaN or infinite coordinate");
    mesh.landmarks.push_back(landmark);
  }
}

} // namespace

vtkSmartPointer<vtkUnstructuredGrid> ToVTK(const FEMesh& mesh)
{
  mesh.Validate();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    coordinates->SetTypedTuple(static_cast<vtkIdType>(i), mesh.nodes[i].data());
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  grid->SetPoints(points);

  grid->Allocate(static_cast<vtkIdType>(mesh.elements.size()));
  auto layers = IntArray("Layer", {});
  layers->SetNumberOfValues(static_cast<vtkIdType>(mesh.elements.size()));
  for (std::size_t i = 0; i < mesh.elements.size(); ++i)
  {
    const auto& e = mesh.elements[i];
    vtkIdType ids[8];
    const int n = NodeCount(e.type);
    for (int k = 0; k < n; ++k)
      ids[k] = e.nodes[k];
    grid->InsertNextCell(static_cast<int>(e.type), n, ids);
    layers->SetValue(static_cast<vtkIdType>(i), static_cast<int>(e.layer));
  }
  grid->GetCellData()->AddArray(layers);

  if (mesh.HasMirrorMap())
    grid->GetPointData()->AddArray(IntArray(kMirrorArray, mesh.mirror));

  vtkFieldData* field = grid->GetFieldData();
  field->AddArray(IntArray(kPrefix + "Version", {1}));
  const auto nodeCount = static_cast<vtkIdType>(mesh.nodes.size());
  const auto elementCount = static_cast<vtkIdType>(mesh.elements.size());
  for (const auto& [name, ids] : mesh.nodeSets)
  {
    field->AddArray(IntArray(kPrefix + "NodeSet." + EncodeName(name), ids));
    grid->GetPointData()->AddArray(Mask("NodeSet." + EncodeName(name), nodeCount, ids));
  }
  for (const auto& [name, ids] : mesh.elementSets)
  {
    field->AddArray(IntArray(kPrefix + "ElementSet." + EncodeName(name), ids));
    grid->GetCellData()->AddArray(Mask("ElementSet." + EncodeName(name), elementCount, ids));
  }
  for (const auto& [name, muscle] : mesh.muscles)
  {
    const std::string base = kPrefix + "Muscle." + EncodeName(name) + ".";
    field->AddArray(IntArray(base + "Nodes", muscle.nodes));
    field->AddArray(IntArray(base + "Cables", muscle.cables));
    std::vector<std::int32_t> embeddingElements;
    vtkNew<vtkDoubleArray> pcoords;
    pcoords->SetName((base + "EmbeddingPCoords").c_str());
    pcoords->SetNumberOfComponents(3);
    pcoords->SetNumberOfTuples(static_cast<vtkIdType>(muscle.embedding.size()));
    for (std::size_t k = 0; k < muscle.embedding.size(); ++k)
    {
      embeddingElements.push_back(muscle.embedding[k].element);
      pcoords->SetTypedTuple(static_cast<vtkIdType>(k), muscle.embedding[k].pcoords.data());
    }
    field->AddArray(IntArray(base + "EmbeddingElements", embeddingElements));
    field->AddArray(pcoords);
    vtkNew<vtkDoubleArray> maximumForce;
    maximumForce->SetName((base + "MaximumForce").c_str());
    maximumForce->InsertNextValue(muscle.maximumForce);
    field->AddArray(maximumForce);
  }
  vtkNew<vtkStringArray> landmarkNames;
  landmarkNames->SetName((kPrefix + "LandmarkNames").c_str());
  vtkNew<vtkDoubleArray> landmarkPositions;
  landmarkPositions->SetName((kPrefix + "LandmarkPositions").c_str());
  landmarkPositions->SetNumberOfComponents(3);
  landmarkPositions->SetNumberOfTuples(static_cast<vtkIdType>(mesh.landmarks.size()));
  for (std::size_t k = 0; k < mesh.landmarks.size(); ++k)
  {
    landmarkNames->InsertNextValue(mesh.landmarks[k].name);
    landmarkPositions->SetTypedTuple(static_cast<vtkIdType>(k), mesh.landmarks[k].position.data());
  }
  if (!mesh.landmarks.empty())
  {
    field->AddArray(landmarkNames);
    field->AddArray(landmarkPositions);
  }
  return grid;
}

FEMesh FromVTK(vtkUnstructuredGrid* grid)
{
  if (!grid)
    throw std::runtime_error("no unstructured grid");
  FEMesh mesh;
  ReadNodes(grid, mesh);
  ReadElements(grid, mesh);

  vtkFieldData* field = grid->GetFieldData();
  struct EmbeddingArrays
  {
    std::vector<std::int32_t> elements;
    vtkDataArray* pcoords = nullptr;
  };
  std::map<std::string, EmbeddingArrays> embeddings;
  vtkAbstractArray* landmarkNames = nullptr;
  vtkDataArray* landmarkPositions = nullptr;
  for (int a = 0; field && a < field->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = field->GetAbstractArray(a);
    const std::string name = array && array->GetName() ? array->GetName() : "";
    if (!StartsWith(name, kPrefix))
      continue; // somebody else's data
    const std::string key = name.substr(kPrefix.size());
    if (key == "Version")
    {
      const auto version = ReadInts(array);
      if (version.size() != 1 || version[0] != 1)
        throw std::runtime_error("unsupported MMRep.Version (this build reads version 1)");
    }
    else if (StartsWith(key, "NodeSet."))
      mesh.nodeSets[DecodeName(key.substr(8))] = ReadInts(array);
    else if (StartsWith(key, "ElementSet."))
      mesh.elementSets[DecodeName(key.substr(11))] = ReadInts(array);
    else if (StartsWith(key, "Muscle."))
    {
      const auto dot = key.rfind('.');
      if (dot < 7) // "Muscle.<name>.<part>": the last dot must follow "Muscle."
        throw std::runtime_error("field data array '" + name + "' names no muscle part");
      const std::string muscle = DecodeName(key.substr(7, dot - 7));
      const std::string part = key.substr(dot + 1);
      if (part == "Nodes")
        mesh.muscles[muscle].nodes = ReadInts(array);
      else if (part == "Cables")
        mesh.muscles[muscle].cables = ReadInts(array);
      else if (part == "EmbeddingElements")
        embeddings[muscle].elements = ReadInts(array);
      else if (part == "EmbeddingPCoords")
        embeddings[muscle].pcoords = Vectors(array);
      else if (part == "MaximumForce")
      {
        auto* values = vtkDataArray::SafeDownCast(array);
        const double force = values && values->GetNumberOfValues() == 1 ? values->GetComponent(0, 0) : -1;
        if (!(force > 0 && std::isfinite(force)))
          throw std::runtime_error("field data array '" + name + "' must hold one positive force (N)");
        mesh.muscles[muscle].maximumForce = force;
      }
      else
        throw std::runtime_error("unknown muscle field data array '" + name + "'");
    }
    else if (key == "LandmarkNames")
      landmarkNames = array;
    else if (key == "LandmarkPositions")
      landmarkPositions = Vectors(array);
    else
      throw std::runtime_error("unknown MMRep field data array '" + name + "'");
  }

  for (const auto& [muscle, arrays] : embeddings)
  {
    const vtkIdType n = arrays.pcoords ? arrays.pcoords->GetNumberOfTuples() : 0;
    if (static_cast<vtkIdType>(arrays.elements.size()) != n || !mesh.muscles.count(muscle))
      throw std::runtime_error("muscle '" + muscle + "' has inconsistent embedding arrays");
    auto& embedding = mesh.muscles[muscle].embedding;
    embedding.resize(arrays.elements.size());
    for (vtkIdType k = 0; k < n; ++k)
    {
      embedding[static_cast<std::size_t>(k)].element = arrays.elements[static_cast<std::size_t>(k)];
      arrays.pcoords->GetTuple(k, embedding[static_cast<std::size_t>(k)].pcoords.data());
    }
  }

  ReadLandmarks(vtkStringArray::SafeDownCast(landmarkNames), landmarkNames, landmarkPositions, mesh);

  try
  {
    mesh.Validate();
  }
  catch (const std::invalid_argument& e)
  {
    throw std::runtime_error(std::string("inconsistent MMRep data: ") + e.what());
  }
  return mesh;
}

} // namespace mmrep
