// SPDX-License-Identifier: MIT
// The `stroma` command as a user runs it: the built binary, its output and its exit code
// (0 success, 1 simulation failure, 2 bad input or usage).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/StateFile.h"

extern char** environ;

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int exitCode = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// Runs the built `stroma` with `args`, StromaTestPlugin in STROMA_PLUGIN_PATH and `extraEnv`
/// ("NAME=value") added to the environment; captures both streams and the exit code.
CommandResult runStroma(const std::vector<std::string>& args,
                        const std::vector<std::string>& extraEnv = {}) {
  TempDir capture;
  const std::string outFile = (capture.path() / "out").string();
  const std::string errFile = (capture.path() / "err").string();

  std::vector<std::string> argStrings{STROMA_CLI};
  argStrings.insert(argStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argStrings) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::vector<std::string> envStrings{"STROMA_PLUGIN_PATH=" + testPluginDirectory().string()};
  envStrings.insert(envStrings.end(), extraEnv.begin(), extraEnv.end());
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    bool overridden = false;
    for (const auto& mine : envStrings) overridden |= mine.rfind(name + "=", 0) == 0;
    if (!overridden) envStrings.push_back(entry);
  }
  std::vector<char*> envp;
  for (auto& e : envStrings) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  CommandResult result;
  if (spawned != 0) {
    result.err = "posix_spawn failed: " + std::string(std::strerror(spawned));
    return result;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = readFile(outFile);
  result.err = readFile(errFile);
  return result;
}

/// For failure messages: the whole run.
std::string show(const CommandResult& r) {
  return "exit code " + std::to_string(r.exitCode) + "\n--- stdout ---\n" + r.out +
         "--- stderr ---\n" + r.err;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::string kKernelScene = std::string(STROMA_SOURCE_DIR) + "/scenes/kernel/Kernel.scn";

/// A scene stepping a TestCounter, which fails at `failAtStep` (0: never).
std::string counterScene(int failAtStep) {
  return R"(<Node name="root" dt="0.1">
  <TestCounter name="counter" failAtStep=")" +
         std::to_string(failAtStep) + R"("/>
  <MechanicalObject name="dofs" position="0 0 0  1 2 3"/>
</Node>
)";
}

// --- A minimal JSON reader, to check --log-json lines -----------------------------------------

class JsonObjectReader {
 public:
  explicit JsonObjectReader(std::string_view text) : m_text(text) {}

  /// Reads one JSON object of scalar values (strings, numbers, true, false, null) spanning the
  /// whole text; values are kept as their text (strings unescaped). False on any syntax error.
  bool read(std::map<std::string, std::string>& object) {
    skipSpace();
    if (!consume('{')) return false;
    skipSpace();
    if (consume('}')) return atEnd();
    while (true) {
      std::string key, value;
      skipSpace();
      if (!readString(key)) return false;
      skipSpace();
      if (!consume(':')) return false;
      skipSpace();
      if (!readScalar(value)) return false;
      if (!object.emplace(key, value).second) return false;  // duplicate key
      skipSpace();
      if (consume('}')) return atEnd();
      if (!consume(',')) return false;
    }
  }

