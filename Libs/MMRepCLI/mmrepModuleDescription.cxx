// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Reads a Slicer Execution Model <executable> description (ModuleDescription.xsd) with VTK's XML parser.
#include "mmrepCLIInternal.h"

#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <expat.h>

#include <set>
#include <sstream>

namespace mmrep::cli
{
namespace
{
using detail::Lower;
using detail::Trim;

// Keeps XML syntax errors as a message instead of printing them through vtkOutputWindow.
class QuietXMLParser : public vtkXMLDataParser
{
public:
  static QuietXMLParser* New();
  vtkTypeMacro(QuietXMLParser, vtkXMLDataParser);
  std::string error;

protected:
  void ReportXmlParseError() override
  {
    auto* parser = static_cast<XML_Parser>(this->Parser);
    error =
      "line " + std::to_string(XML_GetCurrentLineNumber(parser)) + ": " + XML_ErrorString(XML_GetErrorCode(parser));
  }
};
vtkStandardNewMacro(QuietXMLParser);

std::string Text(vtkXMLDataElement* e)
{
  return e && e->GetCharacterData() ? Trim(e->GetCharacterData()) : std::string();
}

std::string ChildText(vtkXMLDataElement* e, const char* name)
{
  return Text(e->FindNestedElementWithName(name));
}

std::string Attribute(vtkXMLDataElement* e, const char* name)
{
  const char* v = e->GetAttribute(name);
  return v ? Trim(v) : std::string();
}

std::string StripDashes(std::string flag)
{
  flag.erase(0, flag.find_first_not_of('-'));
  return flag;
}

Parameter ReadParameter(vtkXMLDataElement* e)
{
  Parameter p;
  p.tag = e->GetName();
  p.multiple = Lower(Attribute(e, "multiple")) == "true";
  p.coordinateSystem = Lower(Attribute(e, "coordinateSystem"));
  if (p.coordinateSystem.empty() && (p.tag == "point" || p.tag == "pointfile" || p.tag == "region"))
    p.coordinateSystem = "ras"; // Slicer's default
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* c = e->GetNestedElement(i);
    const std::string n = c->GetName();
    if (n == "name")
      p.name = Text(c);
    else if (n == "flag")
      p.flag = StripDashes(Text(c));
    else if (n == "longflag")
      p.longflag = StripDashes(Text(c));
    else if (n == "channel")
      p.channel = Text(c);
    else if (n == "label")
      p.label = Text(c);
    else if (n == "description")
      p.description = Text(c);
    else if (n == "default")
      p.defaultValue = Text(c);
    else if (n == "element")
      p.elements.push_back(Text(c));
    else if (n == "constraints")
    {
      p.minimum = ChildText(c, "minimum");
      p.maximum = ChildText(c, "maximum");
    }
    else if (n == "index")
    {
      long long index = -1;
      if (!detail::ParseInt(Text(c), index) || index < 0)
        throw ModuleError("parameter '" + p.name + "': <index> must be a non-negative integer");
      p.index = static_cast<int>(index);
    }
  }
  if (p.name.empty())
    throw ModuleError("a <" + p.tag + "> parameter has no <name>");
  if (p.flag.size() > 1)
    throw ModuleError("parameter '" + p.name + "': <flag> must be a single character");
  return p;
}
} // namespace

bool Parameter::IsReturnValue() const
{
  static const std::set<std::string> files = {"file",      "directory", "image",     "geometry",
                                              "transform", "table",     "pointfile", "measurement"};
  // The project's schema allows no <channel> on scalars, so "not an input" is enough.
  return channel != "input" && flag.empty() && longflag.empty() && index < 0 && !files.count(tag);
}

ModuleDescription ModuleDescription::FromXML(const std::string& xml)
{
  std::istringstream stream(xml);
  vtkNew<QuietXMLParser> parser;
  parser->SetStream(&stream);
  if (!parser->Parse() || !parser->GetRootElement())
    throw ModuleError("malformed XML description: " +
                      (parser->error.empty() ? std::string("no root element") : parser->error));
  vtkXMLDataElement* root = parser->GetRootElement();
  if (std::string(root->GetName()) != "executable")
    throw ModuleError("XML description: root element is <" + std::string(root->GetName()) + ">, expected <executable>");

  ModuleDescription d;
  d.category = ChildText(root, "category");
  d.title = ChildText(root, "title");
  d.description = ChildText(root, "description");
  d.version = ChildText(root, "version");
  d.license = ChildText(root, "license");
  d.contributor = ChildText(root, "contributor");
  std::set<std::string> names;
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement* group = root->GetNestedElement(g);
    if (std::string(group->GetName()) != "parameters")
      continue;
    for (int i = 0; i < group->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* e = group->GetNestedElement(i);
      const std::string tag = e->GetName();
      if (tag == "label" || tag == "description") // the group's own label/description
        continue;
      Parameter p = ReadParameter(e);
      if (!names.insert(p.name).second)
        throw ModuleError("XML description: parameter '" + p.name + "' is declared twice");
      d.parameters.push_back(std::move(p));
    }
  }
  return d;
}

const Parameter* ModuleDescription::Find(const std::string& name) const
{
  for (const Parameter& p : parameters)
    if (p.name == name)
      return &p;
  return nullptr;
}

} // namespace mmrep::cli
