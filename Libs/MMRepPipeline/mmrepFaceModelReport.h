// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The speaker model's report: JSON for programs, Markdown for people, with the accuracy tables of
// the paper (Table 1: skin and skull, Table 2: lips after R, Q∘R and repair), the paper's figures
// beside ours, control points, element quality before and after repair, muscles, time per stage.
#pragma once

#include "mmrepFaceModelPipeline.h"

#include <string>
#include <vector>

namespace mmrep
{

struct FaceModelReportInputs
{
  std::string ct, controlPoints, atlas; // paths as given
  double repairThreshold = 0.3;
  std::vector<std::pair<std::string, std::string>> files; // output file, what it holds
};

std::string FaceModelReportJson(const FaceModelResult& result, const FaceModelReportInputs& inputs);
std::string FaceModelReportMarkdown(const FaceModelResult& result, const FaceModelReportInputs& inputs);

} // namespace mmrep
