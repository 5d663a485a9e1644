// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// ToolkitMessage on the texts ITK 5.2, VTK 9.1 and MetaIO really produce (taken from their output
// for a truncated NRRD, an unknown MetaImage type, a short MetaImage block and a cut .vtp).
#include "mmrepToolkitMessage.h"

#include <gtest/gtest.h>

TEST(ToolkitMessage, NrrdStackGivesTheInnermostReason)
{
  const std::string itk = "ITK ERROR: NrrdImageIO(0x55a8f24b72e0): Read: Error reading trunc.nrrd:\n"
                          "[nrrd] nrrdLoad: trouble reading \"trunc.nrrd\"\n[nrrd] nrrdRead: trouble\n"
                          "[nrrd] _nrrdRead: trouble reading NRRD file\n[nrrd] _nrrdFormatNRRD_read:\n"
                          "[nrrd] _nrrdEncodingGzip_read: expected 14811136 bytes but received 13066\n";
  EXPECT_EQ(mmrep::ToolkitMessage(itk), "Error reading trunc.nrrd: expected 14811136 bytes but received 13066");
  // what() also carries the source location.
  EXPECT_EQ(mmrep::ToolkitMessage("./Modules/IO/NRRD/src/itkNrrdImageIO.cxx:769:\n" + itk),
            "Error reading trunc.nrrd: expected 14811136 bytes but received 13066");
}

TEST(ToolkitMessage, ItkAddressAndEnumNamesRemoved)
{
  EXPECT_EQ(mmrep::ToolkitMessage("ITK ERROR: MetaImageIO(0x560729bd5e20): Unknown component type: "
                                  "itk::CommonEnums::IOComponent::UNKNOWNCOMPONENTTYPE"),
            "Unknown component type: UNKNOWNCOMPONENTTYPE");
  EXPECT_EQ(mmrep::ToolkitMessage("itk::ERROR: ResampleImageFilter(0x7ffd12345678): Input image not set"),
            "Input image not set");
}

TEST(ToolkitMessage, VtkLocationAndObjectRemoved)
{
  EXPECT_EQ(mmrep::ToolkitMessage("ERROR: In /build/vtk9-1/IO/XML/vtkXMLPolyDataReader.cxx, line 123\n"
                                  "vtkXMLPolyDataReader (0x557ff69be2f0): Cannot read points array from Points in "
                                  "piece 0.\n\n"),
            "Cannot read points array from Points in piece 0.");
}

TEST(ToolkitMessage, MetaIOLinesJoined)
{
  EXPECT_EQ(mmrep::ToolkitMessage("MetaImage: M_ReadElementsData: data not read completely\n"
                                  "   ideal = 761856 : actual = 99447\n"),
            "data not read completely; ideal = 761856 : actual = 99447");
}

TEST(ToolkitMessage, PlainTextKeptAndEmptyNamed)
{
  EXPECT_EQ(mmrep::ToolkitMessage("requested itk failure"), "requested itk failure");
  EXPECT_EQ(mmrep::ToolkitMessage("\n \n"), "unknown toolkit error");
}