 private:
  bool atEnd() {
    skipSpace();
    return m_pos == m_text.size();
  }
  void skipSpace() {
    while (m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos])))
      ++m_pos;
  }
  bool consume(char c) {
    if (m_pos < m_text.size() && m_text[m_pos] == c) {
      ++m_pos;
      return true;
    }
    return false;
  }
  bool readString(std::string& out) {
    if (!consume('"')) return false;
    while (m_pos < m_text.size()) {
      const char c = m_text[m_pos++];
      if (c == '"') return true;
      if (static_cast<unsigned char>(c) < 0x20) return false;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (m_pos >= m_text.size()) return false;
      const char e = m_text[m_pos++];
      switch (e) {
        case '"':
        case '\\':
        case '/':
          out += e;
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u':
          for (int i = 0; i < 4; ++i)
            if (m_pos >= m_text.size() ||
                !std::isxdigit(static_cast<unsigned char>(m_text[m_pos++])))
              return false;
          out += '?';
          break;
        default:
          return false;
      }
    }
    return false;
  }
  bool readScalar(std::string& out) {
    if (m_pos < m_text.size() && m_text[m_pos] == '"') return readString(out);
    for (const char* literal : {"true", "false", "null"}) {
      if (m_text.substr(m_pos).rfind(literal, 0) == 0) {
        out = literal;
        m_pos += std::string_view(literal).size();
        return true;
      }
    }
    // -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
    const std::size_t start = m_pos;
    auto digits = [&] {
      const std::size_t from = m_pos;
      while (m_pos < m_text.size() && std::isdigit(static_cast<unsigned char>(m_text[m_pos])))
        ++m_pos;
      return m_pos - from;
    };
    consume('-');
    if (consume('0')) {
    } else if (digits() == 0) {
      return false;
    }
    if (consume('.') && digits() == 0) return false;
    if (consume('e') || consume('E')) {
      if (!consume('+')) consume('-');
      if (digits() == 0) return false;
    }
    out = std::string(m_text.substr(start, m_pos - start));
    return true;
  }

  std::string_view m_text;
  std::size_t m_pos = 0;
};

TEST(JsonObjectReader, AcceptsObjectsAndRefusesBrokenOnes) {
  std::map<std::string, std::string> o;
  EXPECT_TRUE(JsonObjectReader(R"({"a":"x\"y","b":-1.5e3,"c":true})").read(o));
  EXPECT_EQ(o["a"], "x\"y");
  EXPECT_EQ(o["b"], "-1.5e3");
  for (const char* bad : {R"({"a":1,})", R"({"a":01})", R"({"a":"x)", R"({"a":1} x)",
                          R"({"a":1,"a":2})", "{\"a\":\"tab\there\"}", R"({a:1})"}) {
    std::map<std::string, std::string> ignored;
    EXPECT_FALSE(JsonObjectReader(bad).read(ignored)) << bad;
  }
}

// --- Version, help and usage errors -----------------------------------------------------------

TEST(StromaCommand, VersionPrintsTheVersion) {
  const CommandResult r = runStroma({"--version"});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  EXPECT_EQ(r.out, "stroma " + std::string(stromaVersion()) + "\n");
}

TEST(StromaCommand, HelpListsTheCommands) {
  for (const char* flag : {"--help", "-h", "help"}) {
    const CommandResult r = runStroma({flag});
    EXPECT_EQ(r.exitCode, 0) << show(r);
    for (const char* part : {"Usage:", "stroma run SCENE", "stroma check SCENE", "stroma list",
                             "stroma doc COMPONENT", "--log-json", "Exit codes"})
      EXPECT_TRUE(has(r.out, part)) << part << '\n' << show(r);
  }
}

TEST(StromaCommand, EveryCommandAnswersHelpWithItsOwnUsage) {
  // Each command, with --help or -h anywhere among its arguments (even beside a scene or a
  // bad option), prints its own usage on stdout and exits with 0; `stroma help COMMAND` too.
  const std::map<std::string, std::vector<std::string>> own = {
      {"run", {"stroma run SCENE", "--export-every K", "--data-path DIR", "Exit codes"}},
      {"check", {"stroma check SCENE", "stroma check --stability", "--log-json FILE"}},
      {"bench", {"stroma bench STUDY.xml", "--quick", "--save-scenes"}},
      {"list", {"stroma list [--plugin NAME]"}},
      {"doc", {"stroma doc COMPONENT", "--template"}},
      {"plugin-index", {"stroma plugin-index LIB --output FILE"}}};
  for (const auto& [command, parts] : own) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{command, "--help"},
          {command, "-h"},
          {command, kKernelScene, "--no-such-option", "--help"},
          {"help", command}}) {
      const CommandResult r = runStroma(args);
      SCOPED_TRACE(args.back());
      EXPECT_EQ(r.exitCode, 0) << show(r);
      EXPECT_TRUE(r.err.empty()) << show(r);
      for (const std::string& part : parts)
        EXPECT_TRUE(has(r.out, part)) << part << '\n' << show(r);
      // Its own usage only: no other command's line.
      for (const auto& [other, otherParts] : own)
        if (other != command)
          EXPECT_FALSE(has(r.out, otherParts.front())) << other << '\n' << show(r);
    }
  }
}

