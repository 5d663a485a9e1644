// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Slicer progress protocol on stdout, and the output scalars reported through --returnparameterfile.
#include "mmrepCLIInternal.h"
#include "mmrepModuleProcessInformation.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
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
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c == '\n' ? ' ' : c;
  }
  return out;
}

double Clamp01(double f)
{
  return f >= 0.0 ? std::min(f, 1.0) : 0.0;
} // NaN -> 0

double Seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Set by the signal handler, read by every Progress call (lock-free, so async-signal-safe).
std::atomic<int> interruptSignal{0};

extern "C" void OnInterrupt(int signal)
{
  interruptSignal.store(signal);
}

// Once a run has committed an output, it finishes: aborting then would leave a partial set.
std::atomic<bool> committed{false};
} // namespace

void detail::BeginRun()
{
  committed.store(false);
}
void detail::OutputCommitted()
{
  committed.store(true);
}

void InstallInterruptHandlers()
{
  struct sigaction action = {};
  action.sa_handler = OnInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND; // a second signal terminates at once
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void Progress::PollAbort() const
{
  if (std::this_thread::get_id() != owner_ || committed.load())
    return; // never unwind a worker thread
  if (const int signal = interruptSignal.load())
    throw Aborted{signal};
  if (information_ && *static_cast<volatile unsigned char*>(&information_->Abort))
    throw Aborted{0};
}

void Progress::Update(double overall, double stage)
{
  if (!information_)
    return;
  information_->Progress = static_cast<float>(overall);
  information_->StageProgress = static_cast<float>(stage);
  information_->ElapsedTime = Seconds() - startTime_;
  if (information_->ProgressCallbackFunction)
    information_->ProgressCallbackFunction(information_->ProgressCallbackClientData);
}

void Progress::Start(const std::string& comment)
{
  PollAbort();
  std::lock_guard<std::mutex> lock(mutex_);
  comment_ = comment.empty() ? "Running" : Escape(comment);
  std::cout << "<filter-start>\n<filter-name>" << comment_ << "</filter-name>\n<filter-comment>" << comment_
            << "</filter-comment>\n</filter-start>" << std::endl;
  startTime_ = Seconds();
  if (information_)
  {
    std::snprintf(information_->ProgressMessage, sizeof(information_->ProgressMessage), "%s", comment_.c_str());
    Update(0.0, 0.0);
  }
}

void Progress::Report(double fraction)
{
  ReportRange(0.0, 1.0, fraction);
}

void Progress::ReportRange(double from, double to, double fraction)
{
  PollAbort();
  const double overall = Clamp01(from + (to - from) * Clamp01(fraction));
  const int value = static_cast<int>(std::lround(overall * 1000.0));
  std::lock_guard<std::mutex> lock(mutex_);
  if (value <= last_)
    return; // never backwards, never twice
  last_ = value;
  std::cout << "<filter-progress>" << detail::FormatDouble(value / 1000.0) << "</filter-progress>" << std::endl;
  Update(value / 1000.0, Clamp01(fraction));
}

void Progress::Stage(const std::string& name)
{
  PollAbort();
  std::lock_guard<std::mutex> lock(mutex_);
  if (!information_)
    return;
  std::snprintf(information_->ProgressMessage, sizeof(information_->ProgressMessage), "%s", name.c_str());
  Update(std::max(last_, 0) / 1000.0, 0.0);
}

void Progress::End()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (comment_.empty())
    return; // not started, or already ended
  if (last_ < 1000)
    std::cout << "<filter-progress>1</filter-progress>\n";
  last_ = 1000;
  std::cout << "<filter-end>\n<filter-name>" << comment_ << "</filter-name>\n</filter-end>" << std::endl;
  comment_.clear();
  Update(1.0, 1.0);
}

void ReturnParameters::Set(const std::string& name, double value)
{
  values_[name] = detail::FormatDouble(value);
}

void ReturnParameters::Set(const std::string& name, long long value)
{
  values_[name] = std::to_string(value);
}

void ReturnParameters::Set(const std::string& name, const std::string& value)
{
  // One line per parameter in the return file.
  std::string v = value;
  for (char& c : v)
    if (c == '\n' || c == '\r')
      c = ' ';
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
