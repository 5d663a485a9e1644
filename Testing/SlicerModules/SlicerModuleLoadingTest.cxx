// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Loads every module's shared library the way Slicer's CLI factory does (dlopen, then the symbol
// XMLModuleDescription or the function GetXMLModuleDescription, and ModuleEntryPoint), checks the
// description against the executable's --xml and Slicer's schema, and runs modules in process with
// Slicer's ModuleProcessInformation block: progress reported to the block, Abort honoured.
#include "mmrepModuleProcessInformation.h"
#include "mmrepModuleRunner.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using mmrep::testing::Quote;
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::Slurp;

using EntryPoint = int (*)(int, char*[]);
using DescriptionFunction = char* (*)();

std::vector<std::string> Modules()
{
  std::vector<std::string> names;
  std::stringstream list(MMREP_CLI_MODULES);
  for (std::string name; std::getline(list, name, ',');)
    names.push_back(name);
  return names;
}

// A library opened as Slicer opens it (itksys::DynamicLoader: dlopen RTLD_LAZY | RTLD_LOCAL).
struct Library
{
  explicit Library(const std::string& module)
      : path(std::string(MMREP_CLI_LIBRARY_DIR) + "/lib" + module + "Lib.so"),
        handle(::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL))
  {
  }
  ~Library()
  {
    if (handle)
      ::dlclose(handle);
  }
  void* Symbol(const char* name) const { return handle ? ::dlsym(handle, name) : nullptr; }
  EntryPoint Entry() const { return reinterpret_cast<EntryPoint>(Symbol("ModuleEntryPoint")); }
  std::string path;
  void* handle;
};

// Runs ModuleEntryPoint as Slicer does in process: argv[0] the library, then the parameters and
// --processinformationaddress with the block's address written by %p.
int RunInProcess(const Library& lib, std::vector<std::string> args, ModuleProcessInformation* info)
{
  char address[64];
  std::snprintf(address, sizeof address, "%p", static_cast<void*>(info));
  args.insert(args.begin(), lib.path);
  args.push_back("--processinformationaddress");
  args.push_back(address);
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  return lib.Entry()(static_cast<int>(args.size()), argv.data());
}

// What the progress callback saw.
struct Observed
{
  ModuleProcessInformation* info = nullptr;
  std::vector<float> progress, stage;
  std::vector<std::string> messages;
  float abortAt = 2; // sets Abort once Progress reaches it
};

extern "C" void Observe(void* data)
{
  auto* o = static_cast<Observed*>(data);
  o->progress.push_back(o->info->Progress);
  o->stage.push_back(o->info->StageProgress);
  o->messages.emplace_back(o->info->ProgressMessage);
  if (o->info->Progress >= o->abortAt)
    o->info->Abort = 1;
}

ModuleProcessInformation Block(Observed& observed)
{
  ModuleProcessInformation info{};
  info.ProgressCallbackFunction = Observe;
  info.ProgressCallbackClientData = &observed;
  return info;
}

