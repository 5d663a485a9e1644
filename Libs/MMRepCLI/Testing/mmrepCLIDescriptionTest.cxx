// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// In-process tests of the framework pieces: description parsing, typed arguments, progress,
// return parameters, atomic output and file extensions.
#include "mmrepCLI.h"
#include "mmrepCLITestUtilities.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace fs = std::filesystem;
using namespace mmrep::cli;
using namespace mmrep::cli::test;

namespace
{
const std::string& TestXML()
{
  static const std::string xml = ReadFile(CLI_TEST_MODULE_XML);
  return xml;
}

const ModuleDescription& TestDescription()
{
  static const ModuleDescription d = ModuleDescription::FromXML(TestXML());
  return d;
}

std::string XPath(const std::string& expression)
{
  std::string out = Capture("xmllint --xpath '" + expression + "' '" CLI_TEST_MODULE_XML "'");
  if (!out.empty() && out.back() == '\n') // xmllint ends its answer with a newline
    out.pop_back();
  return out;
}
} // namespace

TEST(CLIDescription, HeaderFields)
{
  const ModuleDescription& d = TestDescription();
  EXPECT_EQ(d.category, "MMRep.Testing");
  EXPECT_EQ(d.title, "CLI Framework Test Module");
  EXPECT_EQ(d.description, "Exercises every parameter type of the MMRep CLI framework & reports what it received.");
  EXPECT_EQ(d.version, "0.1.0");
  EXPECT_EQ(d.license, "BSD-3-Clause");
  EXPECT_EQ(d.contributor, "MMRep developers");
}

// Names, tags and order of the parameters agree with xmllint reading the same file.
TEST(CLIDescription, ParametersMatchXmllint)
{
  const ModuleDescription& d = TestDescription();
  const std::vector<std::string> names = Lines(XPath("//parameters/*[name]/name/text()"));
  ASSERT_EQ(names.size(), 27u);
  ASSERT_EQ(d.parameters.size(), names.size());
  for (size_t i = 0; i < names.size(); ++i)
  {
    const std::string n = std::to_string(i + 1);
    EXPECT_EQ(d.parameters[i].name, names[i]);
    EXPECT_EQ(d.parameters[i].tag, XPath("name((//parameters/*[name])[" + n + "])")) << names[i];
    EXPECT_EQ(d.parameters[i].label, XPath("string((//parameters/*[name])[" + n + "]/label)")) << names[i];
    EXPECT_EQ(d.parameters[i].description, XPath("string((//parameters/*[name])[" + n + "]/description)")) << names[i];
    EXPECT_EQ(d.parameters[i].defaultValue, XPath("string((//parameters/*[name])[" + n + "]/default)")) << names[i];
  }
  for (const char* tag : {"integer",
                          "float",
                          "double",
                          "boolean",
                          "string",
                          "integer-vector",
                          "float-vector",
                          "double-vector",
                          "string-vector",
                          "integer-enumeration",
                          "float-enumeration",
                          "double-enumeration",
                          "string-enumeration",
                          "file",
                          "directory",
                          "image",
                          "geometry",
                          "transform",
                          "point",
                          "pointfile",
                          "region",
                          "table"})
    EXPECT_TRUE(std::any_of(d.parameters.begin(), d.parameters.end(), [&](const Parameter& p) { return p.tag == tag; }))
      << "the test module should declare a <" << tag << ">";
}

