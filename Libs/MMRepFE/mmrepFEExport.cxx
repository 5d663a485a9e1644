// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepFEExport.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <stdexcept>

namespace mmrep::detail
{

std::string SanitizeName(const std::string& rawName)
{
  std::string name;
  for (unsigned char c : rawName)
    name += (std::isalnum(c) && c < 128) || c == '_' ? static_cast<char>(c) : '_';
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0])))
    name = "set_" + name;
  if (name.size() > 64)
    name.resize(64);
  return name;
}

std::string NameRegistry::Add(const std::string& rawName)
{
  const std::string base = SanitizeName(rawName);
  auto upper = [](std::string s) {
    for (auto& c : s)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  };
  std::string name = base;
  for (int k = 2; std::find(upperNames_.begin(), upperNames_.end(), upper(name)) != upperNames_.end(); ++k)
    name = base + "_" + std::to_string(k);
  upperNames_.push_back(upper(name));
  return name;
}

ExportNames MakeExportNames(const FEMesh& mesh)
{
  ExportNames names;
  NameRegistry nodeNames, elementNames;
  // Fixed names the writers use for all nodes / elements of one type (see mmrepAbaqusWriter.cxx).
  for (const char* reserved : {"NALL"})
    nodeNames.Add(reserved);
  for (const char* reserved : {"EHEX", "EWEDGE", "ETET", "ECABLE", "ESOLID"})
    elementNames.Add(reserved);
  // User sets first so they keep their names when a generated name would collide.
  for (const auto& entry : mesh.nodeSets)
    names.nodeSets.push_back(nodeNames.Add(entry.first));
  for (const auto& entry : mesh.elementSets)
    names.elementSets.push_back(elementNames.Add(entry.first));
  for (auto layer : {TissueLayer::None, TissueLayer::Epidermis, TissueLayer::Dermis, TissueLayer::Hypodermis})
    names.layers[static_cast<int>(layer)] = elementNames.Add(std::string("layer_") + TissueLayerName(layer));
  for (const auto& entry : mesh.muscles)
  {
    names.muscleNodes.push_back(nodeNames.Add("muscle_" + entry.first));
    names.muscles.push_back(elementNames.Add("muscle_" + entry.first));
  }
  return names;
}

std::vector<std::int32_t> SolverNodeOrder(const Element& element)
{
  const auto& n = element.nodes;
  if (element.type == ElementType::Wedge)
    return {n[0], n[2], n[1], n[3], n[5], n[4]};
  return std::vector<std::int32_t>(n.begin(), n.begin() + NodeCount(element.type));
}

std::string FormatDouble(double value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

void CheckWritable(const FEMesh& mesh, const std::string& path)
{
  if (mesh.Empty())
    throw std::runtime_error(path + ": cannot write an empty mesh (" + std::to_string(mesh.nodes.size()) + " nodes, " +
                             std::to_string(mesh.elements.size()) + " elements)");
  try
  {
    mesh.Validate();
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error(path + ": invalid mesh: " + e.what());
  }
}

} // namespace mmrep::detail
