// Slicer progress protocol on stdout, and the output scalars reported through --returnparameterfile.
#include "mmrepCLIInternal.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mmrep::cli
{
namespace
{
// Slicer parses these tags from the module's stdout; the text itself must not contain '<'.
std::string Escape(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c == '\n' ? ' ' : c;
  }
  return out;
}
} // namespace

void Progress::Start(const std::string& comment)
{
  std::lock_guard<std::mutex> lock(mutex_);
  comment_ = comment.empty() ? "Running" : Escape(comment);
  std::cout << "<filter-start>\n<filter-name>" << comment_ << "</filter-name>\n<filter-comment>" << comment_
            << "</filter-comment>\n</filter-start>" << std::endl;
}

void Progress::Report(double fraction)
{
  if (!(fraction >= 0.0)) // also catches NaN
    fraction = 0.0;
  const int value = static_cast<int>(std::lround(std::min(fraction, 1.0) * 1000.0));
  std::lock_guard<std::mutex> lock(mutex_);
  if (value <= last_) return; // never backwards, never twice
  last_ = value;
  std::cout << "<filter-progress>" << detail::FormatDouble(value / 1000.0) << "</filter-progress>" << std::endl;
}

void Progress::End()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (comment_.empty()) return; // not started, or already ended
  if (last_ < 1000) std::cout << "<filter-progress>1</filter-progress>\n";
  last_ = 1000;
  std::cout << "<filter-end>\n<filter-name>" << comment_ << "</filter-name>\n</filter-end>" << std::endl;
  comment_.clear();
}

void ReturnParameters::Set(const std::string& name, double value) { values_[name] = detail::FormatDouble(value); }

void ReturnParameters::Set(const std::string& name, long long value) { values_[name] = std::to_string(value); }

void ReturnParameters::Set(const std::string& name, const std::string& value)
{
  // One line per parameter in the return file.
  std::string v = value;
  for (char& c : v)
    if (c == '\n' || c == '\r') c = ' ';
  values_[name] = v;
}

void ReturnParameters::Set(const std::string& name, const std::vector<double>& value)
{
  std::string text;
  for (double v : value)
    text += (text.empty() ? "" : ",") + detail::FormatDouble(v);
  values_[name] = text;
}

} // namespace mmrep::cli
