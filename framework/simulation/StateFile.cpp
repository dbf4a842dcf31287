// SPDX-License-Identifier: MIT
#include "simulation/StateFile.h"

#include <cstdio>
#include <istream>
#include <locale>
#include <ostream>
#include <sstream>

#include "core/BaseState.h"
#include "core/DataTraits.h"
#include "core/Node.h"
#include "simulation/Visitor.h"

namespace stroma {

namespace {

class CaptureVisitor final : public Visitor {
 public:
  explicit CaptureVisitor(StateSnapshot& snapshot) : m_snapshot(snapshot) {}
  Result processNodeTopDown(Node& node) override {
    for (const BaseState* state : node.getAll<BaseState>()) {
      StateRecord r;
      r.path = state->path();
      r.templateName = state->templateName();
      r.coordDimension = state->coordDimension();
      r.derivDimension = state->derivDimension();
      state->copyPositions(r.positions);
      state->copyVelocities(r.velocities);
      m_snapshot.states.push_back(std::move(r));
    }
    return Result::carryOn;
  }
  std::string_view name() const override { return "captureState"; }

 private:
  StateSnapshot& m_snapshot;
};

void writeNumber(std::ostream& out, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  out << buffer;
}

}  // namespace

StateSnapshot captureState(const Node& root, long long step) {
  StateSnapshot snapshot;
  snapshot.time = root.time();
  snapshot.step = step;
  CaptureVisitor visitor(snapshot);
  traverse(const_cast<Node&>(root), visitor);
  return snapshot;
}

void writeStateHeader(std::ostream& out) { out << "# stroma-state 1\n"; }

void writeSnapshot(std::ostream& out, const StateSnapshot& snapshot) {
  // The format is the same whatever the stream's locale (no digit grouping in counts).
  const std::locale previous = out.imbue(std::locale::classic());
  out << "snapshot time ";
  writeNumber(out, snapshot.time);
  out << " step " << snapshot.step << '\n';
  for (const StateRecord& r : snapshot.states) {
    const std::size_t n = r.count();
    out << "state " << r.path << ' ' << (r.templateName.empty() ? "-" : r.templateName) << ' '
        << n << ' ' << r.coordDimension << ' ' << r.derivDimension << '\n';
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < r.coordDimension; ++k) {
        if (k) out << ' ';
        writeNumber(out, r.positions[i * r.coordDimension + k]);
      }
      for (int k = 0; k < r.derivDimension; ++k) {
        out << ' ';
        const std::size_t index = i * r.derivDimension + k;
        writeNumber(out, index < r.velocities.size() ? r.velocities[index] : 0.0);
      }
      out << '\n';
    }
  }
  for (const DataRecord& d : snapshot.data)
    out << "data " << d.name << " [" << d.typeName << "] " << d.text << '\n';
  out << "end\n";
  out.imbue(previous);
}

bool readStateFile(std::istream& in, std::vector<StateSnapshot>& snapshots, std::string& error) {
  snapshots.clear();
  std::string line;
  int lineNumber = 0;
  auto fail = [&](const std::string& what) {
    error = "line " + std::to_string(lineNumber) + ": " + what;
    return false;
  };
  StateSnapshot* current = nullptr;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    words.imbue(std::locale::classic());
    std::string key;
    words >> key;
    if (key == "snapshot") {
      std::string timeWord, stepWord;
      StateSnapshot s;
      if (!(words >> timeWord >> s.time >> stepWord >> s.step) || timeWord != "time" ||
          stepWord != "step")
        return fail("expected 'snapshot time T step S'");
      snapshots.push_back(std::move(s));
      current = &snapshots.back();
    } else if (key == "state") {
      if (!current) return fail("'state' before any 'snapshot'");
      StateRecord r;
      std::size_t n = 0;
      if (!(words >> r.path >> r.templateName >> n >> r.coordDimension >> r.derivDimension) ||
          r.coordDimension < 0 || r.derivDimension < 0 || n > 100000000)
        return fail("expected 'state PATH TEMPLATE COUNT COORD_DIM DERIV_DIM'");
      if (r.templateName == "-") r.templateName.clear();
      // Rows are appended as read, so a corrupt count cannot allocate ahead of the data.
      const std::string expected =
          "expected " + std::to_string(r.coordDimension + r.derivDimension) + " numbers";
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::getline(in, line)) return fail("state " + r.path + " ends early");
        ++lineNumber;
        TokenReader numbers(line);  // locale independent; reads nan and inf back
        if (numbers.remaining() != static_cast<std::size_t>(r.coordDimension + r.derivDimension))
          return fail(expected);
        std::string why;
        for (int k = 0; k < r.coordDimension + r.derivDimension; ++k) {
          double value = 0;
          if (!ElementTraits<double>::parseTokens(numbers, value, why)) return fail(expected);
          (k < r.coordDimension ? r.positions : r.velocities).push_back(value);
        }
      }
      current->states.push_back(std::move(r));
    } else if (key == "data") {
      if (!current) return fail("'data' before any 'snapshot'");
      DataRecord d;
      // The type name may hold spaces ("list of Rigid3d derivative"): it is in brackets.
      if (!(words >> d.name) || !(words >> std::ws) || words.get() != '[' ||
          !std::getline(words, d.typeName, ']'))
        return fail("expected 'data PATH.field [TYPE] VALUE'");
      std::getline(words >> std::ws, d.text);
      current->data.push_back(std::move(d));
    } else if (key == "end") {
      current = nullptr;
    } else {
      return fail("unknown line '" + key + "'");
    }
  }
  return true;
}

}  // namespace stroma
