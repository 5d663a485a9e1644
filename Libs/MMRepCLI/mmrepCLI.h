// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MMRep command-line framework: runs a Slicer Execution Model CLI module from its XML description.
//
// The module's .xml (compiled in by mmrep_add_cli_module) is the single source of truth: flags,
// long flags, indexed arguments, types, defaults and enumerations are all read from it.
// A module writes only its science:
//
//   extern const char MeshQualityXML[];
//   MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
//   {
//     return mmrep::cli::RunModule(argc, argv, MeshQualityXML, [](mmrep::cli::ModuleContext& ctx) {
//       const auto in = ctx.args.String("inputMesh");
//       ctx.progress.Start("Computing quality");
//       ... ctx.progress.Report(0.5); ...
//       mmrep::cli::AtomicOutput out(ctx.args.String("outputMesh"));
//       Write(mesh, out.TempPath());
//       out.Commit();
//       ctx.outputs.Set("minScaledJacobian", 0.42);
//     });
//   }
//
// Behaviour shared by every module:
//   --xml                     prints the description verbatim and exits 0;
//   --help / -h               usage generated from the description;
//   --returnparameterfile F   output-channel scalars written as `name = value` lines on success;
//   --processinformationaddress A  Slicer's in-process ModuleProcessInformation block (see
//                             mmrepModuleProcessInformation.h): progress, stage progress and message
//                             written, its callback called, its Abort flag polled;
//   progress on stdout: <filter-start>…</filter-start>, <filter-progress>0.42</filter-progress>,
//   <filter-end>…</filter-end>, as Slicer parses them;
//   errors: one line on stderr "<Module>: error: <what>", exit code 1 (2 for command-line errors);
//   abort (Slicer's Abort flag, or SIGINT/SIGTERM in the executables): every Progress call polls it and
//   throws Aborted, the module's outputs are never committed, exit code 1 (128 + signal number).
#pragma once

#include <array>
#include <functional>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

struct ModuleProcessInformation; // Slicer's layout, mmrepModuleProcessInformation.h

// Defines the module's Slicer entry point with C linkage, exported from the module's shared library:
//   extern const char MeshQualityXML[];                       // generated from MeshQuality.xml
//   MMREP_MODULE_ENTRY_POINT(int argc, char* argv[]) { return mmrep::cli::RunModule(argc, argv, MeshQualityXML, …); }
#define MMREP_MODULE_ENTRY_POINT extern "C" __attribute__((visibility("default"))) int ModuleEntryPoint

namespace mmrep::cli
{

// A user-facing error (bad file, bad value): reported as one line, never a crash.
class ModuleError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// Runs f and returns its result, turning a library's std::exception into a one-line ModuleError
// (its message after `prefix`); ModuleErrors pass through.
template <typename F> auto AsModuleError(F&& f, const std::string& prefix = "")
{
  try
  {
    return f();
  }
  catch (const ModuleError&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    throw ModuleError(prefix + e.what());
  }
}

// Thrown by Progress when the run is to stop (Slicer's Abort, SIGINT, SIGTERM). Deliberately not a
// std::exception, so the library code's `catch (const std::exception&)` never swallows it.
struct Aborted
{
  int signal = 0; // the signal that asked for it, 0 for Slicer's Abort flag
};

// Executables only (never inside Slicer's process): SIGINT and SIGTERM request an abort, which the
// next Progress call on the module's thread turns into Aborted; a second signal kills at once.
void InstallInterruptHandlers();

// One <parameter> of the description (integer, double, file, image, geometry, point, …).
struct Parameter
{
  std::string tag;      // XML element name: integer, float, double, boolean, string, file, …
  std::string name;     // <name>
  std::string flag;     // <flag> without '-', may be empty
  std::string longflag; // <longflag> without '--', may be empty
  int index = -1;       // <index> for positional arguments, -1 otherwise
  std::string channel;  // input / output / empty
  std::string label;
  std::string description;
  std::string defaultValue;          // <default>, empty when none
  std::vector<std::string> elements; // <element> of *-enumeration
  std::string coordinateSystem;      // point/pointfile attribute: "lps" or "ras" (Slicer default ras)
  bool multiple = false;             // multiple="true"
  std::string minimum, maximum;      // <constraints>
  bool IsReturnValue() const;        // output scalar without flag/index → return parameter file
};

// The parsed <executable> description.
struct ModuleDescription
{
  std::string category, title, description, version, license, contributor;
  std::vector<Parameter> parameters;

  static ModuleDescription FromXML(const std::string& xml); // throws ModuleError on malformed XML
  const Parameter* Find(const std::string& name) const;     // nullptr when absent
};

// Values given on the command line (or defaults), validated against their declared types.
class Arguments
{
public:
  Arguments() = default;
  Arguments(const ModuleDescription& description, std::map<std::string, std::vector<std::string>> values);

