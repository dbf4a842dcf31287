// SPDX-License-Identifier: MIT
// State files: the positions and velocities of every mechanical state of a scene, by node
// path, at one or several times. Plain text so that other tools and other engines can write and
// compare them; docs/state-format.md is the specification.
//
//   # stroma-state 1
//   snapshot time 0.01 step 1
//   state /root/Particles/dofs Vec3d 2 3 3
//   0 1 0 0 -0.098100000000000007 0
//   1 1 0 0 -0.098100000000000007 0
//   end
//
// Each state line gives: path, template, count n, numbers per position, numbers per velocity;
// n lines follow with the position then the velocity of one degree of freedom. Numbers are
// written with 17 significant digits, so a file read back gives the same doubles. Data asked
// for follow the states, one line each: "data PATH.field [TYPE] VALUE...".
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace stroma {

class Node;

struct StateRecord {
  std::string path;
  std::string templateName;
  int coordDimension = 0;
  int derivDimension = 0;
  std::vector<double> positions;   ///< count * coordDimension
  std::vector<double> velocities;  ///< count * derivDimension
  std::size_t count() const {
    return coordDimension ? positions.size() / static_cast<std::size_t>(coordDimension) : 0;
  }
};

/// A Data written beside the states (`stroma run --export-data PATH.field`): its full name, its
/// type and its value as a scene attribute would write it.
struct DataRecord {
  std::string name;
  std::string typeName;
  std::string text;
};

struct StateSnapshot {
  double time = 0;
  long long step = 0;
  std::vector<StateRecord> states;
  std::vector<DataRecord> data;
};

/// The states of every BaseState under `root`, in graph order.
StateSnapshot captureState(const Node& root, long long step);

/// Writes the header line once, then snapshots with writeSnapshot.
void writeStateHeader(std::ostream& out);
void writeSnapshot(std::ostream& out, const StateSnapshot& snapshot);

/// Reads a whole state file. Returns false with `error` naming the line on a malformed file.
bool readStateFile(std::istream& in, std::vector<StateSnapshot>& snapshots, std::string& error);

}  // namespace stroma