TEST(CLIDescription, FlagsIndicesConstraintsEnumerations)
{
  const ModuleDescription& d = TestDescription();
  const Parameter* it = d.Find("iterations");
  ASSERT_NE(it, nullptr);
  EXPECT_EQ(it->flag, "i");
  EXPECT_EQ(it->longflag, "iterations");
  EXPECT_EQ(it->index, -1);
  EXPECT_EQ(it->minimum, "1");
  EXPECT_EQ(it->maximum, "10");
  EXPECT_FALSE(it->multiple);

  const Parameter* in = d.Find("inputVolume");
  ASSERT_NE(in, nullptr);
  EXPECT_EQ(in->index, 0);
  EXPECT_EQ(in->channel, "input");
  EXPECT_TRUE(in->flag.empty() && in->longflag.empty());
  EXPECT_EQ(d.Find("outputFile")->index, 1);
  EXPECT_EQ(d.Find("outputFile")->channel, "output");

  EXPECT_EQ(d.Find("order")->elements, (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(d.Find("mode")->elements, (std::vector<std::string>{"fast", "accurate"}));
  EXPECT_EQ(d.Find("failure")->elements.size(), 6u);

  EXPECT_TRUE(d.Find("seedsRAS")->multiple);
  EXPECT_EQ(d.Find("seedsRAS")->coordinateSystem, "ras");
  EXPECT_EQ(d.Find("seedLPS")->coordinateSystem, "lps");
  EXPECT_EQ(d.Find("landmarks")->coordinateSystem, "lps");
  EXPECT_EQ(d.Find("roi")->coordinateSystem, "ras"); // Slicer's default when the attribute is absent

  for (const Parameter& p : d.parameters)
  {
    const bool expected = p.name == "checksum" || p.name == "seedCount" || p.name == "modeUsed";
    EXPECT_EQ(p.IsReturnValue(), expected) << p.name;
  }
  EXPECT_EQ(d.Find("nonexistent"), nullptr);
}

TEST(CLIDescription, MalformedXmlIsAModuleError)
{
  try
  {
    ModuleDescription::FromXML("<executable>\n<title>x</executable>");
    FAIL() << "no exception";
  }
  catch (const ModuleError& e)
  {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ModuleDescription::FromXML("<module><title>x</title></module>"), ModuleError);
  EXPECT_THROW(ModuleDescription::FromXML("<executable><parameters><integer><name>a</name></integer>"
                                          "<double><name>a</name></double></parameters></executable>"),
               ModuleError);
  EXPECT_THROW(ModuleDescription::FromXML("<executable><parameters><integer><flag>x</flag></integer>"
                                          "</parameters></executable>"),
               ModuleError);
}

TEST(CLIArguments, TypedGettersAndDefaults)
{
  const ModuleDescription& d = TestDescription();
  const Arguments a(d, {{"inputVolume", {"in.nrrd"}},
                        {"iterations", {"+7"}},
                        {"scale", {"-2.5e-1"}},
                        {"verbose", {"true"}},
                        {"size", {"4, 5,6"}},
                        {"tags", {"x,y z"}},
                        {"spacing", {"0.5,0.5,1.25"}},
                        {"order", {"3"}}});
  EXPECT_EQ(a.String("inputVolume"), "in.nrrd");
  EXPECT_EQ(a.Int("iterations"), 7);
  EXPECT_DOUBLE_EQ(a.Double("scale"), -0.25);
  EXPECT_TRUE(a.Bool("verbose"));
  EXPECT_EQ(a.Ints("size"), (std::vector<long long>{4, 5, 6}));
  EXPECT_EQ(a.Strings("tags"), (std::vector<std::string>{"x", "y z"}));
  EXPECT_EQ(a.Doubles("spacing"), (std::vector<double>{0.5, 0.5, 1.25}));
  EXPECT_EQ(a.Int("order"), 3);
  // defaults
  EXPECT_DOUBLE_EQ(a.Double("fraction"), 0.5);
  EXPECT_EQ(a.String("mode"), "fast");
  EXPECT_EQ(a.Doubles("weights"), (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(a.Strings("tags").size(), 2u);
  // given vs. has
  EXPECT_TRUE(a.Given("iterations"));
  EXPECT_FALSE(a.Given("fraction"));
  EXPECT_TRUE(a.Has("fraction"));
  EXPECT_FALSE(a.Has("workDir"));
  EXPECT_THROW(a.String("workDir"), ModuleError);
  EXPECT_THROW(a.Int("notDeclared"), ModuleError);
  EXPECT_TRUE(a.PointsLPS("seedsRAS").empty());

  const Arguments defaults(d, {});
  EXPECT_FALSE(defaults.Bool("verbose"));
  EXPECT_EQ(defaults.Int("iterations"), 3);
}

TEST(CLIArguments, PointsAreConvertedToLPS)
{
  const ModuleDescription& d = TestDescription();
  const Arguments a(d, {{"seedsRAS", {"10,-20.5,30", "-1,2,-3"}}, {"seedLPS", {"10,-20.5,30"}}});
  const auto ras = a.PointsLPS("seedsRAS");
  ASSERT_EQ(ras.size(), 2u);
  EXPECT_EQ(ras[0], (std::array<double, 3>{-10, 20.5, 30}));
  EXPECT_EQ(ras[1], (std::array<double, 3>{1, -2, -3}));
  const auto lps = a.PointsLPS("seedLPS");
  ASSERT_EQ(lps.size(), 1u);
  EXPECT_EQ(lps[0], (std::array<double, 3>{10, -20.5, 30}));
  EXPECT_THROW(a.PointsLPS("roi"), ModuleError); // a region is not a point
}

namespace
{
std::string ValidationError(const std::map<std::string, std::vector<std::string>>& values)
{
  try
  {
    Arguments(TestDescription(), values);
  }
  catch (const ModuleError& e)
  {
    return e.what();
  }
  return "no error";
}
} // namespace

TEST(CLIArguments, ValidationNamesTheParameter)
{
  EXPECT_EQ(ValidationError({{"iterations", {"abc"}}}),
            "parameter 'iterations' (--iterations): 'abc' is not an integer");
  EXPECT_EQ(ValidationError({{"iterations", {"2.5"}}}),
            "parameter 'iterations' (--iterations): '2.5' is not an integer");
  EXPECT_EQ(ValidationError({{"iterations", {"0"}}}),
            "parameter 'iterations' (--iterations): 0 is below the minimum 1");
  EXPECT_EQ(ValidationError({{"fraction", {"1.01"}}}),
            "parameter 'fraction' (--fraction): 1.01 is above the maximum 1");
  EXPECT_EQ(ValidationError({{"scale", {"1.5x"}}}), "parameter 'scale' (--scale): '1.5x' is not a number");
  EXPECT_EQ(ValidationError({{"spacing", {"1,0.05,1"}}}),
            "parameter 'spacing' (--spacing): 0.05 is below the minimum 0.1");
  EXPECT_EQ(ValidationError({{"size", {"1,,2"}}}), "parameter 'size' (--size): '' is not an integer");
  EXPECT_EQ(ValidationError({{"mode", {"slow"}}}), "parameter 'mode' (--mode): 'slow' is not one of fast, accurate");
  EXPECT_EQ(ValidationError({{"order", {"4"}}}), "parameter 'order' (--order): '4' is not one of 1, 2, 3");
  EXPECT_EQ(ValidationError({{"seedLPS", {"1,2"}}}),
            "parameter 'seedLPS' (--seedLPS): '1,2' must have 3 comma-separated numbers");
  EXPECT_EQ(ValidationError({{"roi", {"1,2,3,4,5,six"}}}), "parameter 'roi' (--roi): 'six' is not a number");
  EXPECT_EQ(ValidationError({{"scale", {"1", "2"}}}), "parameter 'scale' (--scale) given more than once");
  EXPECT_EQ(ValidationError({{"bogus", {"1"}}}), "parameter 'bogus' is not declared in the module description");
  // accepted: numeric enumeration compared as numbers, sign, exponent
  EXPECT_EQ(ValidationError({{"sigma", {"2.50"}}, {"ratio", {"1.5"}}, {"scale", {"+1e3"}}, {"order", {"1"}}}),
            "no error");
}

TEST(CLIProgress, MonotonicClampedAndWellFormed)
{
  std::ostringstream captured;
  auto* old = std::cout.rdbuf(captured.rdbuf());
  {
    Progress p;
    p.Start("Smoothing <mesh>");
    p.Report(0.25);
    p.Report(0.1);    // backwards: ignored
    p.Report(0.2501); // same 1/1000: ignored
    p.ReportRange(0.5, 1.0, 0.5);
    p.Report(std::nan(""));
    p.Report(7.0); // clamped
    p.End();
    p.End(); // once only
  }
  std::cout.rdbuf(old);
  EXPECT_EQ(captured.str(), "<filter-start>\n<filter-name>Smoothing &lt;mesh&gt;</filter-name>\n"
                            "<filter-comment>Smoothing &lt;mesh&gt;</filter-comment>\n</filter-start>\n"
                            "<filter-progress>0.25</filter-progress>\n"
                            "<filter-progress>0.75</filter-progress>\n"
                            "<filter-progress>1</filter-progress>\n"
                            "<filter-end>\n<filter-name>Smoothing &lt;mesh&gt;</filter-name>\n</filter-end>\n");
}

TEST(CLIReturnParameters, Formatting)
{
  ReturnParameters r;
  r.Set("a", 0.1);
  r.Set("b", 3);
  r.Set("c", std::vector<double>{1.0, -2.5, 1e-20});
  r.Set("d", std::string("two\nlines"));
  r.Set("e", 1.0 / 3.0);
  EXPECT_EQ(r.Values().at("a"), "0.1");
  EXPECT_EQ(r.Values().at("b"), "3");
  EXPECT_EQ(r.Values().at("c"), "1,-2.5,1e-20");
  EXPECT_EQ(r.Values().at("d"), "two lines");
  EXPECT_EQ(std::stod(r.Values().at("e")), 1.0 / 3.0); // round-trips exactly
}

TEST(CLIFileExtension, SimpleAndCompound)
{
  EXPECT_EQ(FileExtension("/a.b/mesh.VTU"), ".vtu");
  EXPECT_EQ(FileExtension("head.nii.gz"), ".nii.gz");
  EXPECT_EQ(FileExtension("dir/points.mrk.json"), ".mrk.json");
  EXPECT_EQ(FileExtension("mesh.vtk.gz"), ".vtk.gz");
  EXPECT_EQ(FileExtension("a.b.json"), ".json");
  EXPECT_EQ(FileExtension("noext"), "");
  EXPECT_EQ(FileExtension("dir.d/.hidden"), "");
}

TEST(CLIAtomicOutput, CommitRenamesAndAbandonRemoves)
{
  const fs::path dir = TestFolder();
  const std::string final = (dir / "Head.nii.gz").string();
  std::string temp;
  {
    AtomicOutput out(final);
    temp = out.TempPath();
    EXPECT_EQ(fs::path(temp).parent_path(), dir);
    EXPECT_EQ(temp.substr(temp.size() - 7), ".nii.gz");
    EXPECT_NE(temp, final);
    std::ofstream(out.TempPath()) << "partial";
    EXPECT_TRUE(fs::exists(temp));
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_FALSE(fs::exists(final));

  {
    AtomicOutput out(final);
    std::ofstream(out.TempPath()) << "complete";
    out.Commit();
    EXPECT_EQ(out.FinalPath(), final);
  }
  EXPECT_EQ(ReadFile(final), "complete");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);

  AtomicOutput nothingWritten((dir / "empty.vtu").string());
  EXPECT_THROW(nothingWritten.Commit(), ModuleError);
}

TEST(CLIAtomicOutput, MissingFolderIsNamed)
{
  const fs::path dir = TestFolder();
  try
  {
    AtomicOutput out((dir / "missing" / "out.vtu").string());
    FAIL() << "no exception";
  }
  catch (const ModuleError& e)
  {
    EXPECT_NE(std::string(e.what()).find((dir / "missing").string() + "' does not exist"), std::string::npos)
      << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_THROW(AtomicOutput(dir.string()), ModuleError); // a folder is not a file
}
