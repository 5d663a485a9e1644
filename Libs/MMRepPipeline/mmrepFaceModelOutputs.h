// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The files of a speaker model run, written into one (staging) directory: the FE model in every format, the
// optional half model, the displacement field atlas -> speaker, the surfaces, the landmarks, the pictures, the
// report, the intermediates; and the run's one-line summary and failure message.
#pragma once

#include "mmrepFaceModelPipeline.h"
#include "mmrepFaceModelReport.h"

#include <filesystem>
#include <functional>
#include <string>

namespace mmrep
{

struct FaceModelOutputOptions
{
  bool pictures = true;          // model-skin-error.png, lips.png, muscles.png (needs a display)
  bool halfModel = false;        // half-model.vtu/.inp/.feb/.msh
  bool intermediates = false;    // registered.vtu, refined.vtu
  double transformSpacing = 2.0; // mm, grid of transform.nrrd
  FaceModelReportInputs report;  // its `files` are filled by WriteFaceModelOutputs
};

// Writes every output into `directory`; `progress(f)` gets f in [0, 1] between the groups of files.
void WriteFaceModelOutputs(const FaceModelResult& result, const FEMesh& atlas, FaceModelOutputOptions options,
                           const std::filesystem::path& directory, const std::function<void(double)>& progress = {});

// Why a run whose repair failed publishes nothing: the count and the five worst elements.
std::string RepairFailureMessage(const FaceModelResult& result, double qualityThreshold,
                                 const std::filesystem::path& finalDirectory);

// Mean control-point error of the final model (mm).
double ControlPointMeanError(const FaceModelResult& result);

// What the module prints at the end: model size, accuracy of the fitted half and of the whole model.
std::string FaceModelSummary(const FaceModelResult& result);

} // namespace mmrep
