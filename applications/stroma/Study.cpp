// SPDX-License-Identifier: MIT
#include "Study.h"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/NameSuggestions.h"

namespace stroma::cli {

namespace {

using tinyxml2::XMLElement;

/// "FILE:LINE: text"
std::string at(const Study& s, int line, const std::string& text) {
  return s.file.string() + ":" + std::to_string(line) + ": " + text;
}

std::string suggest(const std::string& name, const std::vector<std::string>& known) {
  const auto near = nearestNames(name, known);
  return near.empty() ? "" : "; did you mean " + quotedList(near) + "?";
}

/// The inner text of an element: its text and child elements printed back as XML (so that a
/// substitution can be a scene fragment written as plain elements, mixed with placeholders).
std::string innerXml(const XMLElement& e) {
  if (!e.FirstChildElement()) return e.GetText() ? e.GetText() : "";
  tinyxml2::XMLPrinter printer(nullptr, /*compact=*/false);
  for (const tinyxml2::XMLNode* c = e.FirstChild(); c; c = c->NextSibling()) {
    if (const tinyxml2::XMLText* text = c->ToText())
      printer.PushText(text->Value(), text->CData());  // as written: no escaping of ${...}
    else
      c->Accept(&printer);
  }
  return printer.CStr();
}

bool readCount(const Study& s, const XMLElement& e, const char* attribute, long long& value,
               std::string& error) {
  const char* text = e.Attribute(attribute);
  if (!text) return true;
  const std::string t = text;
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || ptr != t.data() + t.size() || value < 1) {
    error =
        at(s, e.GetLineNum(),
           std::string("attribute '") + attribute + "' expects an integer >= 1, got '" + t + "'");
    return false;
  }
  return true;
}

bool readPositive(const Study& s, const XMLElement& e, const char* attribute, double& value,
                  std::string& error) {
  const char* text = e.Attribute(attribute);
  if (!text) return true;
  char* end = nullptr;
  value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value) || value <= 0) {
    error = at(
        s, e.GetLineNum(),
        std::string("attribute '") + attribute + "' expects a positive number, got '" + text + "'");
    return false;
  }
  return true;
}

/// Checks that `e` has only the attributes in `allowed`.
bool checkAttributes(const Study& s, const XMLElement& e, const std::vector<std::string>& allowed,
                     std::string& error) {
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    if (std::find(allowed.begin(), allowed.end(), a->Name()) != allowed.end()) continue;
    error = at(s, e.GetLineNum(),
               std::string("<") + e.Name() + "> has no attribute '" + a->Name() + "'" +
                   suggest(a->Name(), allowed));
    return false;
  }
  return true;
}

bool readValue(const Study& s, const XMLElement& e, StudyValue& v, std::string& error) {
  if (!checkAttributes(s, e, {"name", "quick", "steps", "quickSteps"}, error)) return false;
  v.line = e.GetLineNum();
  if (!e.Attribute("name") || !*e.Attribute("name")) {
    error = at(s, v.line, "<Value> needs a name (the CSV cell)");
    return false;
  }
  v.name = e.Attribute("name");
  if (const char* q = e.Attribute("quick")) {
    if (std::string(q) != "true" && std::string(q) != "false") {
      error =
          at(s, v.line, std::string("attribute 'quick' expects true or false, got '") + q + "'");
      return false;
    }
    v.quick = std::string(q) == "true";
  }
  long long steps = 0;
  if (!readCount(s, e, "steps", steps, error)) return false;
  if (steps) v.steps = steps;
  steps = 0;
  if (!readCount(s, e, "quickSteps", steps, error)) return false;
  if (steps) v.quickSteps = steps;
  for (const XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::string(c->Name()) != "Set") {
      error = at(s, c->GetLineNum(),
                 std::string("<Value> holds <Set> elements, not <") + c->Name() + ">");
      return false;
    }
    if (!checkAttributes(s, *c, {"name"}, error)) return false;
    if (!c->Attribute("name") || !*c->Attribute("name")) {
      error = at(s, c->GetLineNum(), "<Set> needs the name of the placeholder it sets");
      return false;
    }
    v.substitutions[c->Attribute("name")] = innerXml(*c);
  }
  return true;
}

