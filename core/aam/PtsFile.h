#pragma once
// Landmark files in the .pts format of the 300-W / iBUG data and menpo:
//   version: 1
//   n_points: 68
//   {
//   x y
//   ...
//   }
// The header is optional (the shared Helen files have bare "x y" lines). Coordinates in .pts
// files are 1-based (Matlab convention of 300-W); in memory they are 0-based pixel coordinates,
// so reading subtracts 1 and writing adds 1.
#include "annotation/LandmarkSet.h"

#include <Eigen/Core>

#include <string>

namespace lipsync {

// All points of a .pts file, flat (x0, y0, x1, y1, ...), 0-based. Throws lipsync::Error naming the
// file and line for non-numbers, NaN/inf, a header count that disagrees with the points, no points.
Eigen::VectorXd readPtsFile(const std::string &path);
// Parses .pts text; `path` only names the source in errors.
Eigen::VectorXd parsePts(const std::string &text, const std::string &path = {});

// A 23-point face: 23-point files as they are, 68-point (iBUG) files mapped to 23. Throws for any
// other count. The points get `state`.
Eigen::VectorXd readFaceShape(const std::string &path);
LandmarkSet readLandmarkSet(const std::string &path, PointState state = PointState::Placed);

// Writes flat 0-based points atomically, with or without the version/n_points/{ } header.
void writePtsFile(const std::string &path, const Eigen::VectorXd &points, bool header = true);
std::string formatPts(const Eigen::VectorXd &points, bool header = true);
// Throws if a point of the set is Undefined (the format cannot say "not placed").
void writeLandmarkSet(const std::string &path, const LandmarkSet &set, bool header = true);

// Conversions between LandmarkSet and a flat shape (undefined points become 0,0).
Eigen::VectorXd shapeFromLandmarkSet(const LandmarkSet &set);
LandmarkSet landmarkSetFromShape(const Eigen::VectorXd &shape, PointState state);

} // namespace lipsync