TEST(StromaCommand, NoArgumentsIsAUsageError) {
  const CommandResult r = runStroma({});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "Usage:")) << show(r);
}

TEST(StromaCommand, UnknownCommandSuggestsTheClosest) {
  const CommandResult r = runStroma({"rnu", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "unknown command 'rnu'; did you mean 'run'?")) << show(r);
  EXPECT_TRUE(r.out.empty()) << show(r);
}

TEST(StromaCommand, UnknownOptionSuggestsTheClosest) {
  CommandResult r = runStroma({"run", "--step", "3", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "unknown option --step; did you mean '--steps'?")) << show(r);
  r = runStroma({"check", "--verbos", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "did you mean '--verbose'?")) << show(r);
}

TEST(StromaCommand, BadOptionValuesAreUsageErrors) {
  CommandResult r = runStroma({"run", "-n", "many", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "option -n expects an integer >= 0, got 'many'")) << show(r);
  r = runStroma({"run", "--dt", "-1", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "--dt expects a positive number")) << show(r);
  r = runStroma({"run", "--export-every", "2", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "--export-every needs --export-state")) << show(r);
  r = runStroma({"run"});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "expected a scene file")) << show(r);
}

// --- check --------------------------------------------------------------------------------------

TEST(StromaCommand, CheckAcceptsTheKernelScene) {
  const CommandResult r = runStroma({"check", kKernelScene});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  EXPECT_TRUE(has(r.out, kKernelScene + ": OK (")) << show(r);
  EXPECT_TRUE(has(r.out, "plugins loaded:")) << show(r);
  EXPECT_EQ(r.err, "") << show(r);
}

TEST(StromaCommand, CheckReportsEachErrorWithFileAndLine) {
  TempDir dir;
  const fs::path scene = dir.write("bad.scn", R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0"/>
  <MechanicalObjekt name="other"/>
  <TestCounter name="counter" incremnet="2"/>
</Node>
)");
  const CommandResult r = runStroma({"check", scene.string()});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, scene.string() + ":3: error: /root/other (MechanicalObjekt): unknown "
                                          "component 'MechanicalObjekt'; did you mean "
                                          "'MechanicalObject'?"))
      << show(r);
  EXPECT_TRUE(has(r.err, scene.string() + ":4: error: /root/counter (TestCounter), field "
                                          "'incremnet': unknown attribute 'incremnet'; did you "
                                          "mean 'increment'?"))
      << show(r);
  EXPECT_TRUE(has(r.err, "2 errors; the scene was not run")) << show(r);
  EXPECT_FALSE(has(r.out, "OK")) << show(r);
}

TEST(StromaCommand, CheckReportsMalformedXmlWithItsLine) {
  TempDir dir;
  const fs::path scene =
      dir.write("broken.scn", "<Node name=\"root\">\n  <TestCounter>\n</Node>\n");
  const CommandResult r = runStroma({"check", scene.string()});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, scene.string() + ":2: error: malformed XML")) << show(r);
  EXPECT_TRUE(has(r.err, "1 error; the scene was not run")) << show(r);
}

TEST(StromaCommand, CheckReportsAMissingSceneFile) {
  const CommandResult r = runStroma({"check", "/nonexistent/scene.scn"});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "cannot open scene file '/nonexistent/scene.scn'")) << show(r);
}

