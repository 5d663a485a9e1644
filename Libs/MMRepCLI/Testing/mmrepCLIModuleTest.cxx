// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// End-to-end tests: run the test module (executable and shared library) like Slicer does.
#include "mmrepCLI.h"
#include "mmrepCLITestUtilities.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>

namespace fs = std::filesystem;
using namespace mmrep::cli::test;

namespace
{
const std::string kPrefix = "CLIFrameworkTestModule: error: ";
// The three positional arguments after the input volume and the output report.
const std::string kOthers = " m.vtk t.tfm tab.csv";

struct Result
{
  int code = -1;
  std::string out, err;
};

// Runs the module executable in `dir` with a shell-quoted argument string.
Result RunModule(const fs::path& dir, const std::string& args)
{
  const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
  const std::string command =
    "cd '" + dir.string() + "' && '" CLI_TEST_MODULE_EXE "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = ReadFile(out);
  r.err = ReadFile(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

// Exit code 2 with exactly one stderr line that names the parameter.
void ExpectCommandLineError(const std::string& args, const std::string& expectedMessage)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, args);
  EXPECT_EQ(r.code, 2) << args;
  EXPECT_EQ(r.err, kPrefix + expectedMessage + "\n") << args;
  EXPECT_TRUE(fs::is_empty(dir)) << "a command-line error must not write anything";
}

std::map<std::string, std::vector<std::string>> ReadReport(const fs::path& file)
{
  std::map<std::string, std::vector<std::string>> report;
  for (const std::string& line : Lines(ReadFile(file)))
  {
    const auto eq = line.find('=');
    report[line.substr(0, eq)].push_back(line.substr(eq + 1));
  }
  return report;
}
} // namespace

TEST(CLIModule, XmlIsPrintedByteForByte)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, "--xml");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, ReadFile(CLI_TEST_MODULE_XML));
  EXPECT_EQ(r.err, "");
  // --xml wins even when required arguments or other flags are present
  EXPECT_EQ(RunModule(dir, "--iterations abc --xml").out, ReadFile(CLI_TEST_MODULE_XML));
}

TEST(CLIModule, HelpListsParameters)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, "--help");
  EXPECT_EQ(r.code, 0);
  for (const char* expected : {"CLI Framework Test Module", "--iterations", "-i", "--seedsRAS", "--returnparameterfile",
                               "--xml", "<image>", "<file>", "one of fast accurate", "(default: 3)"})
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
  EXPECT_EQ(r.out.find("--checksum"), std::string::npos) << "return values are not command-line options";
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(CLIModule, ValuesReachTheBody)
{
  const fs::path dir = TestFolder();
  // A work folder of its own: an output folder holding the inputs would be refused (wherever the
  // build tree is, /tmp included).
  fs::create_directory(dir / "work");
  const Result r =
    RunModule(dir, "in.nrrd report.txt m.vtk t.tfm tab.csv -i 4 --fraction 0.75 --scale -2.5 -v --label 'two words' "
                   "--size 7,8 --weights 0.5 --spacing 0.2,0.3,0.4 --tags a,b,c --order 1 --ratio 1.5 "
                   "--sigma 2.5 --mode accurate --workDir work --roi 1,2,3,4,5,6 "
                   "--seedsRAS 10,-20.5,30 --seedsRAS -1,0,2 --seedLPS 1,2,3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  auto report = ReadReport(dir / "report.txt");
  using V = std::vector<std::string>;
  EXPECT_EQ(report["inputVolume"], V{"in.nrrd"});
  EXPECT_EQ(report["iterations"], V{"4"});
  EXPECT_EQ(report["fraction"], V{"0.75"});
  EXPECT_EQ(report["scale"], V{"-2.5"});
  EXPECT_EQ(report["verbose"], V{"1"});
  EXPECT_EQ(report["label"], V{"two words"});
  EXPECT_EQ(report["size"], V{"7,8"});
  EXPECT_EQ(report["weights"], V{"0.5"});
  EXPECT_EQ(report["spacing"], V{"0.20000000000000001,0.29999999999999999,0.40000000000000002"});
  EXPECT_EQ(report["tags"], V{"a,b,c"});
  EXPECT_EQ(report["order"], V{"1"});
  EXPECT_EQ(report["ratio"], V{"1.5"});
  EXPECT_EQ(report["sigma"], V{"2.5"});
  EXPECT_EQ(report["mode"], V{"accurate"});
  EXPECT_EQ(report["workDir"], V{"work"});
  EXPECT_EQ(report["inputMesh"], V{"m.vtk"});
  EXPECT_EQ(report["inputTransform"], V{"t.tfm"});
  EXPECT_EQ(report["outputTable"], V{"tab.csv"});
  EXPECT_EQ(report["roi"], V{"1,2,3,4,5,6"});
  EXPECT_EQ(report["seedsRAS"], (V{"-10,20.5,30", "1,0,2"})); // RAS -> LPS: x and y negated
  EXPECT_EQ(report["seedLPS"], V{"1,2,3"});                   // already LPS: unchanged
}

TEST(CLIModule, DefaultsReachTheBody)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, "in.nrrd report.txt" + kOthers);
  ASSERT_EQ(r.code, 0) << r.err;
  auto report = ReadReport(dir / "report.txt");
  using V = std::vector<std::string>;
  EXPECT_EQ(report["iterations"], V{"3"});
  EXPECT_EQ(report["verbose"], V{"0"});
  EXPECT_EQ(report["size"], V{"1,2,3"});
  EXPECT_EQ(report["tags"], V{"alpha,beta"});
  EXPECT_EQ(report["mode"], V{"fast"});
  EXPECT_EQ(report["workDir"], V{"-"});
  EXPECT_EQ(report["roi"], V{""});
  EXPECT_EQ(report.count("seedsRAS"), 0u);
}

