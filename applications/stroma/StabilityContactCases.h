// SPDX-License-Identifier: MIT
// What the stability suite's beam cases (StabilityCommand.cpp) and contact cases
// (StabilityContactCases.cpp) share: how a case ended, how that is read from the log, how its
// scene file is named.
#pragma once

#include <cmath>
#include <functional>
#include <string>

namespace stroma {
class MessageLog;
class Runtime;
}  // namespace stroma

namespace stroma::cli {

/// How one case of the stability suite ended.
struct StabilityOutcome {
  std::string status, reason;
  long long steps = 0;
  double maxDisplacement = 0, tipRatio = NAN, criticalDt = NAN, wallSeconds = 0;
  double penetration = NAN;  ///< contact cases: the deepest interpenetration at the end (m)
};

/// The status, the worst first: diverged (a value not finite or an energy growth reported, or
/// `unbounded` says why the case's own check failed), refused (a time step above a stability
/// bound), stalled (a stalled Newton iteration or an unconverged linear solve), error, stable;
/// the reason is the message (or `unbounded`).
void classifyOutcome(const MessageLog& log, const std::string& unbounded, StabilityOutcome& out);

/// "corotational-tetrahedra-large_central-differences_dt-1.scn": a case's scene for
/// --save-scenes, to rerun it with `stroma run` (value "-": none).
std::string stabilityCaseFileName(const std::string& model, const std::string& solver,
                                  const std::string& caseName, const std::string& value);

/// Receives each row of the suite: model, solver, case, value, outcome.
using StabilityReport =
    std::function<void(const std::string&, const std::string&, const std::string&,
                       const std::string&, const StabilityOutcome&)>;

/// Contact cases: each contact response (penalty forces, Lagrangian constraints) with implicit
/// Euler and CG or LDL^T, on soft hexahedral boxes above a fixed floor: an impact at 10 m/s, a
/// stiff box on a soft one, a stack, a thin sheet pressed flat. Saves each case's scene in
/// `sceneDir` when given. Returns the rows reported; none, with a line saying why, when this
/// build has no Collision plugin.
int runContactCases(Runtime& runtime, bool quick, const std::string* sceneDir,
                    const StabilityReport& report);

}  // namespace stroma::cli
