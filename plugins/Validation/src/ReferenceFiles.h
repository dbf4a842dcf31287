// SPDX-License-Identifier: MIT
// Reading the references of ReferenceComparison: marker files (CSV of positions, such as the
// Truth Cube beads) and the positions of one state in a state file (docs/state-format.md).
// Errors name the file and the line; nothing here knows of components.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/Types.h"
#include "simulation/StateFile.h"

namespace stroma::reference {

/// Points of a marker file: one position per row, taken from the given 0-based columns of a
/// comma-separated line (blanks around commas allowed), times `scale`. Lines starting with
/// '#' and blank lines are skipped; the first other line may be a header (its first field not
/// a number). Every row must have the columns, as finite numbers.
struct MarkerColumns {
  std::array<int, 3> position{0, 1, 2};
  double scale = 1;
};

/// Reads the rows of `file` into `points` (one list per requested column set). Returns false
/// with `error` naming the file and line.
bool readMarkerFile(const std::string& file, const std::vector<MarkerColumns>& columns,
                    std::vector<std::vector<Vec3d>>& points, std::string& error);

/// The positions of the 3-D state `statePath` (or, when empty, of the only Vec3d-like state:
/// 3 numbers per position) in a snapshot. Returns false with `error` naming what is missing.
bool statePositions(const StateSnapshot& snapshot, const std::string& statePath,
                    std::vector<Vec3d>& positions, std::string& error);

/// The snapshot at `time` (within 1e-9 of max(1, |time|)); a negative time picks the last one.
/// Returns nullptr when there is none.
const StateSnapshot* findSnapshot(const std::vector<StateSnapshot>& snapshots, double time);

}  // namespace stroma::reference