  bool Has(const std::string& name) const;   // given, or has a default
  bool Given(const std::string& name) const; // given explicitly on the command line
  std::string String(const std::string& name) const;
  long long Int(const std::string& name) const;
  double Double(const std::string& name) const;
  bool Bool(const std::string& name) const;
  std::vector<double> Doubles(const std::string& name) const; // integer-/float-/double-vector
  std::vector<long long> Ints(const std::string& name) const;
  std::vector<std::string> Strings(const std::string& name) const; // string-vector or multiple
  // <point> parameters (possibly multiple), converted to LPS whatever their coordinateSystem.
  std::vector<std::array<double, 3>> PointsLPS(const std::string& name) const;

private:
  const Parameter& Declared(const std::string& name) const;
  const ModuleDescription* description_ = nullptr;
  std::map<std::string, std::vector<std::string>> values_;
};

// Slicer-style progress reporting on stdout, and in Slicer's ModuleProcessInformation block when
// one is given. Thread-safe; fractions are clamped to [0,1] and never go backwards; repeated
// identical values are not printed twice. Every call made on the module's thread polls the abort
// request and throws Aborted (calls from worker threads never throw: the next main-thread call does).
class Progress
{
public:
  Progress() = default;
  explicit Progress(ModuleProcessInformation* information) : information_(information) {}
  void Start(const std::string& comment);
  void Report(double fraction);
  // Report progress of a sub-stage mapped into [from, to] of the whole (StageProgress = fraction).
  void ReportRange(double from, double to, double fraction);
  // Names the current stage (ProgressMessage in Slicer); polls the abort request.
  void Stage(const std::string& name);
  void End();
  void PollAbort() const; // throws Aborted when requested and called on the module's thread

private:
  void Update(double overall, double stage); // with mutex_ held
  std::mutex mutex_;
  std::string comment_;
  int last_ = -1; // last printed value in 1/1000
  ModuleProcessInformation* information_ = nullptr;
  std::thread::id owner_ = std::this_thread::get_id();
  double startTime_ = 0;
};

// Output scalars (channel=output, no flag/index), written to --returnparameterfile on success.
class ReturnParameters
{
public:
  void Set(const std::string& name, double value);
  void Set(const std::string& name, long long value);
  void Set(const std::string& name, int value) { Set(name, static_cast<long long>(value)); }
  void Set(const std::string& name, const std::string& value);
  void Set(const std::string& name, const std::vector<double>& value);
  const std::map<std::string, std::string>& Values() const { return values_; }

private:
  std::map<std::string, std::string> values_;
};

struct ModuleContext
{
  std::string moduleName;
  const ModuleDescription& description;
  Arguments args;
  Progress progress;
  ReturnParameters outputs;
};

// Parses argv against the XML description, runs body, reports errors, writes return parameters.
// Returns the process exit code: 0 success, 1 module error, 2 command-line error.
int RunModule(int argc, char* argv[], const char* xmlDescription, const std::function<void(ModuleContext&)>& body);

// Writes to a temporary sibling file and renames it over the final path on Commit(); the
// temporary is removed if Commit() is never reached, so a failure leaves no partial output.
// The temporary keeps the final extension (out.vtu -> out.mmrep-tmp-<pid>-<n>.vtu) so ITK/VTK
// writers that choose the format by extension still work.
class AtomicOutput
{
public:
  explicit AtomicOutput(std::string finalPath); // throws ModuleError if the folder is not writable
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  const std::string& TempPath() const { return temp_; }
  const std::string& FinalPath() const { return final_; }
  void Commit(); // throws ModuleError if the rename fails
  // For an output that explains a failure (a repair report): published even when the run fails.
  void CommitEvenIfRunFails();
  // Writes `text` to the temporary file (a report); throws ModuleError if it cannot.
  void WriteText(const std::string& text) const;

private:
  void Commit(bool evenIfRunFails);
  std::string final_, temp_;
  bool committed_ = false;
};

// Before an output is published: refuses it, naming `shown`, when the disk is full, the file is empty or
// its format's last record is missing (a writer that met a full disk and returned as if all went well).
// CheckWrittenFolder checks every file of a staged output folder (mmrepWrittenFiles.cxx).
void CheckWrittenFile(const std::string& staged, const std::string& shown);
void CheckWrittenFolder(const std::string& staged, const std::string& shown);
// A staging name (a temporary file or folder of an output) is shown as the output's own name in every
// error message of the run: users never see `.mmrep-tmp-` or `.partial-` paths.
void NameStagedPath(const std::string& staged, const std::string& shown);
std::string WithShownNames(std::string text);
// Removes every staged output of the run (a run that ends without unwinding: mmrepFatalError.h).
void RemoveStagedOutputs();

// Removes, in `folder`, what runs that died (kill -9, a crash) left behind: entries named
// <prefix><pid>, <prefix><pid>-… or <prefix><pid>.… whose process no longer exists.
void RemoveStaleOutputs(const std::string& folder, const std::string& prefix);

// A file shipped with the modules (the default atlas), by its path relative to the folder of the
// module's shared library: found the same way in the build tree, the install tree and Slicer.
std::string ModuleResourcePath(const std::string& relativePath);

// Output safety inside RunModule (mmrepOutputSafety.cxx); both do nothing outside a module run.
// Throws ModuleError if `path`, an output file or folder, is, contains or lies inside an input of
// the run, or is already another of its outputs. AtomicOutput calls it.
void CheckOutputPath(const std::string& path, bool folder);
// Schedules `publish` for when the whole run has succeeded (else `discard`; `publish` too when
// evenOnFailure) and returns true; returns false outside a run: the caller publishes at once.
bool DeferPublication(const std::string& finalPath, std::function<void()> publish, std::function<void()> discard,
                      bool evenOnFailure = false);

// Lower-cased extension including the dot; knows double extensions (.nii.gz, .mrk.json).
std::string FileExtension(const std::string& path);

} // namespace mmrep::cli
