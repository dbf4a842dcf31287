// SPDX-License-Identifier: MIT
// State files (docs/state-format.md): written snapshots read back to the same doubles, bit for
// bit; states captured from a graph in graph order; malformed files refused with the line.
#include "simulation/StateFile.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <locale>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/BaseState.h"
#include "core/Node.h"

namespace stroma {
namespace {

// A set of degrees of freedom with given dimensions and numbers.
class TestState final : public BaseState {
 public:
  TestState(std::string name, std::string templateName, int coordDim, int derivDim,
            std::vector<double> positions, std::vector<double> velocities)
      : m_coordDim(coordDim),
        m_derivDim(derivDim),
        m_positions(std::move(positions)),
        m_velocities(std::move(velocities)) {
    setName(std::move(name));
    setClassName("MechanicalObject", std::move(templateName));
  }
  std::size_t size() const override { return m_positions.size() / m_coordDim; }
  int coordDimension() const override { return m_coordDim; }
  int derivDimension() const override { return m_derivDim; }
  void copyPositions(std::vector<double>& out) const override { out = m_positions; }
  void copyVelocities(std::vector<double>& out) const override { out = m_velocities; }

 private:
  int m_coordDim;
  int m_derivDim;
  std::vector<double> m_positions;
  std::vector<double> m_velocities;
};

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  return true;
}

StateRecord record(std::string path, std::string templateName, int coordDim, int derivDim,
                   std::vector<double> positions, std::vector<double> velocities) {
  StateRecord r;
  r.path = std::move(path);
  r.templateName = std::move(templateName);
  r.coordDimension = coordDim;
  r.derivDimension = derivDim;
  r.positions = std::move(positions);
  r.velocities = std::move(velocities);
  return r;
}

// Numbers that a careless writer or reader would change.
StateSnapshot awkwardSnapshot() {
  StateSnapshot s;
  s.time = 0.1 + 0.2;
  s.step = 3;
  s.states.push_back(record("/root/Liver/dofs", "Vec3d", 3, 3,
                            {0.1, 1.0 / 3.0, 1e-300, -0.0, 5e-324, DBL_MAX},
                            {-DBL_MIN, std::nextafter(1.0, 2.0), std::numbers::pi, 1e22,
                             123456789012345678.0, -2.5e-310}));
  s.states.push_back(record("/root/Tool/frame", "Rigid3d", 7, 6,
                            {1, 2, 3, 0, 0, std::sqrt(0.5), std::sqrt(0.5)},
                            {0.01, 0, 0, 0, 0, -1.0 / 7.0}));
  return s;
}

std::string written(const std::vector<StateSnapshot>& snapshots) {
  std::ostringstream out;
  writeStateHeader(out);
  for (const auto& s : snapshots) writeSnapshot(out, s);
  return out.str();
}

std::vector<StateSnapshot> readBack(const std::string& text) {
  std::istringstream in(text);
  std::vector<StateSnapshot> snapshots;
  std::string error;
  EXPECT_TRUE(readStateFile(in, snapshots, error)) << error << "\n" << text;
  return snapshots;
}

std::string readError(const std::string& text) {
  std::istringstream in(text);
  std::vector<StateSnapshot> snapshots;
  std::string error;
  EXPECT_FALSE(readStateFile(in, snapshots, error)) << text;
  return error;
}

void expectSame(const StateSnapshot& a, const StateSnapshot& b) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.time), std::bit_cast<std::uint64_t>(b.time));
  EXPECT_EQ(a.step, b.step);
  ASSERT_EQ(a.states.size(), b.states.size());
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    const StateRecord& x = a.states[i];
    const StateRecord& y = b.states[i];
    EXPECT_EQ(x.path, y.path);
    EXPECT_EQ(x.templateName, y.templateName);
    EXPECT_EQ(x.coordDimension, y.coordDimension);
    EXPECT_EQ(x.derivDimension, y.derivDimension);
    EXPECT_EQ(x.count(), y.count());
    EXPECT_TRUE(sameBits(x.positions, y.positions)) << x.path;
    EXPECT_TRUE(sameBits(x.velocities, y.velocities)) << x.path;
  }
}

TEST(StateFile, WritesTheDocumentedLayout) {
  StateSnapshot s;
  s.time = 0.25;
  s.step = 1;
  s.states.push_back(
      record("/root/Particles/dofs", "Vec3d", 3, 3, {0, 1, 0, 1, 0, 0}, {0, -0.5, 0, 0, 0, 0}));
  EXPECT_EQ(written({s}),
            "# stroma-state 1\n"
            "snapshot time 0.25 step 1\n"
            "state /root/Particles/dofs Vec3d 2 3 3\n"
            "0 1 0 0 -0.5 0\n"
            "1 0 0 0 0 0\n"
            "end\n");
}