bool readFilter(const Study& s, const XMLElement& e, StudyFilter& f, std::string& error) {
  f.line = e.GetLineNum();
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    const std::string name = a->Name();
    if (name == "reason") {
      f.reason = a->Value();
      continue;
    }
    if (std::find(kStudyAxes.begin(), kStudyAxes.end(), name) == kStudyAxes.end()) {
      std::vector<std::string> known = kStudyAxes;
      known.push_back("reason");
      error = at(s, f.line,
                 "<" + std::string(e.Name()) + "> names unknown axis '" + name + "'" +
                     suggest(name, known));
      return false;
    }
    f.values[name] = a->Value();
  }
  if (f.values.empty()) {
    error = at(s, f.line, "<" + std::string(e.Name()) + "> names no axis value");
    return false;
  }
  return true;
}

bool readColumn(const Study& s, const XMLElement& e, const std::string& column,
                const char* dataAttr, StudyColumn& c, std::string& error) {
  c.column = column;
  const char* component = e.Attribute("component");
  if (!component || !*component) {
    error = at(s, e.GetLineNum(),
               "<" + std::string(e.Name()) + "> needs the component (class or object name)");
    return false;
  }
  c.component = component;
  c.data = e.Attribute(dataAttr) ? e.Attribute(dataAttr) : "";
  return readPositive(s, e, "scale", c.scale, error);
}

/// True when `pattern` names `value` ("abc*" matches every name starting with "abc").
bool matches(const std::string& pattern, const std::string& value) {
  if (!pattern.empty() && pattern.back() == '*')
    return value.rfind(pattern.substr(0, pattern.size() - 1), 0) == 0;
  return pattern == value;
}

bool filterMatches(const StudyFilter& f, const StudyCombination& c) {
  for (const auto& [axis, pattern] : f.values) {
    auto it = c.values.find(axis);
    if (it == c.values.end() || !matches(pattern, it->second->name)) return false;
  }
  return true;
}

/// Checks a filter's values against the axes, so that a misspelt value is not silently inert.
bool checkFilter(const Study& s, const StudyFilter& f, const char* element, std::string& error) {
  for (const auto& [axisName, pattern] : f.values) {
    const std::string wanted = axisName;  // lambdas may not capture structured bindings
    auto axis = std::find_if(s.axes.begin(), s.axes.end(),
                             [&](const StudyAxis& a) { return a.name == wanted; });
    if (axis == s.axes.end()) {
      error = at(s, f.line,
                 std::string("<") + element + "> names axis '" + axisName +
                     "', which the study does not have");
      return false;
    }
    std::vector<std::string> names;
    bool found = false;
    for (const StudyValue& v : axis->values) {
      names.push_back(v.name);
      found |= matches(pattern, v.name);
    }
    if (!found) {
      error = at(s, f.line,
                 std::string("<") + element + "> names " + axisName + " '" + pattern +
                     "', which is not a value of that axis" + suggest(pattern, names));
      return false;
    }
  }
  return true;
}

bool readScene(Study& s, const XMLElement& e, std::string& error) {
  if (!checkAttributes(s, e, {"file"}, error)) return false;
  s.sceneLine = e.GetLineNum();
  if (const char* file = e.Attribute("file")) {
    s.sceneFile = s.file.parent_path() / file;
    std::ifstream in(s.sceneFile, std::ios::binary);
    if (!in) {
      error = at(s, s.sceneLine, "scene template '" + s.sceneFile.string() + "' cannot be read");
      return false;
    }
    std::stringstream text;
    text << in.rdbuf();
    s.sceneText = text.str();
  } else {
    s.sceneFile = s.file;
    s.sceneText = innerXml(e);
  }
  if (s.sceneText.find_first_not_of(" \t\r\n") == std::string::npos) {
    error = at(s, s.sceneLine, "<Scene> is empty: give file=\"...\" or the scene inside it");
    return false;
  }
  return true;
}

}  // namespace

