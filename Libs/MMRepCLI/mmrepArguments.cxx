// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Typed, validated access to the values given on the command line (or the <default>s).
#include "mmrepCLIInternal.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace mmrep::cli
{
namespace detail
{

std::string Trim(std::string_view text)
{
  const auto b = text.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos)
    return {};
  const auto e = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(b, e - b + 1));
}

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::vector<std::string> SplitComma(const std::string& text)
{
  std::vector<std::string> items;
  if (Trim(text).empty())
    return items;
  std::string::size_type start = 0;
  for (;;)
  {
    const auto comma = text.find(',', start);
    items.push_back(Trim(std::string_view(text).substr(start, comma - start)));
    if (comma == std::string::npos)
      return items;
    start = comma + 1;
  }
}

// from_chars rejects a leading '+', which command lines commonly contain.
template <typename T> bool ParseNumber(const std::string& text, T& value)
{
  std::string_view s = text;
  if (s.size() > 1 && s[0] == '+' && s[1] != '-')
    s.remove_prefix(1);
  if (s.empty())
    return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

bool ParseInt(const std::string& text, long long& value)
{
  return ParseNumber(text, value);
}

bool ParseDouble(const std::string& text, double& value)
{
  return ParseNumber(text, value) && std::isfinite(value);
}

bool ParseBool(const std::string& text, bool& value)
{
  const std::string t = Lower(Trim(text));
  if (t == "true" || t == "1" || t == "yes" || t == "on")
    return value = true, true;
  if (t == "false" || t == "0" || t == "no" || t == "off")
    return value = false, true;
  return false;
}

std::string FormatDouble(double value)
{
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, end);
}

std::string Describe(const Parameter& p)
{
  std::string d = "'" + p.name + "'";
  if (!p.longflag.empty())
    d += " (--" + p.longflag + ")";
  else if (!p.flag.empty())
    d += " (-" + p.flag + ")";
  else if (p.index >= 0)
    d += " (argument " + std::to_string(p.index + 1) + ")";
  return d;
}

namespace
{
bool StartsWith(const std::string& s, const char* prefix)
{
  return s.rfind(prefix, 0) == 0;
}

// Number of comma-separated components a value of this type has; 0 = any count, -1 = not split.
int Components(const std::string& tag)
{
  if (tag == "point")
    return 3;
  if (tag == "region")
    return 6;
  if (tag.size() > 7 && tag.compare(tag.size() - 7, 7, "-vector") == 0)
    return 0;
  return -1;
}

void CheckNumber(const Parameter& p, const std::string& item, bool integer)
{
  const std::string what = "parameter " + Describe(p) + ": '" + item + "' is not ";
  double v = 0;
  if (integer)
  {
    long long i = 0;
    if (!ParseInt(item, i))
      throw ModuleError(what + "an integer");
    v = static_cast<double>(i);
  }
  else if (!ParseDouble(item, v))
    throw ModuleError(what + "a number");
  double bound = 0;
  if (ParseDouble(p.minimum, bound) && v < bound)
    throw ModuleError("parameter " + Describe(p) + ": " + item + " is below the minimum " + p.minimum);
  if (ParseDouble(p.maximum, bound) && v > bound)
    throw ModuleError("parameter " + Describe(p) + ": " + item + " is above the maximum " + p.maximum);
}

bool InEnumeration(const Parameter& p, const std::string& value)
{
  double v = 0, e = 0;
  const bool numeric = !StartsWith(p.tag, "string") && ParseDouble(value, v);
  for (const std::string& element : p.elements)
    if (element == value || (numeric && ParseDouble(element, e) && e == v))
      return true;
  return false;
}
} // namespace

void Validate(const Parameter& p, const std::vector<std::string>& values)
{
  if (values.size() > 1 && !p.multiple)
    throw ModuleError("parameter " + Describe(p) + " given more than once");
  const bool integer = StartsWith(p.tag, "integer");
  const bool number =
    integer || StartsWith(p.tag, "float") || StartsWith(p.tag, "double") || p.tag == "point" || p.tag == "region";
  for (const std::string& value : values)
  {
    if (p.tag.size() > 12 && p.tag.compare(p.tag.size() - 12, 12, "-enumeration") == 0)
    {
      if (!InEnumeration(p, value))
      {
        std::string allowed;
        for (const std::string& e : p.elements)
          allowed += (allowed.empty() ? "" : ", ") + e;
        throw ModuleError("parameter " + Describe(p) + ": '" + value + "' is not one of " + allowed);
      }
      if (number)
        CheckNumber(p, value, integer);
      continue;
    }
    if (p.tag == "boolean")
    {
      bool b = false;
      if (!ParseBool(value, b))
        throw ModuleError("parameter " + Describe(p) + ": '" + value + "' is not true or false");
      continue;
    }
    const int components = Components(p.tag);
    const std::vector<std::string> items = components < 0 ? std::vector<std::string>{value} : SplitComma(value);
    if (components > 0 && static_cast<int>(items.size()) != components)
      throw ModuleError("parameter " + Describe(p) + ": '" + value + "' must have " + std::to_string(components) +
                        " comma-separated numbers");
    if (number)
      for (const std::string& item : items)
        CheckNumber(p, item, integer);
  }
}
} // namespace detail

