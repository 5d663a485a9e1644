// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// SyntheticSubject module: the image, both fields and the moved landmarks against the library, and
// failures (missing file, rotation above 15°, unpaired landmark options) without output.
#include "mmrepLandmarkIO.h"
#include "mmrepModuleRunner.h"
#include "mmrepSyntheticSubject.h"

#include <gtest/gtest.h>
#include <itkImageRegionConstIteratorWithIndex.h>

#include <cmath>

namespace
{
using mmrep::testing::RunModuleExecutable;
using mmrep::testing::ScratchDirectory;
const std::string kSource = std::string(MMREP_SAMPLE_DATA) + "/headsq.nrrd";
} // namespace

TEST(SyntheticSubjectModule, WritesImageFieldsAndLandmarks)
{
  ScratchDirectory dir("SyntheticSubjectModule");
  std::vector<mmrep::Landmark> in = {{"nose", {5, -90, 40}}, {"chin", {0, -70, -20}}, {"earL", {70, 0, 10}}};
  mmrep::WriteLandmarks(in, dir / "in.mrk.json");
  const auto run = RunModuleExecutable("SyntheticSubject", {kSource,
                                                            dir / "subject.nrrd",
                                                            "--roll",
                                                            "-12",
                                                            "--yaw",
                                                            "7",
                                                            "--pitch",
                                                            "3",
                                                            "--translation",
                                                            "2,5,-4",
                                                            "--seed",
                                                            "42",
                                                            "--forwardField",
                                                            dir / "fwd.nrrd",
                                                            "--inverseField",
                                                            dir / "inv.mha",
                                                            "--landmarksIn",
                                                            dir / "in.mrk.json",
                                                            "--landmarksOut",
                                                            dir / "out.fcsv",
                                                            "--returnparameterfile",
                                                            dir / "ret.txt"});
  ASSERT_EQ(run.exitCode, 0) << run.err;

  mmrep::SyntheticWarpParameters p;
  p.rollDegrees = -12;
  p.yawDegrees = 7;
  p.pitchDegrees = 3;
  p.translation = {2, 5, -4};
  p.seed = 42;
  const auto source = mmrep::ReadCTImage(kSource);
  mmrep::FitWarpToImage(p, source);
  const mmrep::SyntheticWarp warp(p);

  // Image: identical to the library's resampling.
  const auto expected = mmrep::ResampleSyntheticSubject(source, warp);
  const auto subject = mmrep::ReadCTImage(dir / "subject.nrrd");
  ASSERT_EQ(subject->GetLargestPossibleRegion().GetSize(), source->GetLargestPossibleRegion().GetSize());
  const std::size_t n = source->GetLargestPossibleRegion().GetNumberOfPixels();
  std::size_t differing = 0;
  for (std::size_t i = 0; i < n; ++i)
    differing += subject->GetBufferPointer()[i] != expected->GetBufferPointer()[i];
  EXPECT_EQ(differing, 0u);
  // It differs from the source (the head moved).
  std::size_t moved = 0;
  for (std::size_t i = 0; i < n; ++i)
    moved += std::abs(subject->GetBufferPointer()[i] - source->GetBufferPointer()[i]) > 100;
  EXPECT_GT(moved, n / 50);

  // Fields: F(x) - x on the source grid, G(y) - y on the subject grid.
  const auto fwd = mmrep::ReadDisplacementField(dir / "fwd.nrrd");
  const auto inv = mmrep::ReadDisplacementField(dir / "inv.mha");
  double worstF = 0, worstG = 0;
  for (itk::ImageRegionConstIteratorWithIndex<mmrep::DisplacementField> it(fwd, fwd->GetLargestPossibleRegion());
       !it.IsAtEnd(); ++it)
  {
    if ((it.GetIndex()[0] + it.GetIndex()[1] + it.GetIndex()[2]) % 37 != 0)
      continue;
    itk::Point<double, 3> pt;
    source->TransformIndexToPhysicalPoint(it.GetIndex(), pt);
    const Eigen::Vector3d x(pt[0], pt[1], pt[2]);
    const auto d = it.Get();
    const auto e = inv->GetPixel(it.GetIndex());
    worstF = std::max(worstF, (x + Eigen::Vector3d(d[0], d[1], d[2]) - warp.Forward(x)).norm());
    worstG = std::max(worstG, (x + Eigen::Vector3d(e[0], e[1], e[2]) - warp.Inverse(x)).norm());
  }
  EXPECT_LT(worstF, 1e-3);
  EXPECT_LT(worstG, 1e-3);
  EXPECT_EQ(fwd->GetSpacing(), source->GetSpacing());
  EXPECT_EQ(inv->GetOrigin(), source->GetOrigin());

  // Landmarks moved by F, names and order kept.
  const auto out = mmrep::ReadLandmarks(dir / "out.fcsv");
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    EXPECT_EQ(out[i].name, in[i].name);
    EXPECT_LT((out[i].position - warp.Forward(in[i].position)).norm(), 1e-3);
    EXPECT_GT((out[i].position - in[i].position).norm(), 1.0);
  }
  const auto values = mmrep::testing::ReadReturnParameters(dir / "ret.txt");
  EXPECT_NEAR(std::stod(values.at("gradientBound")), warp.GradientBound(), 1e-12);
  EXPECT_GT(std::stod(values.at("jacobianLowerBound")), 0.5);
}

TEST(SyntheticSubjectModule, BadInputFailsWithOneLineAndNoOutput)
{
  ScratchDirectory dir("SyntheticSubjectModuleBad");
  const std::vector<std::vector<std::string>> cases = {
    {dir / "missing.nrrd", dir / "subject.nrrd", "--forwardField", dir / "fwd.nrrd"},
    {kSource, dir / "subject.nrrd", "--roll", "16", "--forwardField", dir / "fwd.nrrd"},
    {kSource, dir / "subject.nrrd", "--yaw", "-20"},
    {kSource, dir / "subject.nrrd", "--landmarksIn", dir / "in.mrk.json"},
    {kSource, dir / "subject.nrrd", "--warpAmplitude", "10"}, // gradient bound above 0.2
  };
  for (const auto& args : cases)
  {
    const auto run = RunModuleExecutable("SyntheticSubject", args);
    EXPECT_NE(run.exitCode, 0) << args[2];
    ASSERT_EQ(run.ErrLines().size(), 1u) << run.err;
    EXPECT_TRUE(dir.Entries().empty()) << run.err;
  }
}
