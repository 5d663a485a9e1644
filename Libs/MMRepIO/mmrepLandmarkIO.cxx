// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Slicer point lists: markups JSON (.mrk.json, schema v1.0) and the legacy CSV format (.fcsv).
#include "mmrepLandmarkIO.h"

#include "mmrepIOPath.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{

const char* const kSchema =
  "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/"
  "markups-schema-v1.0.3.json#";

[[noreturn]] void Fail(const std::string& path, const std::string& what)
{
  throw std::runtime_error("'" + path + "': " + what);
}

// LPS <-> RAS is the same sign flip of the first two axes in both directions.
Point3 Convert(const Point3& p, CoordinateSystem from, CoordinateSystem to)
{
  return from == to ? p : Point3(-p.x(), -p.y(), p.z());
}

std::string FormatNumber(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof(buffer), "%.17g", v);
  return buffer;
}

// ---- markups JSON ----------------------------------------------------------------------------

// The markup's "coordinateUnits" (Slicer writes "mm", or "um" for microscopy; the schema also
// allows one unit per axis): the factor to millimetres. Other units are refused, never ignored.
double MillimetresPerUnit(const std::string& path, const nlohmann::json& markup)
{
  if (!markup.contains("coordinateUnits"))
    return 1.0;
  std::vector<std::string> units;
  const nlohmann::json& u = markup["coordinateUnits"];
  if (u.is_string())
    units.push_back(u.get<std::string>());
  else if (u.is_array())
    for (const auto& axis : u)
      units.push_back(axis.is_string() ? axis.get<std::string>() : std::string("?"));
  else
    Fail(path, "coordinateUnits is neither a unit nor a list of units");
  double factor = 0;
  for (const std::string& unit : units)
  {
    double f = 0;
    if (unit == "mm" || unit.empty())
      f = 1.0;
    else if (unit == "um" || unit == "\u00b5m" || unit == "\u03bcm")
      f = 1e-3;
    else if (unit == "cm")
      f = 10.0;
    else if (unit == "m")
      f = 1e3;
    else
      Fail(path, "unsupported coordinateUnits '" + unit + "' (expected mm, um, cm or m)");
    if (factor != 0 && f != factor)
      Fail(path, "coordinateUnits differ between the axes");
    factor = f;
  }
  return factor == 0 ? 1.0 : factor;
}

