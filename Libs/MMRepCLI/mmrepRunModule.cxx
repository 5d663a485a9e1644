// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// RunModule: command line (TCLAP) from the XML description, error reporting, return parameters.
#include "mmrepCLIInternal.h"
#include "mmrepFatalError.h"
#include "mmrepModuleProcessInformation.h"
#include "mmrepToolkitMessage.h"

#include <itkMacro.h> // itk::ExceptionObject
#include <tclap/CmdLine.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <regex>

namespace mmrep::cli
{
namespace
{
// Positional arguments must not swallow an unknown "--flag": TCLAP would take it as a value.
bool LooksLikeFlag(const std::string& token)
{
  double number = 0;
  return token.size() > 1 && token[0] == '-' && !detail::ParseDouble(token, number);
}

class Positional : public TCLAP::UnlabeledValueArg<std::string>
{
public:
  Positional(const Parameter& p, const std::string& help)
      : UnlabeledValueArg<std::string>(p.name, help, true, "", p.tag)
  {
  }
  bool processArg(int* i, std::vector<std::string>& args) override
  {
    return !LooksLikeFlag(args[*i]) && UnlabeledValueArg<std::string>::processArg(i, args);
  }
};

class PositionalList : public TCLAP::UnlabeledMultiArg<std::string>
{
public:
  PositionalList(const Parameter& p, const std::string& help)
      : UnlabeledMultiArg<std::string>(p.name, help, true, p.tag)
  {
  }
  bool processArg(int* i, std::vector<std::string>& args) override
  {
    return !LooksLikeFlag(args[*i]) && UnlabeledMultiArg<std::string>::processArg(i, args);
  }
};

// Slicer runs the executable (argv[0] = .../MeshQuality) or the library (.../libMeshQualityLib.so).
std::string ModuleName(const char* argv0, const ModuleDescription* description)
{
  std::string name = argv0 ? argv0 : "";
  name = name.substr(name.find_last_of('/') + 1);
  const auto so = name.find(".so");
  if (so != std::string::npos && name.rfind("lib", 0) == 0)
  {
    name = name.substr(3, so - 3);
    if (name.size() > 3 && name.compare(name.size() - 3, 3, "Lib") == 0)
      name.resize(name.size() - 3);
  }
  if (name.empty() && description)
    name = description->title;
  return name.empty() ? "module" : name;
}

std::string OneLine(std::string text)
{
  for (char& c : text)
    if (c == '\n' || c == '\r')
      c = ' ';
  return detail::Trim(text);
}

int Fail(const std::string& module, const std::string& what, int code)
{
  // A toolkit's text passed on as it came (an ITK exception caught as std::exception) is put in words.
  static const std::regex toolkit(R"(ITK ERROR|itk::ERROR|ERROR: In |\w ?\(0x[0-9a-fA-F]+\))");
  std::cout.flush(); // keep progress lines before the error when both go to one terminal
  std::cerr << module
            << ": error: " << OneLine(WithShownNames(std::regex_search(what, toolkit) ? ToolkitMessage(what) : what))
            << std::endl;
  return code;
}

std::string Help(const Parameter& p)
{
  std::string help = p.label.empty() ? p.name : p.label;
  if (!p.description.empty())
    help += ": " + p.description;
  if (!p.elements.empty())
  {
    help += " (one of";
    for (const std::string& e : p.elements)
      help += " " + e;
    help += ")";
  }
  if (!p.defaultValue.empty())
    help += " (default: " + p.defaultValue + ")";
  return help;
}

// Turns a TCLAP parse exception into "what, naming the parameter".
std::string Explain(const TCLAP::ArgException& e, const std::vector<std::pair<const Parameter*, TCLAP::Arg*>>& args)
{
  const std::string error = e.error();
  if (error.rfind("Couldn't find match", 0) == 0)
  {
    const std::string token = e.argId().substr(e.argId().rfind("Argument: ", 0) == 0 ? 10 : 0);
    return (LooksLikeFlag(token) ? "unknown option '" : "unexpected argument '") + token + "'";
  }
  if (error.rfind("Required argument", 0) == 0)
    for (const auto& [p, arg] : args)
      if (arg->isRequired() && !arg->isSet())
        return "missing required argument " + detail::Describe(*p);
  std::string id = e.argId();
  if (id.rfind("Argument: ", 0) == 0)
    id = id.substr(10);
  for (const auto& [p, arg] : args)
    if (arg->toString() == id)
    {
      if (error.rfind("Missing a value", 0) == 0)
        return "parameter " + detail::Describe(*p) + " needs a value";
      if (error.rfind("Argument already set", 0) == 0)
        return "parameter " + detail::Describe(*p) + " given more than once";
      return "parameter " + detail::Describe(*p) + ": " + error;
    }
  return error + (id.empty() || id == "undefined" ? "" : " (" + id + ")");
}

struct ParsedCommandLine
{
  std::map<std::string, std::vector<std::string>> values;
  std::string returnParameterFile;
  ModuleProcessInformation* processInformation = nullptr;
};

// Builds a TCLAP command line from the description and parses argv. Throws TCLAP exceptions.
ParsedCommandLine Parse(int argc, char* argv[], const ModuleDescription& d, const std::string& module)
{
  std::string message = d.title.empty() ? module : d.title;
  if (!d.description.empty())
    message += ": " + d.description;
  TCLAP::CmdLine cmd(message, ' ', d.version.empty() ? "unknown" : d.version);
  cmd.setExceptionHandling(false); // report errors ourselves, never exit() inside Slicer
  std::vector<std::unique_ptr<TCLAP::Arg>> owned;
  std::vector<std::pair<const Parameter*, TCLAP::Arg*>> args;

  TCLAP::SwitchArg xml("", "xml", "Print the XML description and exit", false);
  TCLAP::ValueArg<std::string> returnFile(
    "", "returnparameterfile", "File where the output scalars are written as name = value", false, "", "file");
  TCLAP::ValueArg<std::string> processAddress("", "processinformationaddress",
                                              "Address of Slicer's in-process progress block", false, "", "address");
  cmd.add(xml);
  cmd.add(returnFile);
  cmd.add(processAddress);

  // TCLAP lists flags in reverse order of addition; positional arguments keep theirs (sorted by index).
  std::vector<const Parameter*> positional;
  for (auto it = d.parameters.rbegin(); it != d.parameters.rend(); ++it)
  {
    const Parameter& p = *it;
    if (p.index >= 0)
    {
      positional.push_back(&p);
      continue;
    }
    if (p.IsReturnValue())
      continue;
    const std::string longflag = p.flag.empty() && p.longflag.empty() ? p.name : p.longflag;
    const std::string help = Help(p);
    if (p.tag == "boolean")
      owned.push_back(std::make_unique<TCLAP::SwitchArg>(p.flag, longflag, help, false));
    else if (p.multiple)
      owned.push_back(std::make_unique<TCLAP::MultiArg<std::string>>(p.flag, longflag, help, false, p.tag));
    else
      owned.push_back(
        std::make_unique<TCLAP::ValueArg<std::string>>(p.flag, longflag, help, false, p.defaultValue, p.tag));
    cmd.add(*owned.back());
    args.emplace_back(&p, owned.back().get());
  }
  std::stable_sort(positional.begin(), positional.end(),
                   [](const Parameter* a, const Parameter* b) { return a->index < b->index; });
  for (const Parameter* p : positional)
  {
    if (p->multiple)
      owned.push_back(std::make_unique<PositionalList>(*p, Help(*p)));
    else
      owned.push_back(std::make_unique<Positional>(*p, Help(*p)));
    cmd.add(*owned.back());
    args.emplace_back(p, owned.back().get());
  }

  try
  {
    std::vector<std::string> tokens(argv, argv + argc);
    if (!tokens.empty())
      tokens[0] = module; // usage shows the module name, not the path Slicer used
    cmd.parse(tokens);
  }
  catch (TCLAP::SpecificationException&)
  {
    throw;
  }
  catch (TCLAP::ArgException& e)
  {
    throw ModuleError(Explain(e, args));
  }

  ParsedCommandLine parsed;
  parsed.returnParameterFile = returnFile.getValue();
  if (processAddress.isSet() && !processAddress.getValue().empty())
  {
    // Slicer writes the address with %p (as its GenerateCLP reads it back).
    void* address = nullptr;
    if (std::sscanf(processAddress.getValue().c_str(), "%p", &address) != 1 || address == nullptr)
      throw ModuleError("--processinformationaddress: '" + processAddress.getValue() + "' is not an address");
    parsed.processInformation = static_cast<ModuleProcessInformation*>(address);
  }
  for (const auto& [p, arg] : args)
  {
    if (!arg->isSet())
      continue;
    std::vector<std::string>& v = parsed.values[p->name];
    if (auto* s = dynamic_cast<TCLAP::SwitchArg*>(arg))
      v.push_back(s->getValue() ? "true" : "false");
    else if (auto* m = dynamic_cast<TCLAP::MultiArg<std::string>*>(arg))
      v = m->getValue();
    else
      v.push_back(static_cast<TCLAP::ValueArg<std::string>*>(arg)->getValue());
  }
  return parsed;
}

void WriteReturnParameters(const std::string& path, const ModuleDescription& d, const ReturnParameters& outputs)
{
  for (const auto& [name, value] : outputs.Values())
    if (const Parameter* p = d.Find(name); !p || !p->IsReturnValue())
      throw ModuleError("'" + name + "' is not an output scalar of the module description");
  AtomicOutput out(path);
  {
    std::ofstream file(out.TempPath());
    for (const Parameter& p : d.parameters) // in declaration order
      if (const auto it = outputs.Values().find(p.name); it != outputs.Values().end())
        file << p.name << " = " << it->second << "\n";
    if (!file.flush())
      throw ModuleError("cannot write return parameter file '" + path + "'");
  }
  out.Commit();
}
} // namespace

int RunModule(int argc, char* argv[], const char* xmlDescription, const std::function<void(ModuleContext&)>& body)
{
  const std::string xml = xmlDescription ? xmlDescription : "";
  // --xml is answered before anything else: Slicer calls it without the required arguments.
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--xml")
    {
      std::fwrite(xml.data(), 1, xml.size(), stdout);
      std::fflush(stdout);
      return 0;
    }

  detail::SilenceToolkitConsoles();
  detail::BeginRun();
  ModuleDescription description;
  try
  {
    description = ModuleDescription::FromXML(xml);
  }
  catch (const std::exception& e)
  {
    return Fail(ModuleName(argc > 0 ? argv[0] : nullptr, nullptr), e.what(), 1);
  }
  const std::string module = ModuleName(argc > 0 ? argv[0] : nullptr, &description);
  // An error that cannot unwind (a lost X display while pictures are rendered): one line, nothing
  // staged left, exit code 1.
  SetFatalErrorHandler([module](const std::string& message) {
    std::cout.flush();
    std::cerr << module << ": error: " << WithShownNames(message) << std::endl;
    RemoveStagedOutputs();
    std::_Exit(1);
  });

  ParsedCommandLine parsed;
  Arguments arguments;
  // Outputs are published together once everything succeeded; any failure discards them.
  struct DiscardUnlessPublished
  {
    bool published = false;
    ~DiscardUnlessPublished()
    {
      if (!published)
        detail::DiscardOutputs();
    }
  } transaction;
  try
  {
    parsed = Parse(argc, argv, description, module);
    arguments = Arguments(description, parsed.values);
    detail::BeginOutputTransaction(description, parsed.values, parsed.returnParameterFile);
  }
  catch (const TCLAP::ExitException& e) // --help, --version
  {
    std::cout.flush();
    return e.getExitStatus();
  }
  catch (const TCLAP::SpecificationException& e) // two parameters share a flag: a description bug
  {
    return Fail(module, "invalid XML description: " + e.error() + " " + e.argId(), 1);
  }
  catch (const std::exception& e)
  {
    return Fail(module, e.what(), 2);
  }

  try
  {
    ModuleContext context{module, description, std::move(arguments), Progress(parsed.processInformation), {}};
    body(context);
    context.progress.End();
    if (!parsed.returnParameterFile.empty())
      WriteReturnParameters(parsed.returnParameterFile, description, context.outputs);
    transaction.published = true;
    detail::PublishOutputs();
  }
  catch (const Aborted& a) // outputs not committed were removed while unwinding
  {
    std::cout.flush();
    if (a.signal == 0)
    {
      std::cerr << module << ": aborted" << std::endl;
      return 1;
    }
    std::cerr << module << ": interrupted by "
              << (a.signal == SIGINT    ? "SIGINT"
                  : a.signal == SIGTERM ? "SIGTERM"
                                        : "a signal")
              << ", nothing written" << std::endl;
    return 128 + a.signal;
  }
  catch (const itk::ExceptionObject& e)
  {
    return Fail(module, ToolkitMessage(e.GetDescription()), 1); // what() adds the source file and line
  }
  catch (const std::bad_alloc&)
  {
    return Fail(module, "out of memory", 1);
  }
  catch (const std::exception& e)
  {
    return Fail(module, e.what(), 1);
  }
  catch (...)
  {
    return Fail(module, "unknown failure", 1);
  }
  return 0;
}

} // namespace mmrep::cli
