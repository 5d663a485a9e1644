// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Damaged PLY, STL and VTK XML files against ReadSurface: truncated at many lengths, bytes flipped, counts
// that no file holds, faces naming vertices that do not exist. Each either reads as a valid
// surface (every face index within the points) or throws std::runtime_error naming the file; none
// may crash this process or take long (vtkPLYReader crashed on truncated files before the checks).
#include "mmrepSurfaceIO.h"
#include "mmrepTestDir.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <regex>

namespace
{
namespace fs = std::filesystem;

using mmrep::test::ReadBytes;
using mmrep::test::WriteBytes;

// Reads `path`: "" when it gives a valid surface, the error text when it throws.
std::string Outcome(const fs::path& path)
{
  try
  {
    const auto s = mmrep::ReadSurface(path.string());
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < s->GetNumberOfCells(); ++c)
    {
      s->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        EXPECT_LT(ids->GetId(k), s->GetNumberOfPoints()) << path;
    }
    return {};
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << e.what();
    return e.what();
  }
}

fs::path Sphere(const fs::path& dir, const std::string& name)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  sphere->Update();
  const fs::path p = dir / name;
  mmrep::WriteSurface(sphere->GetOutput(), p.string());
  return p;
}

TEST(SurfaceFuzz, TruncatedFlippedAndOverCountedFilesNeverCrash)
{
  const fs::path dir = mmrep::test::ScratchDir();
  const auto start = std::chrono::steady_clock::now();
  std::string asciiPly = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 3\n";
  WriteBytes(dir / "ascii.ply", asciiPly);
  for (const fs::path& whole : {Sphere(dir, "sphere.ply"), Sphere(dir, "sphere.stl"), dir / "ascii.ply"})
  {
    ASSERT_EQ(Outcome(whole), "") << whole;
    const std::string bytes = ReadBytes(whole);
    // Truncated: 24 lengths from the first byte to one short of the whole.
    for (int cut = 0; cut < 24; ++cut)
    {
      const std::size_t length = bytes.size() * static_cast<std::size_t>(cut) / 24 + (cut == 23 ? 0 : 1);
      const fs::path p = dir / ("cut-" + std::to_string(cut) + whole.extension().string());
      WriteBytes(p, bytes.substr(0, std::min(length, bytes.size() - 1)));
      EXPECT_NE(Outcome(p), "") << p << " of " << length << " bytes was read";
    }
    // Flipped bytes (every 37th past the first 100): valid or refused, never a crash.
    for (std::size_t at = 100; at < bytes.size(); at += 37)
    {
      std::string flipped = bytes;
      flipped[at] = static_cast<char>(~flipped[at]);
      const fs::path p = dir / ("flip" + whole.extension().string());
      WriteBytes(p, flipped);
      Outcome(p);
    }
  }
  // VTK XML (.vtp, appended and compressed as the project writes it): cut or flipped, read as a valid
  // surface or refused; a cut in the closing tags alone may still hold the whole surface.
  {
    const fs::path whole = Sphere(dir, "sphere.vtp");
    const std::string bytes = ReadBytes(whole);
    for (int k = 0; k < 40; ++k)
    {
      std::string flipped = bytes;
      flipped[bytes.size() * static_cast<std::size_t>(k) / 40] ^= 0x5a;
      WriteBytes(dir / "flip.vtp", flipped);
      Outcome(dir / "flip.vtp");
      WriteBytes(dir / "cut.vtp", bytes.substr(0, bytes.size() * static_cast<std::size_t>(k) / 40));
      const bool closingTagsOnly = bytes.size() * static_cast<std::size_t>(k) / 40 > bytes.rfind("</AppendedData>");
      if (!closingTagsOnly)
        EXPECT_NE(Outcome(dir / "cut.vtp"), "") << "a .vtp cut at " << k << "/40 was read";
    }
  }
  // Counts no file holds, and faces naming vertices that do not exist.
  WriteBytes(dir / "huge.ply",
             std::regex_replace(asciiPly, std::regex("element vertex 4"), "element vertex 1000000000000"));
  EXPECT_NE(Outcome(dir / "huge.ply").find("truncated PLY: the header declares more data"), std::string::npos);
  WriteBytes(dir / "badface.ply", std::regex_replace(asciiPly, std::regex("3 0 2 3\n"), "3 0 2 9\n"));
  EXPECT_NE(Outcome(dir / "badface.ply").find("PLY face 1 refers to vertex 9"), std::string::npos);
  std::string binary = ReadBytes(dir / "sphere.ply");
  WriteBytes(dir / "hugebinary.ply",
             std::regex_replace(binary, std::regex("element face [0-9]+"), "element face 999999999"));
  EXPECT_NE(Outcome(dir / "hugebinary.ply").find("truncated PLY"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
}

} // namespace