std::vector<Landmark> ReadMarkupsJson(const std::string& path, std::istream& in)
{
  nlohmann::json doc;
  try
  {
    in >> doc;
  }
  catch (const nlohmann::json::exception& e)
  {
    Fail(path, std::string("invalid JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("markups") || !doc["markups"].is_array() || doc["markups"].empty())
  {
    Fail(path, "not a Slicer markups file (no \"markups\" array)");
  }
  std::vector<Landmark> landmarks;
  try
  {
    // Every point-list markup contributes its points, in file order.
    for (const nlohmann::json& markup : doc["markups"])
    {
      CoordinateSystem system = CoordinateSystem::LPS; // the schema's default
      if (markup.contains("coordinateSystem"))
      {
        const std::string name = markup["coordinateSystem"].get<std::string>();
        if (name == "RAS")
        {
          system = CoordinateSystem::RAS;
        }
        else if (name != "LPS")
        {
          Fail(path, "unsupported coordinateSystem '" + name + "' (expected LPS or RAS)");
        }
      }
      if (!markup.contains("controlPoints"))
      {
        continue;
      }
      const double toMillimetres = MillimetresPerUnit(path, markup);
      int index = 0;
      for (const nlohmann::json& cp : markup["controlPoints"])
      {
        ++index;
        const std::string label = cp.value("label", std::string());
        const std::string which = label.empty() ? std::to_string(index) : "'" + label + "'";
        // Points placed as "missing" in Slicer have no position: they are not landmarks. A point
        // "undefined" or still in "preview" has a position that nobody placed: it is refused.
        const std::string status = cp.value("positionStatus", std::string("defined"));
        if (status == "missing")
        {
          continue;
        }
        if (status != "defined")
        {
          Fail(path, "control point " + which + " is not placed (positionStatus '" + status +
                       "'): place it in Slicer, or mark it missing");
        }
        if (!cp.contains("position") || !cp["position"].is_array() || cp["position"].size() != 3)
        {
          Fail(path, "control point " + which + " has no 3-component position");
        }
        Landmark lm;
        lm.name = label;
        const Point3 p(cp["position"][0].get<double>(), cp["position"][1].get<double>(),
                       cp["position"][2].get<double>());
        lm.position = Convert(toMillimetres * p, system, CoordinateSystem::LPS);
        landmarks.push_back(lm);
      }
    }
  }
  catch (const nlohmann::json::exception& e)
  {
    Fail(path, std::string("malformed markups content: ") + e.what());
  }
  return landmarks;
}

void WriteMarkupsJson(const std::vector<Landmark>& landmarks, std::ostream& out, CoordinateSystem system)
{
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < landmarks.size(); ++i)
  {
    const Point3 p = Convert(landmarks[i].position, CoordinateSystem::LPS, system);
    nlohmann::ordered_json cp;
    cp["id"] = std::to_string(i + 1);
    cp["label"] = landmarks[i].name;
    cp["description"] = "";
    cp["associatedNodeID"] = "";
    cp["position"] = {p.x(), p.y(), p.z()};
    cp["orientation"] = {-1.0, -0.0, -0.0, -0.0, -1.0, -0.0, 0.0, 0.0, 1.0};
    cp["selected"] = true;
    cp["locked"] = false;
    cp["visibility"] = true;
    cp["positionStatus"] = "defined";
    points.push_back(cp);
  }
  nlohmann::ordered_json markup;
  markup["type"] = "Fiducial";
  markup["coordinateSystem"] = system == CoordinateSystem::LPS ? "LPS" : "RAS";
  markup["coordinateUnits"] = "mm";
  markup["locked"] = false;
  markup["fixedNumberOfControlPoints"] = false;
  markup["labelFormat"] = "%N-%d";
  markup["lastUsedControlPointNumber"] = landmarks.size();
  markup["controlPoints"] = points;
  markup["measurements"] = nlohmann::ordered_json::array();

  nlohmann::ordered_json doc;
  doc["@schema"] = kSchema;
  doc["markups"] = nlohmann::ordered_json::array({markup});
  out << doc.dump(4) << "\n";
}

// ---- legacy .fcsv ----------------------------------------------------------------------------

// Splits one CSV line; Slicer double-quotes fields that contain commas or quotes.
std::vector<std::string> SplitCsv(const std::string& line)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (quoted)
    {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      {
        fields.back() += '"';
        ++i;
      }
      else if (c == '"')
      {
        quoted = false;
      }
      else
      {
        fields.back() += c;
      }
    }
    else if (c == '"')
    {
      quoted = true;
    }
    else if (c == ',')
    {
      fields.emplace_back();
    }
    else if (c != '\r')
    {
      fields.back() += c;
    }
  }
  return fields;
}