TEST(CLIModule, WrongTypeIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --iterations abc",
                         "parameter 'iterations' (--iterations): 'abc' is not an integer");
}

TEST(CLIModule, WrongVectorTypeIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --size 1,x", "parameter 'size' (--size): 'x' is not an integer");
}

TEST(CLIModule, UnknownFlagIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --bogus 3", "unknown option '--bogus'");
}

TEST(CLIModule, UnknownFlagBeforePositionalsIsExit2)
{
  ExpectCommandLineError("--bogus in out" + kOthers, "unknown option '--bogus'");
}

TEST(CLIModule, EnumerationViolationIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --mode slow",
                         "parameter 'mode' (--mode): 'slow' is not one of fast, accurate");
}

TEST(CLIModule, ConstraintViolationIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " -i 11",
                         "parameter 'iterations' (--iterations): 11 is above the maximum 10");
}

TEST(CLIModule, MissingPositionalIsExit2)
{
  ExpectCommandLineError("in.nrrd --iterations 2", "missing required argument 'outputFile' (argument 2)");
}

TEST(CLIModule, MissingValueIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --iterations", "parameter 'iterations' (--iterations) needs a value");
}

TEST(CLIModule, RepeatedFlagIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --scale 1 --scale 2",
                         "parameter 'scale' (--scale) given more than once");
}

TEST(CLIModule, ExtraPositionalIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " extra", "unexpected argument 'extra'");
}

TEST(CLIModule, BadPointIsExit2)
{
  ExpectCommandLineError("in out" + kOthers + " --seedsRAS 1,2",
                         "parameter 'seedsRAS' (--seedsRAS): '1,2' must have 3 comma-separated numbers");
}

TEST(CLIModule, ReturnParameterFile)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, "in report.txt" + kOthers +
                                    " --mode accurate --scale 0.25 --spacing 1,2,3.5 --seedsRAS 1,2,3 "
                                    "--seedsRAS 4,5,6 --returnparameterfile rp.txt");
  ASSERT_EQ(r.code, 0) << r.err;
  // checksum = scale + sum(spacing), in declaration order
  EXPECT_EQ(ReadFile(dir / "rp.txt"), "checksum = 6.75\nseedCount = 2\nmodeUsed = accurate\n");
  // nothing else left in the folder (no temporary file)
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    files.insert(e.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"report.txt", "rp.txt"}));
}

TEST(CLIModule, ProgressIsSlicerFormattedAndMonotonic)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, "in report.txt" + kOthers);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<std::string> lines = Lines(r.out);
  ASSERT_GE(lines.size(), 8u) << r.out;
  EXPECT_EQ(lines[0], "<filter-start>");
  EXPECT_EQ(lines[1], "<filter-name>Testing the CLI framework</filter-name>");
  EXPECT_EQ(lines[2], "<filter-comment>Testing the CLI framework</filter-comment>");
  EXPECT_EQ(lines[3], "</filter-start>");
  const size_t n = lines.size();
  EXPECT_EQ(lines[n - 3], "<filter-end>");
  EXPECT_EQ(lines[n - 2], "<filter-name>Testing the CLI framework</filter-name>");
  EXPECT_EQ(lines[n - 1], "</filter-end>");
  const std::regex progress(R"(<filter-progress>([0-9.e-]+)</filter-progress>)");
  std::vector<double> values;
  for (size_t i = 4; i < n - 3; ++i)
  {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(lines[i], m, progress)) << "line " << i << ": " << lines[i];
    values.push_back(std::stod(m[1]));
  }
  ASSERT_GE(values.size(), 2u);
  for (size_t i = 1; i < values.size(); ++i)
    EXPECT_LT(values[i - 1], values[i]) << "progress went backwards or repeated at " << i;
  EXPECT_GE(values.front(), 0.0);
  EXPECT_DOUBLE_EQ(values[values.size() - 2], 0.95); // the last Report() of the body
  EXPECT_DOUBLE_EQ(values.back(), 1.0);              // End() completes it
}

