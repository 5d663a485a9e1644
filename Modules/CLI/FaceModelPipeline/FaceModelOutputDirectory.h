// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// An output directory that appears only when complete: files are written into a staging
// directory beside it, which replaces the final one on Commit(); without Commit (an error) the
// staging directory is removed, so no partial result is ever presented.
#pragma once

#include <filesystem>
#include <string>

class FaceModelOutputDirectory
{
public:
  explicit FaceModelOutputDirectory(const std::string& path); // throws ModuleError if not creatable
  ~FaceModelOutputDirectory();
  FaceModelOutputDirectory(const FaceModelOutputDirectory&) = delete;
  FaceModelOutputDirectory& operator=(const FaceModelOutputDirectory&) = delete;
  const std::filesystem::path& StagingPath() const { return staging_; }
  const std::filesystem::path& FinalPath() const { return final_; }
  void Commit(); // throws ModuleError if the rename fails

private:
  static void Publish(const std::filesystem::path& final, const std::filesystem::path& staging);
  std::filesystem::path final_, staging_;
  std::filesystem::path createdParent_; // outermost parent folder this run created (empty: none)
  bool committed_ = false;
};