TEST(StromaCommand, DataPathOptionAndVariableAreSearched) {
  TempDir scenes, data;
  data.write("meshes/part.obj", "");
  const fs::path scene =
      scenes.write("visual.scn", R"(<Node><TestLoader filename="meshes/part.obj"/></Node>)");
  CommandResult r = runStroma({"check", scene.string()});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "file 'meshes/part.obj' not found")) << show(r);
  r = runStroma({"check", "--data-path", data.path().string(), scene.string()});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  r = runStroma({"check", scene.string()}, {"STROMA_DATA_PATH=" + data.path().string()});
  EXPECT_EQ(r.exitCode, 0) << show(r);
}

// --- run ----------------------------------------------------------------------------------------

TEST(StromaCommand, RunPrintsTheTimingSummary) {
  const CommandResult r = runStroma({"run", "-n", "5", kKernelScene});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  EXPECT_TRUE(has(r.out, "Ran 5 steps of " + kKernelScene)) << show(r);
  EXPECT_TRUE(has(r.out, "simulated time 0.05 s")) << show(r);
  EXPECT_TRUE(has(r.out, "steps/s")) << show(r);
  EXPECT_TRUE(has(r.out, "phase")) << show(r);
  EXPECT_EQ(r.err, "") << show(r);
}

TEST(StromaCommand, RunWithStepsAndTimeStepOptions) {
  const CommandResult r = runStroma({"run", "--steps", "4", "--dt", "0.5", kKernelScene});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  EXPECT_TRUE(has(r.out, "Ran 4 steps")) << show(r);
  EXPECT_TRUE(has(r.out, "(dt 0.5 s, simulated time 2 s)")) << show(r);
}

TEST(StromaCommand, RunExportsStatesEveryKStepsAndAtTheEnd) {
  TempDir dir;
  const fs::path states = dir.path() / "states.txt";
  const CommandResult r = runStroma(
      {"run", "-n", "5", "--export-state", states.string(), "--export-every", "2", kKernelScene});
  ASSERT_EQ(r.exitCode, 0) << show(r);
  std::ifstream in(states);
  ASSERT_TRUE(in) << states;
  std::vector<StateSnapshot> snapshots;
  std::string error;
  ASSERT_TRUE(readStateFile(in, snapshots, error)) << error;
  std::vector<long long> steps;
  for (const auto& s : snapshots) steps.push_back(s.step);
  EXPECT_EQ(steps, (std::vector<long long>{0, 2, 4, 5}));
  ASSERT_EQ(snapshots.size(), 4u);
  EXPECT_NEAR(snapshots[0].time, 0.0, 1e-12);
  EXPECT_NEAR(snapshots[1].time, 0.02, 1e-12);
  EXPECT_NEAR(snapshots[3].time, 0.05, 1e-12);
  for (const auto& s : snapshots) {
    ASSERT_FALSE(s.states.empty());
    bool foundPoints = false;
    for (const StateRecord& record : s.states) {
      if (record.path != "/root/Points/dofs") continue;
      foundPoints = true;
      EXPECT_EQ(record.templateName, "Vec3d");
      EXPECT_EQ(record.count(), 4u);
      ASSERT_EQ(record.positions.size(), 12u);
      EXPECT_DOUBLE_EQ(record.positions[1], 2.0);  // translation="0 2 0" was applied
    }
    EXPECT_TRUE(foundPoints) << "step " << s.step;
  }
}

TEST(StromaCommand, RunExportsOnlyTheFinalStateWithoutExportEvery) {
  TempDir dir;
  const fs::path states = dir.path() / "final.txt";
  const CommandResult r =
      runStroma({"run", "-n", "3", "--export-state", states.string(), kKernelScene});
  ASSERT_EQ(r.exitCode, 0) << show(r);
  std::ifstream in(states);
  std::vector<StateSnapshot> snapshots;
  std::string error;
  ASSERT_TRUE(readStateFile(in, snapshots, error)) << error;
  ASSERT_EQ(snapshots.size(), 1u);
  EXPECT_EQ(snapshots[0].step, 3);
}