fs::path FreshFolder(const std::string& name)
{
  const fs::path dir = fs::temp_directory_path() / ("mmrep-slicer-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(SlicerModuleLoading, EveryLibraryHasSlicersSymbolsAndTheExecutablesDescription)
{
  const auto modules = Modules();
  ASSERT_GE(modules.size(), 13u);
  const fs::path dir = FreshFolder("xml");
  for (const std::string& module : modules)
  {
    SCOPED_TRACE(module);
    Library lib(module);
    ASSERT_NE(lib.handle, nullptr) << ::dlerror();
    const auto* symbol = static_cast<const char*>(lib.Symbol("XMLModuleDescription"));
    const auto function = reinterpret_cast<DescriptionFunction>(lib.Symbol("GetXMLModuleDescription"));
    ASSERT_NE(symbol, nullptr);
    ASSERT_NE(function, nullptr);
    ASSERT_NE(lib.Entry(), nullptr);
    const std::string xml = symbol;
    EXPECT_EQ(std::string(function()), xml);
    // Byte for byte what the executable prints with --xml, and what the source .xml holds.
    const auto run = RunModuleExecutable(module, {"--xml"});
    ASSERT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.out, xml);
    EXPECT_EQ(Slurp(fs::path(MMREP_SOURCE_DIR) / "Modules/CLI" / module / (module + ".xml")), xml);
    // Parsed by an independent parser (libxml2) against Slicer's schema.
    const fs::path file = dir / (module + ".xml");
    std::ofstream(file, std::ios::binary) << xml;
    const std::string check = std::string(XMLLINT_EXECUTABLE) + " --noout --schema " + Quote(MMREP_MODULE_SCHEMA) +
                              " " + Quote(file.string()) + " 2>/dev/null";
    EXPECT_EQ(std::system(check.c_str()), 0) << "the library's description does not validate against Slicer's schema";
  }
  fs::remove_all(dir);
}

TEST(SlicerModuleLoading, RunsInProcessReportingToTheProgressBlock)
{
  const fs::path dir = FreshFolder("quality");
  const std::string atlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";
  Library lib("MeshQuality");
  ASSERT_NE(lib.Entry(), nullptr);
  Observed observed;
  auto info = Block(observed);
  observed.info = &info;
  const fs::path out = dir / "inprocess.vtu";
  ASSERT_EQ(RunInProcess(lib, {atlas, "--outputMesh", out.string()}, &info), 0);
  // Progress rose to 1 through the callback, never backwards; the message names the module's work.
  ASSERT_GE(observed.progress.size(), 3u);
  for (std::size_t i = 1; i < observed.progress.size(); ++i)
    EXPECT_GE(observed.progress[i], observed.progress[i - 1]);
  EXPECT_EQ(observed.progress.front(), 0.0f);
  EXPECT_EQ(observed.progress.back(), 1.0f);
  EXPECT_EQ(info.Progress, 1.0f);
  EXPECT_EQ(info.StageProgress, 1.0f);
  EXPECT_STREQ(info.ProgressMessage, "Computing element quality");
  EXPECT_GT(info.ElapsedTime, 0.0);
  // The same bytes as the executable writes.
  const fs::path reference = dir / "executable.vtu";
  ASSERT_EQ(RunModuleExecutable("MeshQuality", {atlas, "--outputMesh", reference.string()}).exitCode, 0);
  EXPECT_EQ(Slurp(out), Slurp(reference));
  // A second run in the same process (Slicer keeps the library loaded) works the same.
  Observed again;
  auto info2 = Block(again);
  again.info = &info2;
  const fs::path out2 = dir / "again.vtu";
  ASSERT_EQ(RunInProcess(lib, {atlas, "--outputMesh", out2.string()}, &info2), 0);
  EXPECT_EQ(info2.Progress, 1.0f);
  EXPECT_EQ(Slurp(out2), Slurp(reference));
  fs::remove_all(dir);
}

TEST(SlicerModuleLoading, AnAddressThatIsNotOneIsACommandLineError)
{
  const std::string atlas = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlas.vtu";
  const auto run = RunModuleExecutable("MeshQuality", {atlas, "--processinformationaddress", "nowhere"});
  EXPECT_EQ(run.exitCode, 2);
  ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
  EXPECT_NE(run.err.find("--processinformationaddress: 'nowhere' is not an address"), std::string::npos) << run.err;
}

TEST(SlicerModuleLoading, AbortFromTheProgressCallbackStopsTheRunAndLeavesNoOutput)
{
  const fs::path dir = FreshFolder("abort");
  const std::string skin = std::string(MMREP_SOURCE_DIR) + "/Resources/Atlas/FaceAtlasSkin.vtp";
  Library lib("DistanceMap");
  ASSERT_NE(lib.Entry(), nullptr);
  Observed observed;
  observed.abortAt = 0.1f; // once the surface is read: mid-run, inside the distance computation
  auto info = Block(observed);
  observed.info = &info;
  const fs::path out = dir / "map.nrrd";
  EXPECT_NE(RunInProcess(lib, {skin, out.string(), "--spacing", "1.5"}, &info), 0);
  EXPECT_EQ(info.Abort, 1);
  EXPECT_LT(info.Progress, 1.0f); // it stopped before the end
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(dir)) << "temporary files left behind";
  // Without the abort the same run completes (the abort, not the input, stopped it).
  Observed full;
  auto info2 = Block(full);
  full.info = &info2;
  EXPECT_EQ(RunInProcess(lib, {skin, out.string(), "--spacing", "1.5"}, &info2), 0);
  EXPECT_TRUE(fs::exists(out));
  EXPECT_EQ(info2.Progress, 1.0f);
  fs::remove_all(dir);
}

} // namespace
