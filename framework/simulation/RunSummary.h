// SPDX-License-Identifier: MIT
// What a component has to say at the end of a run, beside the timing summary: an error against
// a reference, a count of events, a measured quantity. `stroma run` prints, after its timing
// table, the lines of every component of the scene that implements this interface, in graph
// order; other drivers (a study runner, a viewer) may show them the same way.
#pragma once

#include <string>
#include <vector>

namespace stroma {

class RunSummaryProvider {
 public:
  virtual ~RunSummaryProvider() = default;
  /// Lines to print at the end of a run (without a trailing newline), from the state the
  /// scene is in then. Empty: nothing to say.
  virtual std::vector<std::string> runSummaryLines() const = 0;
};

}  // namespace stroma
