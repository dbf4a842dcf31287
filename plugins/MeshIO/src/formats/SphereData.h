// SPDX-License-Identifier: MIT
// Sphere files (.sph, SOFA's format for sphere collision models): parse their bytes into
// centers and radii, free of components.
//
// The format, as the files of SOFA's share/mesh write it:
//   sph 1.0                       the header, on the first line
//   # a comment                   anywhere, also after the values of a line
//   nums 27                       optional: how many spheres follow (checked)
//   sphe 1 -1.75 -1.75 0.0 2.5    a sphere: its index, center x y z, radius
// Blank lines are skipped; lines end with LF or CRLF. The index is read (an integer) and not
// used: SOFA's files repeat it (liver.sph numbers every sphere 1), spheres are numbered in file
// order.
//
// parseSpheres() never throws for bad input and never reads out of bounds. Every failure gives
// false and an error "line N: ..." naming the field of the line that is wrong: a header other
// than 'sph 1.0', a keyword other than sphe, nums or a comment, a sphe line without exactly 5
// numbers, an index that is not an integer, a coordinate or radius that is not a finite number,
// a negative radius, a second nums line or one that disagrees with the spheres present, no
// sphere at all, an empty file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/Types.h"

namespace stroma {

/// What a sphere file holds: one center and one radius per sphere, in file order.
struct SphereData {
  std::vector<Vec3d> centers;
  std::vector<double> radii;  ///< finite and >= 0, one per center
};

/// Parses the bytes of a .sph file. On failure returns false, leaves `spheres` empty and sets
/// `error` ("line 4: expected the radius of the sphere, a finite number >= 0, got 'x'").
bool parseSpheres(std::string_view bytes, SphereData& spheres, std::string& error);

/// Reads a whole .sph file and parses it. Errors also cover a missing or unreadable file.
bool readSphereFile(const std::string& path, SphereData& spheres, std::string& error);

}  // namespace stroma