TEST(StromaCommand, RunPrintsAndExportsDataAskedFor) {
  // --print PATH.field prints a Data after each step; --export-data writes it in the snapshots,
  // read back as written.
  TempDir dir;
  const fs::path states = dir.path() / "data.txt";
  CommandResult r = runStroma({"run", "-n", "2", "--print", "/root/Points/dofs.velocity",
                               "--export-state", states.string(), "--export-data",
                               "@/root/Frame/frame.position", kKernelScene});
  ASSERT_EQ(r.exitCode, 0) << show(r);
  EXPECT_TRUE(has(r.out, "step 1 time 0.01 /root/Points/dofs.velocity ")) << show(r);
  EXPECT_TRUE(has(r.out, "step 2 time 0.02 /root/Points/dofs.velocity ")) << show(r);
  std::ifstream in(states);
  std::vector<StateSnapshot> snapshots;
  std::string error;
  ASSERT_TRUE(readStateFile(in, snapshots, error)) << error;
  ASSERT_EQ(snapshots.size(), 1u);
  ASSERT_EQ(snapshots[0].data.size(), 1u);
  EXPECT_EQ(snapshots[0].data[0].name, "/root/Frame/frame.position");
  EXPECT_EQ(snapshots[0].data[0].text, "0 1 0 0 0 0 1");
  EXPECT_FALSE(snapshots[0].data[0].typeName.empty());
  // A Data that does not exist is bad input, named.
  r = runStroma({"run", "-n", "2", "--print", "/root/Points/dofs.nothing", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "--print /root/Points/dofs.nothing")) << show(r);
  EXPECT_TRUE(has(r.err, "no field 'nothing'")) << show(r);
  r = runStroma({"run", "--export-data", "/root/Frame/frame.position", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "--export-data needs --export-state")) << show(r);
}

TEST(StromaCommand, RunOfABadSceneDoesNotRun) {
  TempDir dir;
  const fs::path scene = dir.write("bad.scn", R"(<Node><TestCounter increment="20"/></Node>)");
  const CommandResult r = runStroma({"run", "-n", "5", scene.string()});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, scene.string() + ":1: error:")) << show(r);
  EXPECT_TRUE(has(r.err, "expected a value <= 10, got 20")) << show(r);
  EXPECT_TRUE(has(r.err, "the scene was not run")) << show(r);
  EXPECT_FALSE(has(r.out, "Ran ")) << show(r);
}

TEST(StromaCommand, RunStopsWithExitCodeOneWhenAStepFails) {
  TempDir dir;
  const fs::path scene = dir.write("fails.scn", counterScene(3));
  const CommandResult r = runStroma({"run", "-n", "10", scene.string()});
  EXPECT_EQ(r.exitCode, 1) << show(r);
  EXPECT_TRUE(has(r.err, "/root/counter (TestCounter), field 'failAtStep': failing at step 3"))
      << show(r);
  EXPECT_TRUE(has(r.err, "the simulation failed at step 3")) << show(r);
  EXPECT_TRUE(has(r.out, "Ran 3 steps")) << show(r);  // the summary still comes
}

