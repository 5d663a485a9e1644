// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Control points that contradict the anatomy are refused before they steer a registration: a model
// fitted to points 15 mm off the face, or to a head whose orientation header is wrong, is a wrong
// model that looks like a right one. Three checks, each one line naming the culprit:
//   * configuration: the similarity from the atlas's landmarks to the points, leave one out: a
//     point far from where the other four place it is mislabelled, swapped or on the wrong feature;
//     a scale far from 1 is a unit error;
//   * orientation: the face the points describe must look to the front and stand upright in LPS, as
//     the atlas's does (a CT stored turned or upside down, its points placed on the turned head);
//   * on the skin: every point within a few mm of the subject's skin surface (points clicked on the
//     skin are), which also catches points of the upright head given for a CT stored upside down.
#pragma once

#include "mmrepFEMesh.h"

#include <vtkPolyData.h>

#include <string>
#include <vector>

namespace mmrep
{

struct ControlPointBounds
{
  double leaveOneOut = 18.0; // mm a point may lie from where the other four place it
  double minScale = 0.6;     // the points' face size against the atlas's (a child to a large adult)
  double maxScale = 1.6;
  double maxTurn = 60.0;        // degrees the face may look away from the front, or tilt from upright
  double maxSkinDistance = 5.0; // mm from the skin surface
};

struct ControlPointConfiguration
{
  double scale = 1;                                   // of the similarity atlas landmarks -> points
  std::vector<double> leaveOneOut;                    // mm, per point (NaN when the other four place nothing)
  Eigen::Vector3d anterior = Eigen::Vector3d::Zero(); // where the points' face looks, LPS unit vector
  Eigen::Vector3d superior = Eigen::Vector3d::Zero(); // the points' face's up, LPS unit vector
  double turn = 0, tilt = 0;                          // degrees from the atlas's front and up
};

// The configuration of `targets` (in the order of atlas.landmarks) against the atlas's landmarks.
// Throws std::invalid_argument when the atlas's landmarks place nothing (collinear).
ControlPointConfiguration AssessControlPoints(const FEMesh& atlas, const std::vector<Point3>& targets);

// Throws std::invalid_argument with one line naming the worst point (or the orientation, or the
// scale) when the configuration is outside `bounds`.
void CheckControlPointConfiguration(const FEMesh& atlas, const std::vector<std::string>& names,
                                    const std::vector<Point3>& targets, const ControlPointBounds& bounds = {});

// Throws std::invalid_argument naming the point farthest from `skin` when it lies farther than
// bounds.maxSkinDistance.
void CheckControlPointsOnSkin(vtkPolyData* skin, const std::vector<std::string>& names,
                              const std::vector<Point3>& targets, const ControlPointBounds& bounds = {});

// The atlas face's front and up (LPS unit vectors): left is the normal of its `midsagittal` node
// set's plane, up runs from its lip landmarks to its eye landmarks within that plane. False when
// the atlas has no such landmarks or set.
bool AtlasFaceFrame(const FEMesh& atlas, Eigen::Vector3d& anterior, Eigen::Vector3d& superior);

// "the patient's left", "the front", ...: the LPS direction `d` is nearest to, in words.
std::string DirectionInWords(const Eigen::Vector3d& d);

} // namespace mmrep