TEST(StateFile, ReadBackGivesBitIdenticalDoubles) {
  const StateSnapshot s = awkwardSnapshot();
  const auto back = readBack(written({s}));
  ASSERT_EQ(back.size(), 1u);
  expectSame(s, back[0]);
  EXPECT_EQ(back[0].states[0].count(), 2u);
  EXPECT_EQ(back[0].states[1].count(), 1u);
  EXPECT_TRUE(std::signbit(back[0].states[0].positions[3]));  // -0.0 stays negative
}

TEST(StateFile, SeveralSnapshotsInOneFile) {
  StateSnapshot first = awkwardSnapshot();
  StateSnapshot second = awkwardSnapshot();
  second.time = 0.6;
  second.step = 60;
  second.states[0].positions[0] = -0.1;
  StateSnapshot empty;
  empty.time = 1e-3;
  empty.step = 123456789012LL;
  const auto back = readBack(written({first, second, empty}));
  ASSERT_EQ(back.size(), 3u);
  expectSame(first, back[0]);
  expectSame(second, back[1]);
  expectSame(empty, back[2]);
}

TEST(StateFile, UntemplatedAndEmptyStates) {
  StateSnapshot s;
  s.states.push_back(record("/root/points", "", 2, 0, {1, 2, 3, 4}, {}));
  s.states.push_back(record("/root/none", "Vec3d", 3, 3, {}, {}));
  const std::string text = written({s});
  EXPECT_NE(text.find("state /root/points - 2 2 0\n1 2\n3 4\n"), std::string::npos) << text;
  EXPECT_NE(text.find("state /root/none Vec3d 0 3 3\nend\n"), std::string::npos) << text;
  const auto back = readBack(text);
  ASSERT_EQ(back.size(), 1u);
  expectSame(s, back[0]);
}

TEST(StateFile, MissingVelocitiesAreWrittenAsZero) {
  StateSnapshot s;
  s.states.push_back(record("/root/dofs", "Vec3d", 3, 3, {1, 2, 3}, {}));
  const auto back = readBack(written({s}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].states[0].velocities, (std::vector<double>{0, 0, 0}));
}

TEST(StateFile, CommentsAndBlankLinesAreIgnored) {
  const auto back = readBack(
      "# stroma-state 1\n\n# a comment\nsnapshot time 0.5 step 2\n\nstate /a Vec3d 1 3 3\n"
      "1 2 3 4 5 6\nend\n");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].time, 0.5);
  EXPECT_EQ(back[0].step, 2);
  EXPECT_EQ(back[0].states[0].positions, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(back[0].states[0].velocities, (std::vector<double>{4, 5, 6}));
  EXPECT_TRUE(readBack("").empty());
}

TEST(StateFile, DataLinesAreReadBackAsWritten) {
  StateSnapshot s;
  s.step = 2;
  s.data.push_back({"/root/Probe/dofs.constraintForce", "list of Rigid3d derivative",
                    "0 0 1.5 0 0 -0.25"});
  const std::string text = written({s});
  EXPECT_NE(text.find("data /root/Probe/dofs.constraintForce [list of Rigid3d derivative] 0 0 "
                      "1.5 0 0 -0.25\n"),
            std::string::npos)
      << text;
  const auto back = readBack(text);
  ASSERT_EQ(back.size(), 1u);
  ASSERT_EQ(back[0].data.size(), 1u);
  EXPECT_EQ(back[0].data[0].name, s.data[0].name);
  EXPECT_EQ(back[0].data[0].typeName, s.data[0].typeName);
  EXPECT_EQ(back[0].data[0].text, s.data[0].text);
  EXPECT_EQ(readError("snapshot time 0 step 0\ndata /a.b list 1 2\n"),
            "line 2: expected 'data PATH.field [TYPE] VALUE'");
  EXPECT_EQ(readError("data /a.b [real] 1\n"), "line 1: 'data' before any 'snapshot'");
}

TEST(StateFile, MalformedFilesNameTheLine) {
  EXPECT_EQ(readError("# stroma-state 1\nsnapshot time x step 1\n"),
            "line 2: expected 'snapshot time T step S'");
  EXPECT_EQ(readError("snapshot at 0 step 1\n"), "line 1: expected 'snapshot time T step S'");
  EXPECT_EQ(readError("snapshot time 0\n"), "line 1: expected 'snapshot time T step S'");
  EXPECT_EQ(readError("# stroma-state 1\nstate /a Vec3d 1 3 3\n"),
            "line 2: 'state' before any 'snapshot'");
  EXPECT_EQ(readError("snapshot time 0 step 0\nend\nstate /a Vec3d 1 3 3\n"),
            "line 3: 'state' before any 'snapshot'");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d two 3 3\n"),
            "line 2: expected 'state PATH TEMPLATE COUNT COORD_DIM DERIV_DIM'");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 1 -3 3\n"),
            "line 2: expected 'state PATH TEMPLATE COUNT COORD_DIM DERIV_DIM'");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 1 3\n"),
            "line 2: expected 'state PATH TEMPLATE COUNT COORD_DIM DERIV_DIM'");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 2 3 3\n1 2 3 4 5 6\n1 2 3 4 5\n"),
            "line 4: expected 6 numbers");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 1 3 3\n1 2 x 4 5 6\n"),
            "line 3: expected 6 numbers");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 2 3 3\n1 2 3 4 5 6\n"),
            "line 3: state /a ends early");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstat /a Vec3d 1 3 3\n"),
            "line 2: unknown line 'stat'");
  EXPECT_EQ(readError("snapshot time 0 step 0\nend\n1 2 3\n"), "line 3: unknown line '1'");
}