TEST(StromaCommand, RunWritesEveryMessageAsJsonLines) {
  TempDir dir;
  const fs::path scene = dir.write("fails.scn", counterScene(2));
  const fs::path log = dir.path() / "log.jsonl";
  const CommandResult r = runStroma({"run", "-n", "5", "--log-json", log.string(), scene.string()});
  EXPECT_EQ(r.exitCode, 1) << show(r);
  std::ifstream in(log);
  ASSERT_TRUE(in) << log;
  std::string line;
  int lines = 0, stepErrors = 0;
  while (std::getline(in, line)) {
    ++lines;
    std::map<std::string, std::string> object;
    ASSERT_TRUE(JsonObjectReader(line).read(object)) << "not a JSON object: " << line;
    for (const char* key : {"level", "text", "component", "class", "field", "file", "line"})
      EXPECT_TRUE(object.count(key)) << key << " missing in " << line;
    EXPECT_TRUE(object["level"] == "info" || object["level"] == "warning" ||
                object["level"] == "error")
        << line;
    EXPECT_FALSE(object["line"].empty() || object["line"][0] == '"') << line;
    if (object["level"] == "error" && has(object["text"], "failing at step 2")) {
      ++stepErrors;
      EXPECT_EQ(object["component"], "/root/counter");
      EXPECT_EQ(object["class"], "TestCounter");
      EXPECT_EQ(object["field"], "failAtStep");
      EXPECT_EQ(object["file"], scene.string());
      EXPECT_EQ(object["line"], "2");
    }
  }
  EXPECT_GE(lines, 1);
  EXPECT_EQ(stepErrors, 1);
}

TEST(StromaCommand, RunLogsTheSolversSummaryAtUnloadAsJsonLines) {
  // CG capped at one iteration warns at the end of the run (its summary, written when the scene
  // unloads): the JSON log must still be open then (it was closed first: a crash at exit).
  TempDir dir;
  const fs::path scene = dir.write("capped.scn", R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <EulerImplicitSolver/>
  <CGLinearSolver iterations="1" tolerance="1e-12" threshold="1e-30"/>
  <MeshTopology tetrahedra="0 1 2 3"/>
  <MechanicalObject position="0 0 0  1 0 0  0 1 0  0 0 1"/>
  <UniformMass totalMass="1"/>
  <TetrahedronFEMForceField youngModulus="1000" poissonRatio="0.3"/>
  <FixedConstraint indices="0"/>
</Node>
)");
  const fs::path log = dir.path() / "log.jsonl";
  const CommandResult r = runStroma({"run", "-n", "5", "--log-json", log.string(), scene.string()});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  std::map<std::string, std::string> object;
  ASSERT_TRUE(JsonObjectReader(last).read(object)) << "not a JSON object: " << last;
  EXPECT_TRUE(has(object["text"], "did not converge in 5 of 5 solves")) << last;
}

TEST(StromaCommand, CheckWritesLoadErrorsAsJsonLines) {
  TempDir dir;
  // The last value holds quotes, which the JSON text must escape.
  const fs::path scene = dir.write("bad.scn", R"(<Node>
  <Nope name="x"/>
  <TestCounter incremnet="1" increment="&quot;1&quot;"/>
</Node>
)");
  const fs::path log = dir.path() / "log.jsonl";
  const CommandResult r = runStroma({"check", scene.string(), "--log-json", log.string()});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  std::ifstream in(log);
  std::string line;
  std::vector<std::map<std::string, std::string>> objects;
  while (std::getline(in, line)) {
    std::map<std::string, std::string> object;
    ASSERT_TRUE(JsonObjectReader(line).read(object)) << "not a JSON object: " << line;
    objects.push_back(object);
  }
  ASSERT_EQ(objects.size(), 3u);
  EXPECT_EQ(objects[0]["level"], "error");
  EXPECT_EQ(objects[0]["line"], "2");
  EXPECT_EQ(objects[0]["class"], "Nope");
  EXPECT_EQ(objects[0]["component"], "/root/x");
  EXPECT_EQ(objects[1]["line"], "3");
  EXPECT_EQ(objects[1]["field"], "incremnet");
  EXPECT_EQ(objects[1]["file"], scene.string());
  EXPECT_EQ(objects[2]["field"], "increment");
  EXPECT_TRUE(has(objects[2]["text"], "got '\"1\"'")) << objects[2]["text"];
}

TEST(StromaCommand, LogJsonToAnUnwritablePathIsAUsageError) {
  const CommandResult r =
      runStroma({"check", "--log-json", "/nonexistent/dir/log.jsonl", kKernelScene});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "cannot write the JSON log")) << show(r);
}