bool readStudy(const std::filesystem::path& file, Study& s, std::string& error) {
  s = Study();
  s.file = file;
  s.name = file.stem().string();
  tinyxml2::XMLDocument doc;
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    error = file.string() + ": cannot read the study file";
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  if (doc.Parse(content.c_str(), content.size()) != tinyxml2::XML_SUCCESS) {
    error = at(s, doc.ErrorLineNum(), std::string("malformed XML: ") + doc.ErrorStr());
    return false;
  }
  const XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "Study") {
    error = at(s, root ? root->GetLineNum() : 1, "the root element must be <Study>");
    return false;
  }
  if (!checkAttributes(s, *root, {"title", "steps", "quickSteps", "timeLimit"}, error) ||
      !readCount(s, *root, "steps", s.steps, error) ||
      !readCount(s, *root, "quickSteps", s.quickSteps, error) ||
      !readPositive(s, *root, "timeLimit", s.timeLimit, error))
    return false;
  s.title = root->Attribute("title") ? root->Attribute("title") : s.name;

  const std::vector<std::string> elements = {"Scene",  "Define", "Axis",  "Error",
                                             "Column", "Skip",   "Expect"};
  bool haveError = false;
  std::vector<StudyColumn> extraColumns;
  for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "Scene") {
      if (!s.sceneText.empty()) {
        error = at(s, e->GetLineNum(), "a study has one <Scene>");
        return false;
      }
      if (!readScene(s, *e, error)) return false;
    } else if (tag == "Define") {
      if (!checkAttributes(s, *e, {"name"}, error)) return false;
      if (!e->Attribute("name") || !*e->Attribute("name")) {
        error = at(s, e->GetLineNum(), "<Define> needs the name of the placeholder it sets");
        return false;
      }
      s.defines[e->Attribute("name")] = innerXml(*e);
    } else if (tag == "Axis") {
      if (!checkAttributes(s, *e, {"name"}, error)) return false;
      const std::string name = e->Attribute("name") ? e->Attribute("name") : "";
      if (std::find(kStudyAxes.begin(), kStudyAxes.end(), name) == kStudyAxes.end()) {
        error = at(s, e->GetLineNum(),
                   "unknown axis '" + name + "' (the axes are model, " + "resolution, solver, dt)" +
                       suggest(name, kStudyAxes));
        return false;
      }
      for (const StudyAxis& a : s.axes)
        if (a.name == name) {
          error = at(s, e->GetLineNum(), "axis '" + name + "' is given twice");
          return false;
        }
      StudyAxis axis{name, {}};
      std::set<std::string> seen;
      for (const XMLElement* v = e->FirstChildElement(); v; v = v->NextSiblingElement()) {
        if (std::string(v->Name()) != "Value") {
          error = at(s, v->GetLineNum(),
                     "<Axis> holds <Value> elements, not <" + std::string(v->Name()) + ">");
          return false;
        }
        StudyValue value;
        if (!readValue(s, *v, value, error)) return false;
        if (!seen.insert(value.name).second) {
          error =
              at(s, value.line, "axis '" + name + "' has two values named '" + value.name + "'");
          return false;
        }
        axis.values.push_back(std::move(value));
      }
      if (axis.values.empty()) {
        error = at(s, e->GetLineNum(), "axis '" + name + "' has no <Value>");
        return false;
      }
      s.axes.push_back(std::move(axis));
    } else if (tag == "Error") {
      if (!checkAttributes(s, *e, {"component", "max", "rms", "scale", "label"}, error))
        return false;
      StudyColumn max, rms;
      if (!readColumn(s, *e, "max_error", "max", max, error) ||
          !readColumn(s, *e, "rms_error", "rms", rms, error))
        return false;
      if (max.data.empty()) max.data = "maxError";
      if (rms.data.empty()) rms.data = "rmsError";
      s.errors.insert(s.errors.begin(), {max, rms});
      s.errorLabel = e->Attribute("label") ? e->Attribute("label") : "max_error";
      haveError = true;
    } else if (tag == "Column") {
      if (!checkAttributes(s, *e, {"name", "component", "data", "scale"}, error)) return false;
      StudyColumn c;
      const char* name = e->Attribute("name");
      if (!name || !*name || !e->Attribute("data")) {
        error = at(s, e->GetLineNum(), "<Column> needs name, component and data");
        return false;
      }
      if (!readColumn(s, *e, name, "data", c, error)) return false;
      extraColumns.push_back(c);
    } else if (tag == "Skip" || tag == "Expect") {
      StudyFilter f;
      if (!readFilter(s, *e, f, error)) return false;
      (tag == "Skip" ? s.skips : s.expectedFailures).push_back(std::move(f));
    } else {
      error = at(s, e->GetLineNum(),
                 "unknown element <" + tag + "> in a study" + suggest(tag, elements));
      return false;
    }
  }
  if (s.sceneText.empty()) {
    error = at(s, root->GetLineNum(), "the study has no <Scene>");
    return false;
  }
  if (!haveError && !extraColumns.empty()) {
    error = at(s, root->GetLineNum(), "<Column> needs an <Error> (max_error, rms_error) first");
    return false;
  }
  s.errors.insert(s.errors.end(), extraColumns.begin(), extraColumns.end());
  for (const StudyFilter& f : s.skips)
    if (!checkFilter(s, f, "Skip", error)) return false;
  for (const StudyFilter& f : s.expectedFailures)
    if (!checkFilter(s, f, "Expect", error)) return false;

  // Every combination must leave no placeholder undefined.
  for (bool quick : {false, true})
    for (const StudyCombination& c : studyCombinations(s, quick)) {
      std::string scene, what;
      if (!substituteScene(s, c, scene, what)) {
        error = at(s, s.sceneLine, what);
        return false;
      }
    }
  return true;
}