Arguments::Arguments(const ModuleDescription& description, std::map<std::string, std::vector<std::string>> values)
    : description_(&description), values_(std::move(values))
{
  for (const auto& [name, given] : values_)
    detail::Validate(Declared(name), given);
}

const Parameter& Arguments::Declared(const std::string& name) const
{
  const Parameter* p = description_ ? description_->Find(name) : nullptr;
  if (!p)
    throw ModuleError("parameter '" + name + "' is not declared in the module description");
  return *p;
}

bool Arguments::Given(const std::string& name) const
{
  Declared(name);
  const auto it = values_.find(name);
  return it != values_.end() && !it->second.empty();
}

bool Arguments::Has(const std::string& name) const
{
  return Given(name) || !Declared(name).defaultValue.empty();
}

namespace
{
// The given values, else the default as a single value; throws when there is neither.
std::vector<std::string> Raw(const Parameter& p, const std::map<std::string, std::vector<std::string>>& values)
{
  const auto it = values.find(p.name);
  if (it != values.end() && !it->second.empty())
    return it->second;
  if (!p.defaultValue.empty())
    return {p.defaultValue};
  throw ModuleError("parameter " + detail::Describe(p) + " is required but was not given");
}
} // namespace

std::string Arguments::String(const std::string& name) const
{
  return Raw(Declared(name), values_).front();
}

long long Arguments::Int(const std::string& name) const
{
  const Parameter& p = Declared(name);
  long long v = 0;
  const std::string text = Raw(p, values_).front();
  if (!detail::ParseInt(text, v))
    throw ModuleError("parameter " + detail::Describe(p) + ": '" + text + "' is not an integer");
  return v;
}

double Arguments::Double(const std::string& name) const
{
  const Parameter& p = Declared(name);
  double v = 0;
  const std::string text = Raw(p, values_).front();
  if (!detail::ParseDouble(text, v))
    throw ModuleError("parameter " + detail::Describe(p) + ": '" + text + "' is not a number");
  return v;
}

bool Arguments::Bool(const std::string& name) const
{
  const Parameter& p = Declared(name);
  if (!Has(name))
    return false; // an unset switch
  bool v = false;
  const std::string text = Raw(p, values_).front();
  if (!detail::ParseBool(text, v))
    throw ModuleError("parameter " + detail::Describe(p) + ": '" + text + "' is not true or false");
  return v;
}

std::vector<std::string> Arguments::Strings(const std::string& name) const
{
  const Parameter& p = Declared(name);
  if (!Has(name))
    return {};
  std::vector<std::string> result;
  for (const std::string& value : Raw(p, values_))
  {
    if (p.tag == "string-vector")
      for (std::string& item : detail::SplitComma(value))
        result.push_back(std::move(item));
    else
      result.push_back(value);
  }
  return result;
}

std::vector<double> Arguments::Doubles(const std::string& name) const
{
  const Parameter& p = Declared(name);
  if (!Has(name))
    return {};
  std::vector<double> result;
  for (const std::string& value : Raw(p, values_))
    for (const std::string& item : detail::SplitComma(value))
    {
      double v = 0;
      if (!detail::ParseDouble(item, v))
        throw ModuleError("parameter " + detail::Describe(p) + ": '" + item + "' is not a number");
      result.push_back(v);
    }
  return result;
}

std::vector<long long> Arguments::Ints(const std::string& name) const
{
  const Parameter& p = Declared(name);
  if (!Has(name))
    return {};
  std::vector<long long> result;
  for (const std::string& value : Raw(p, values_))
    for (const std::string& item : detail::SplitComma(value))
    {
      long long v = 0;
      if (!detail::ParseInt(item, v))
        throw ModuleError("parameter " + detail::Describe(p) + ": '" + item + "' is not an integer");
      result.push_back(v);
    }
  return result;
}

std::vector<std::array<double, 3>> Arguments::PointsLPS(const std::string& name) const
{
  const Parameter& p = Declared(name);
  if (p.tag != "point")
    throw ModuleError("parameter " + detail::Describe(p) + " is a <" + p.tag + ">, not a <point>");
  if (p.coordinateSystem != "ras" && p.coordinateSystem != "lps")
    throw ModuleError("parameter " + detail::Describe(p) + ": coordinateSystem '" + p.coordinateSystem +
                      "' is not supported (use ras or lps)");
  std::vector<std::array<double, 3>> points;
  if (!Has(name))
    return points;
  // Slicer's RAS and the toolkit's LPS differ by the sign of the first two axes.
  const double sign = p.coordinateSystem == "ras" ? -1.0 : 1.0;
  for (const std::string& value : Raw(p, values_))
  {
    const std::vector<std::string> items = detail::SplitComma(value);
    std::array<double, 3> x{};
    if (items.size() != 3 || !detail::ParseDouble(items[0], x[0]) || !detail::ParseDouble(items[1], x[1]) ||
        !detail::ParseDouble(items[2], x[2]))
      throw ModuleError("parameter " + detail::Describe(p) + ": '" + value + "' is not a point x,y,z");
    points.push_back({sign * x[0] + 0.0, sign * x[1] + 0.0, x[2]}); // + 0.0: no "-0"
  }
  return points;
}

} // namespace mmrep::cli