namespace
{
void ExpectModuleFailure(const std::string& failure, const std::string& message)
{
  const fs::path dir = TestFolder();
  fs::create_directory(dir / "out");
  const Result r =
    RunModule(dir, "in out/report.txt" + kOthers + " --failure " + failure + " --returnparameterfile out/rp.txt");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, kPrefix + message + "\n");
  EXPECT_TRUE(fs::is_empty(dir / "out")) << "no output, no temporary, no return file after a failure";
}
} // namespace

TEST(CLIModule, ModuleErrorIsExit1)
{
  ExpectModuleFailure("module", "requested module failure");
}

TEST(CLIModule, StdExceptionIsExit1)
{
  ExpectModuleFailure("std", "requested std failure");
}

TEST(CLIModule, ItkExceptionIsExit1InWords) // no source location, no "ITK ERROR:" prefix
{
  ExpectModuleFailure("itk", "requested itk failure");
}

TEST(CLIModule, FailureAfterWritingLeavesNoFile)
{
  const fs::path dir = TestFolder();
  fs::create_directory(dir / "out");
  const Result r =
    RunModule(dir, "in out/report.txt" + kOthers + " --failure afterWrite --returnparameterfile out/rp.txt");
  EXPECT_EQ(r.code, 1);
  ASSERT_EQ(Lines(r.err).size(), 1u) << r.err;
  // the temporary being written is shown by the output's own name (no staging names in messages)
  EXPECT_EQ(r.err, kPrefix + "requested failure after writing 'out/report.txt'\n");
  EXPECT_TRUE(fs::is_empty(dir / "out"));
}

TEST(CLIModule, MissingOutputFolderIsNamed)
{
  const fs::path dir = TestFolder();
  const Result r = RunModule(dir, "in nowhere/report.txt" + kOthers);
  EXPECT_EQ(r.code, 2); // refused from the command line, before the body runs
  EXPECT_EQ(r.err, kPrefix + "'outputFile' (argument 2): cannot write 'nowhere/report.txt': folder '" +
                     (fs::weakly_canonical(dir) / "nowhere").string() + "' does not exist\n");
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
}

TEST(CLIModule, FailureAfterCommitPublishesNothing)
{
  const fs::path dir = TestFolder();
  fs::create_directory(dir / "out");
  std::ofstream(dir / "out" / "report.txt") << "earlier result";
  const Result r =
    RunModule(dir, "in out/report.txt" + kOthers + " --failure afterCommit --returnparameterfile out/rp.txt");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, kPrefix + "requested failure after committing the output\n");
  // The earlier result is as it was, no return parameters, no temporary left.
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "out"))
    names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"report.txt"});
  std::ifstream f(dir / "out" / "report.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(f), {}), "earlier result");
}

TEST(CLIModule, ReturnParameterFailurePublishesNothing)
{
  // The return-parameter file cannot be written (its name is a folder): the output is not published either.
  const fs::path dir = TestFolder();
  fs::create_directories(dir / "out" / "rp.txt");
  const Result r = RunModule(dir, "in out/report.txt" + kOthers + " --returnparameterfile out/rp.txt");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(Lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("rp.txt"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "report.txt"));
}

namespace
{
// Calls the library's entry point in this process, with stderr sent to a file.
int CallEntryPoint(const fs::path& dir, std::vector<std::string> args, std::string& err)
{
  void* library = dlopen(CLI_TEST_MODULE_LIB, RTLD_NOW | RTLD_LOCAL);
  if (!library)
    throw std::runtime_error(dlerror());
  using EntryPoint = int (*)(int, char*[]);
  auto entry = reinterpret_cast<EntryPoint>(dlsym(library, "ModuleEntryPoint"));
  if (!entry)
    throw std::runtime_error("ModuleEntryPoint is not exported");
  args.insert(args.begin(), CLI_TEST_MODULE_LIB); // Slicer passes the library location as argv[0]
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);

  const fs::path errFile = dir / "stderr.txt";
  std::fflush(stderr);
  const int saved = dup(2);
  const int fd = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(fd, 2);
  close(fd);
  const int code = entry(static_cast<int>(args.size()), argv.data());
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  err = ReadFile(errFile);
  fs::remove(errFile);
  dlclose(library);
  return code;
}
} // namespace

TEST(CLIModule, SharedLibraryExportsEntryPoint)
{
  const fs::path dir = TestFolder();
  std::string err;
  EXPECT_EQ(
    CallEntryPoint(dir, {"in.nrrd", (dir / "report.txt").string(), "m", "t", "tab", "--seedsRAS", "1,2,3"}, err), 0)
    << err;
  EXPECT_EQ(err, "");
  EXPECT_EQ(ReadReport(dir / "report.txt")["seedsRAS"], std::vector<std::string>{"-1,-2,3"});

  // the module name comes from the library file name
  EXPECT_EQ(CallEntryPoint(dir, {"a", "b", "c", "d", "e", "--iterations", "abc"}, err), 2);
  EXPECT_EQ(err, kPrefix + "parameter 'iterations' (--iterations): 'abc' is not an integer\n");
}