std::vector<StudyCombination> studyCombinations(const Study& s, bool quick) {
  std::vector<StudyCombination> result;
  std::vector<std::size_t> index(s.axes.size(), 0);
  while (true) {
    StudyCombination c;
    bool allQuick = true;
    // Steps: the smallest count the combination's values set (a static solver's single step
    // beats a time step's count), else the study's; --quick caps it with quickSteps.
    long long valueSteps = 0;
    for (std::size_t a = 0; a < s.axes.size(); ++a) {
      const StudyValue& v = s.axes[a].values[index[a]];
      c.values[s.axes[a].name] = &v;
      allQuick &= v.quick;
      const std::optional<long long> n = quick && v.quickSteps ? v.quickSteps : v.steps;
      if (n) valueSteps = valueSteps ? std::min(valueSteps, *n) : *n;
    }
    c.steps = valueSteps ? valueSteps : s.steps;
    if (quick && s.quickSteps) c.steps = std::min(c.steps, s.quickSteps);
    const bool skipped = std::any_of(s.skips.begin(), s.skips.end(),
                                     [&](const StudyFilter& f) { return filterMatches(f, c); });
    if (!skipped && (!quick || allQuick)) {
      for (const StudyFilter& f : s.expectedFailures)
        if (filterMatches(f, c)) c.expectedFailure = &f;
      result.push_back(c);
    }
    // Next index, the last axis fastest.
    std::size_t a = s.axes.size();
    while (a > 0) {
      --a;
      if (++index[a] < s.axes[a].values.size()) break;
      index[a] = 0;
      if (a == 0) return result;
    }
    if (s.axes.empty()) return result;
  }
}

bool substituteScene(const Study& s, const StudyCombination& c, std::string& text,
                     std::string& error) {
  std::map<std::string, std::string> table = s.defines;
  table["studyDir"] = std::filesystem::absolute(s.file).parent_path().string();
  for (const auto& [axis, value] : c.values) {
    table[axis] = value->name;  // ${model} is the value's name unless a Set says otherwise
    for (const auto& [key, replacement] : value->substitutions) table[key] = replacement;
  }
  text = s.sceneText;
  // Replacements may hold placeholders themselves: a few passes, then whatever is left is an
  // undefined name (or a cycle).
  for (int pass = 0; pass < 8; ++pass) {
    std::string out;
    bool replaced = false;
    std::size_t pos = 0;
    while (true) {
      const std::size_t open = text.find("${", pos);
      if (open == std::string::npos) break;
      const std::size_t close = text.find('}', open);
      if (close == std::string::npos) break;
      const std::string key = text.substr(open + 2, close - open - 2);
      auto it = table.find(key);
      out += text.substr(pos, open - pos);
      if (it != table.end()) {
        out += it->second;
        replaced = true;
      } else {
        out += text.substr(open, close + 1 - open);
      }
      pos = close + 1;
    }
    out += text.substr(pos);
    text = std::move(out);
    if (!replaced) break;
  }
  const std::size_t open = text.find("${");
  if (open != std::string::npos) {
    const std::size_t close = text.find('}', open);
    const std::string key =
        close == std::string::npos ? text.substr(open) : text.substr(open + 2, close - open - 2);
    std::vector<std::string> known;
    for (const auto& entry : table) known.push_back(entry.first);
    std::string where;
    for (const auto& [axis, value] : c.values) where += " " + axis + "=" + value->name;
    error = "placeholder ${" + key + "} of the scene is defined by no axis value (combination" +
            where + ")" + suggest(key, known);
    return false;
  }
  return true;
}

}  // namespace stroma::cli