// --- list and doc -------------------------------------------------------------------------------

TEST(StromaCommand, ListShowsPluginsAndTheirComponents) {
  const CommandResult r = runStroma({"list"});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  for (const char* part :
       {"StateContainer\n", "  MechanicalObject<Vec3d,Vec2d,Vec1d,Rigid3d>: ", "SceneBasics\n",
        "  RequiredPlugin: ", "Visual\n", "  OglModel", "StromaTestPlugin\n",
        "  TestCounter (also LegacyTestCounter): Counts its steps (test)\n",
        "  TestTemplated<Vec3d,Rigid3d>: "})
    EXPECT_TRUE(has(r.out, part)) << part << '\n' << show(r);
}

TEST(StromaCommand, ListOfOnePlugin) {
  CommandResult r = runStroma({"list", "--plugin", "StromaTestPlugin"});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  EXPECT_TRUE(has(r.out, "TestEngine")) << show(r);
  EXPECT_FALSE(has(r.out, "MechanicalObject")) << show(r);
  r = runStroma({"list", "--plugin", "StromaTestPlugn"});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "no plugin named 'StromaTestPlugn'; did you mean 'StromaTestPlugin'?"))
      << show(r);
}

TEST(StromaCommand, DocListsFieldsWithTypeDefaultAndUnit) {
  const CommandResult r = runStroma({"doc", "MechanicalObject"});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  for (const char* part :
       {"MechanicalObject <Vec3d>\n", "plugin: StateContainer\n",
        "templates: Vec3d Vec2d Vec1d Rigid3d", "Fields:\n",
        "  position  (list of Vec3d, unit m)\n", "  velocity  (list of Vec3d, unit m/s)\n",
        "  translation  (Vec3d, unit m)\n      Translation applied to the initial positions.\n"
        "      default: 0 0 0\n",
        "  rotation  (Vec3d, unit deg)\n", "  size  (int, range [0, ", "  name  (string)\n"})
    EXPECT_TRUE(has(r.out, part)) << part << '\n' << show(r);
}

TEST(StromaCommand, DocOfAnotherTemplateAndOfATestComponent) {
  CommandResult r = runStroma({"doc", "MechanicalObject", "--template", "Rigid3d"});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  EXPECT_TRUE(has(r.out, "MechanicalObject <Rigid3d>")) << show(r);
  EXPECT_TRUE(has(r.out, "  position  (list of Rigid3d coordinates, unit m)")) << show(r);
  r = runStroma({"doc", "TestCounter"});
  EXPECT_EQ(r.exitCode, 0) << show(r);
  for (const char* part : {"also accepted as: LegacyTestCounter",
                           "  increment  (real, range [0, 10])\n      Added to 'total' at each "
                           "step.\n      default: 1\n",
                           "  count  (int, output)", "  elapsed  (real, unit s, output)",
                           "Links:\n  mstate  (link to BaseState)",
                           "SOFA options accepted without effect: showCount"})
    EXPECT_TRUE(has(r.out, part)) << part << '\n' << show(r);
}

TEST(StromaCommand, DocOfAnUnknownComponentFailsWithASuggestion) {
  CommandResult r = runStroma({"doc", "Nope"});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "unknown component 'Nope'")) << show(r);
  EXPECT_TRUE(has(r.err, "`stroma list`")) << show(r);
  r = runStroma({"doc", "MechanicalObjct"});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "unknown component 'MechanicalObjct'; did you mean 'MechanicalObject'?"))
      << show(r);
  r = runStroma({"doc", "BeamFEMForceField"});
  EXPECT_EQ(r.exitCode, 2) << show(r);
  EXPECT_TRUE(has(r.err, "is a SOFA component that Stroma does not provide")) << show(r);
}

}  // namespace
}  // namespace stroma::test