std::string QuoteCsv(const std::string& field)
{
  if (field.find_first_of(",\"\n") == std::string::npos)
  {
    return field;
  }
  std::string quoted = "\"";
  for (char c : field)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

std::string Trim(const std::string& s)
{
  const std::size_t b = s.find_first_not_of(" \t\r");
  const std::size_t e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<Landmark> ReadFcsv(const std::string& path, std::istream& in)
{
  // Files written before Slicer 4.11 have no (or a numeric) coordinate system and are RAS.
  CoordinateSystem system = CoordinateSystem::RAS;
  std::vector<std::string> columns = {"id", "x", "y", "z", "ow", "ox", "oy", "oz", "vis", "sel", "lock", "label"};
  std::vector<Landmark> landmarks;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (Trim(line).empty())
    {
      continue;
    }
    if (line[0] == '#')
    {
      const std::size_t eq = line.find('=');
      if (eq == std::string::npos)
      {
        continue;
      }
      const std::string key = Trim(line.substr(1, eq - 1));
      const std::string value = Trim(line.substr(eq + 1));
      if (key == "CoordinateSystem")
      {
        // vtkMRMLStorageNode numbering: 0 = RAS, 1 = LPS.
        if (value == "LPS" || value == "1")
        {
          system = CoordinateSystem::LPS;
        }
        else if (value == "RAS" || value == "0")
        {
          system = CoordinateSystem::RAS;
        }
        else
        {
          Fail(path, "unsupported CoordinateSystem '" + value + "' (expected LPS, RAS, 0 or 1)");
        }
      }
      else if (key == "columns")
      {
        columns = SplitCsv(value);
        for (std::string& c : columns)
        {
          c = Trim(c);
        }
      }
      continue;
    }
    auto column = [&](const char* name) -> int {
      for (std::size_t i = 0; i < columns.size(); ++i)
      {
        if (columns[i] == name)
        {
          return static_cast<int>(i);
        }
      }
      return -1;
    };
    const int cx = column("x"), cy = column("y"), cz = column("z"), cl = column("label");
    if (cx < 0 || cy < 0 || cz < 0)
    {
      Fail(path, "the columns header has no x, y, z");
    }
    const std::vector<std::string> fields = SplitCsv(line);
    double xyz[3];
    const int cols[3] = {cx, cy, cz};
    for (int a = 0; a < 3; ++a)
    {
      std::size_t used = 0;
      const std::string text = cols[a] < static_cast<int>(fields.size()) ? Trim(fields[cols[a]]) : std::string();
      try
      {
        xyz[a] = std::stod(text, &used);
      }
      catch (const std::exception&)
      {
        used = 0;
      }
      if (text.empty() || used != text.size())
      {
        Fail(path, "line " + std::to_string(lineNumber) + ": invalid coordinate '" + text + "'");
      }
    }
    Landmark lm;
    lm.name = cl >= 0 && cl < static_cast<int>(fields.size()) ? fields[cl] : std::string();
    lm.position = Convert(Point3(xyz[0], xyz[1], xyz[2]), system, CoordinateSystem::LPS);
    landmarks.push_back(lm);
  }
  return landmarks;
}

void WriteFcsv(const std::vector<Landmark>& landmarks, std::ostream& out, CoordinateSystem system)
{
  out << "# Markups fiducial file version = 4.11\n";
  out << "# CoordinateSystem = " << (system == CoordinateSystem::LPS ? "LPS" : "RAS") << "\n";
  out << "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n";
  for (std::size_t i = 0; i < landmarks.size(); ++i)
  {
    const Point3 p = Convert(landmarks[i].position, CoordinateSystem::LPS, system);
    out << (i + 1) << "," << FormatNumber(p.x()) << "," << FormatNumber(p.y()) << "," << FormatNumber(p.z())
        << ",0,0,0,1,1,1,0," << QuoteCsv(landmarks[i].name) << ",,\n";
  }
}

std::string FormatOf(const std::string& path)
{
  if (io::EndsWith(path, ".fcsv"))
  {
    return "fcsv";
  }
  if (io::EndsWith(path, ".json")) // .mrk.json (also the temporaries that keep only .json)
  {
    return "mrk.json";
  }
  return {};
}

} // namespace

std::vector<Landmark> ReadLandmarks(const std::string& path)
{
  const std::string format = FormatOf(path);
  if (format.empty())
  {
    Fail(path, "unknown landmark file extension (supported: .mrk.json, .fcsv)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    Fail(path, "cannot open landmark file (missing or unreadable)");
  }
  return format == "fcsv" ? ReadFcsv(path, in) : ReadMarkupsJson(path, in);
}

void WriteLandmarks(const std::vector<Landmark>& landmarks, const std::string& path, CoordinateSystem system)
{
  const std::string format = FormatOf(path);
  if (format.empty())
  {
    Fail(path, "unknown landmark file extension (supported: .mrk.json, .fcsv)");
  }
  WriteLandmarks(landmarks, path, format, system);
}

void WriteLandmarks(const std::vector<Landmark>& landmarks, const std::string& path, const std::string& format,
                    CoordinateSystem system)
{
  const std::string f = io::Lower(format);
  if (f != "fcsv" && f != "mrk.json" && f != "json")
  {
    throw std::invalid_argument("WriteLandmarks: unknown format '" + format + "' for '" + path +
                                "' (expected mrk.json or fcsv)");
  }
  std::ostringstream text;
  if (f == "fcsv")
  {
    WriteFcsv(landmarks, text, system);
  }
  else
  {
    WriteMarkupsJson(landmarks, text, system);
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text.str();
  out.close();
  if (!out)
  {
    std::remove(path.c_str());
    Fail(path, "cannot write landmark file");
  }
}

} // namespace mmrep
