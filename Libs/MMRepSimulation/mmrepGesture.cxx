// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Built-in speech gestures and gesture files.
#include "mmrepGesture.h"

#include "mmrepHalfModel.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <stdexcept>

namespace mmrep::simulation
{
namespace
{

struct Part
{
  const char* muscle; // without the side suffix
  double level;
};

struct Definition
{
  const char* name;
  std::vector<Part> muscles;
  double jawAngle;
};

const std::vector<Definition>& Definitions()
{
  static const std::vector<Definition> all{
    {"smile", {{"ZygomaticusMajor", 1.0}}, 0.0},
    {"round",
     {{"OrbicularisOrisPeripheralisUpper", 1.0},
      {"OrbicularisOrisPeripheralisLower", 1.0},
      {"OrbicularisOrisMarginalisUpper", 1.0},
      {"OrbicularisOrisMarginalisLower", 1.0}},
     0.0},
    {"open", {}, 10.0},
    {"close",
     {{"OrbicularisOrisMarginalisUpper", 0.6}, {"OrbicularisOrisMarginalisLower", 0.6}, {"Mentalis", 0.3}},
     0.0}};
  return all;
}

} // namespace

std::string GestureNames()
{
  std::string s;
  for (const auto& d : Definitions())
    s += (s.empty() ? "" : ", ") + std::string(d.name);
  return s;
}

Gesture BuiltInGesture(const std::string& name, const FEMesh& mesh)
{
  for (const auto& d : Definitions())
  {
    if (name != d.name)
      continue;
    Gesture g;
    g.name = d.name;
    g.jawAngle = d.jawAngle;
    const bool half = IsHalfModel(mesh);
    for (const auto& part : d.muscles)
      for (const char* side : {"_L", "_R"})
      {
        const std::string muscle = part.muscle + std::string(side);
        if (half && std::string(side) == "_R")
          continue;
        if (mesh.muscles.count(muscle) == 0)
          throw std::invalid_argument("gesture '" + name + "' needs muscle '" + muscle +
                                      "', which the model does not have");
        g.activations.push_back({muscle, part.level});
      }
    return g;
  }
  throw std::invalid_argument("unknown gesture '" + name + "'; the gestures are: " + GestureNames());
}

Gesture ReadGestureFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::invalid_argument("gesture file '" + path + "' cannot be read");
  Gesture g;
  try
  {
    // nlohmann keeps the last of two equal keys without a word: a duplicate is refused, naming it.
    std::vector<std::set<std::string>> objects;
    std::string duplicate;
    const nlohmann::json j =
      nlohmann::json::parse(in, [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        if (event == nlohmann::json::parse_event_t::object_start)
          objects.emplace_back();
        else if (event == nlohmann::json::parse_event_t::object_end && !objects.empty())
          objects.pop_back();
        else if (event == nlohmann::json::parse_event_t::key && !objects.empty() &&
                 !objects.back().insert(parsed.get<std::string>()).second && duplicate.empty())
          duplicate = parsed.get<std::string>();
        return true;
      });
    if (!duplicate.empty())
      throw std::invalid_argument("key '" + duplicate + "' is given twice (which one is meant?)");
    if (!j.is_object())
      throw std::invalid_argument("it is not a JSON object");
    for (auto it = j.begin(); it != j.end(); ++it)
      if (it.key() != "name" && it.key() != "muscles" && it.key() != "jawAngle")
        throw std::invalid_argument("unknown key '" + it.key() + "' (keys: name, muscles, jawAngle)");
    g.name = j.value("name", std::string("gesture"));
    if (j.contains("muscles"))
    {
      if (!j.at("muscles").is_object())
        throw std::invalid_argument("'muscles' must map muscle names to activation levels");
      for (auto it = j.at("muscles").begin(); it != j.at("muscles").end(); ++it)
      {
        if (!it.value().is_number())
          throw std::invalid_argument("the activation of '" + it.key() + "' is not a number");
        g.activations.push_back({it.key(), it.value().get<double>()});
      }
    }
    if (j.contains("jawAngle"))
    {
      if (!j.at("jawAngle").is_number())
        throw std::invalid_argument("'jawAngle' is not a number (degrees)");
      g.jawAngle = j.at("jawAngle").get<double>();
    }
  }
  catch (const nlohmann::json::exception& e)
  {
    throw std::invalid_argument("gesture file '" + path + "' is not valid JSON (" + std::string(e.what()) + ")");
  }
  catch (const std::invalid_argument& e)
  {
    throw std::invalid_argument("gesture file '" + path + "': " + e.what());
  }
  if (g.activations.empty() && g.jawAngle == 0)
    throw std::invalid_argument("gesture file '" + path + "' activates no muscle and opens no jaw");
  return g;
}

} // namespace mmrep::simulation