TEST(StateFile, ExtraNumbersOnALineAreAnError) {
  // A row longer than the header says means the dimensions are wrong: refuse, do not guess.
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 1 3 3\n1 2 3 4 5 6 7\n"),
            "line 3: expected 6 numbers");
  EXPECT_EQ(readError("snapshot time 0 step 0\nstate /a Vec3d 1 3 3\n1 2 3 4 5 6 junk\n"),
            "line 3: expected 6 numbers");
}

TEST(StateFile, FailedReadClearsPreviousSnapshots) {
  std::vector<StateSnapshot> snapshots(2);
  std::istringstream in("snapshot time 0 step 0\nbad\n");
  std::string error;
  EXPECT_FALSE(readStateFile(in, snapshots, error));
  EXPECT_EQ(error, "line 2: unknown line 'bad'");
  std::istringstream good("snapshot time 0 step 0\nend\n");
  ASSERT_TRUE(readStateFile(good, snapshots, error)) << error;
  EXPECT_EQ(snapshots.size(), 1u);
}

// A C++ locale that writes "1.234,5": the file format must not follow it.
struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(StateFile, FormatIgnoresTheGlobalLocale) {
  StateSnapshot s = awkwardSnapshot();
  s.step = 1234567;
  const std::locale previous =
      std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  std::ostringstream out;  // takes the global locale
  writeSnapshot(out, s);
  std::istringstream in(out.str());
  std::vector<StateSnapshot> back;
  std::string error;
  const bool ok = readStateFile(in, back, error);
  std::locale::global(previous);
  EXPECT_NE(out.str().find("step 1234567\n"), std::string::npos) << out.str();
  ASSERT_TRUE(ok) << error;
  ASSERT_EQ(back.size(), 1u);
  expectSame(s, back[0]);
}

TEST(CaptureState, TakesEveryStateInGraphOrder) {
  Node root;
  root.setTime(0.25);
  root.addObject(std::make_unique<TestState>("dofs", "Vec3d", 3, 3,
                                             std::vector<double>{0, 1, 2, 3, 4, 5},
                                             std::vector<double>{0.1, 0, 0, 0, 0, 0}));
  Node& a = root.createChild("A");
  Node& b = root.createChild("B");
  a.addObject(std::make_unique<TestState>("frame", "Rigid3d", 7, 6,
                                          std::vector<double>{0, 0, 0, 0, 0, 0, 1},
                                          std::vector<double>(6, 0.5)));
  b.addObject(std::make_unique<TestState>("off", "Vec3d", 3, 3, std::vector<double>{9, 9, 9},
                                          std::vector<double>{9, 9, 9}));
  b.d_activated.setValue(false);
  root.addObject(std::make_unique<TestState>("second", "", 1, 1, std::vector<double>{7},
                                             std::vector<double>{8}));

  const StateSnapshot s = captureState(root, 25);
  EXPECT_EQ(s.time, 0.25);
  EXPECT_EQ(s.step, 25);
  ASSERT_EQ(s.states.size(), 3u);  // the deactivated node's state is left out
  EXPECT_EQ(s.states[0].path, "/root/dofs");
  EXPECT_EQ(s.states[0].templateName, "Vec3d");
  EXPECT_EQ(s.states[0].count(), 2u);
  EXPECT_EQ(s.states[0].velocities[0], 0.1);
  EXPECT_EQ(s.states[1].path, "/root/second");  // this node's components before its children
  EXPECT_EQ(s.states[1].templateName, "");
  EXPECT_EQ(s.states[2].path, "/root/A/frame");
  EXPECT_EQ(s.states[2].coordDimension, 7);
  EXPECT_EQ(s.states[2].derivDimension, 6);
  EXPECT_EQ(s.states[2].velocities, std::vector<double>(6, 0.5));

  const auto back = readBack(written({s}));
  ASSERT_EQ(back.size(), 1u);
  expectSame(s, back[0]);
}

}  // namespace
}  // namespace stroma
