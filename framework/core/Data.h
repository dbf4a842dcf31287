// SPDX-License-Identifier: MIT
// Data<T>: a typed, named, documented field of a component, readable from a scene attribute.
//
// A component declares each parameter once, as a member:
//
//   Data<double> d_youngModulus{this, "youngModulus", 5000.0,
//                               "Young's modulus of the material", {.unit = "Pa", .min = 0.0}};
//
// That single declaration feeds the scene parser, `stroma doc` and the attribute checker.
// A Data can follow another one (`position="@loader.position"`): it then pulls the parent's
// value lazily, when read after the parent changed. Outputs of a DataEngine are recomputed
// lazily in the same way.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "core/DataTraits.h"

namespace stroma {

class Base;
class BaseData;
class DataEngine;

/// Optional properties of a Data, given with designated initializers.
struct DataOptions {
  std::string unit = {};          ///< SI or scene unit, shown by `stroma doc` ("Pa", "kg/m^3")
  std::optional<double> min = {}; ///< inclusive lower bound on every number of the value
  std::optional<double> max = {}; ///< inclusive upper bound on every number of the value
  bool allowNonFinite = false;    ///< NaN and infinities are refused unless this is true
  bool output = false;            ///< computed by the component (loaders, engines); linkable
  bool mustExist = true;          ///< for a FileName: a missing file is an error (else a warning)
  /// False for a source's settings that `src="@source"` must not copy (a loader's translation
  /// or filename: the follower would apply them a second time), as SOFA's setAutoLink(false).
  bool autoLink = true;
  /// Another name the scene may give it (SOFA's older name, as its addAlias): found by
  /// Base::findData, shown by `stroma doc`.
  const char* alias = nullptr;
};

namespace internal {
void registerData(Base* owner, BaseData* data);
}

/// The untyped part of a Data: name, documentation, text conversion and the lazy link.
class BaseData {
 public:
  BaseData(Base* owner, std::string name, std::string help, DataOptions options);
  virtual ~BaseData() = default;
  BaseData(const BaseData&) = delete;
  BaseData& operator=(const BaseData&) = delete;

  const std::string& name() const { return m_name; }
  const std::string& help() const { return m_help; }
  const DataOptions& options() const { return m_options; }
  Base* owner() const { return m_owner; }

  virtual std::string typeName() const = 0;
  /// The current value as a scene attribute would write it.
  std::string valueText() const;
  virtual std::string defaultText() const = 0;

  /// Parses `text` and checks it against the options. On failure the value is unchanged and
  /// `error` says what was expected.
  bool read(std::string_view text, std::string& error);

  /// True once the scene, a link or the code has given a value.
  bool isSet() const { return m_isSet; }
  /// Incremented at every change of the value; followers compare it to decide to copy.
  std::uint64_t version() const {
    update();
    return m_version;
  }
  /// Marks the value changed after an in-place modification.
  void markChanged() {
    ++m_version;
    m_isSet = true;
  }

  /// Follows `parent` (nullptr to stop following). Checks that its value converts to this
  /// Data's type; on failure nothing changes and `error` says why.
  bool setParent(BaseData* parent, std::string& error);
  BaseData* parent() const { return m_parent; }

  /// The "@path.field" text written in the scene, kept until the loader resolves it.
  const std::string& linkText() const { return m_linkText; }
  void setLinkText(std::string text) { m_linkText = std::move(text); }

  /// Output Data are recomputed by their engine when read after an input changed.
  void setEngine(DataEngine* engine) { m_engine = engine; }

 protected:
  /// Brings the value up to date with the engine or the parent. Cheap when nothing changed.
  void update() const;

  virtual void printValue(std::string& out) const = 0;
  virtual bool parseValue(std::string_view text, std::string& error) = 0;
  /// Copies the parent's value: directly when the types match, through text otherwise.
  virtual bool copyFrom(const BaseData& other, std::string& error) = 0;

 private:
  Base* m_owner;
  std::string m_name;
  std::string m_help;
  DataOptions m_options;
  std::string m_linkText;
  BaseData* m_parent = nullptr;
  DataEngine* m_engine = nullptr;
  mutable std::uint64_t m_parentVersionSeen = 0;
  mutable std::uint64_t m_version = 0;
  mutable bool m_updating = false;
  bool m_isSet = false;

  template <class T>
  friend class Data;
};

/// Checks a parsed value against the options (finite numbers, bounds).
template <class T>
bool checkDataValue(const T& value, const DataOptions& options, std::string& error) {
  bool ok = true;
  forEachReal(value, [&](double x) {
    if (!ok) return;
    if (!options.allowNonFinite && !std::isfinite(x)) {
      error = "expected a finite number, got " + std::string(std::isnan(x) ? "NaN" : "infinity");
      ok = false;
    } else if (options.min && x < *options.min) {
      std::string bound;
      internal::printDouble(bound, *options.min);
      std::string got;
      internal::printDouble(got, x);
      error = "expected a value >= " + bound + ", got " + got;
      ok = false;
    } else if (options.max && x > *options.max) {
      std::string bound;
      internal::printDouble(bound, *options.max);
      std::string got;
      internal::printDouble(got, x);
      error = "expected a value <= " + bound + ", got " + got;
      ok = false;
    }
  });
  forEachInteger(value, [&](long long x) {
    if (!ok) return;
    if ((options.min && x < *options.min) || (options.max && x > *options.max)) {
      error = "value " + std::to_string(x) + " is outside the allowed range";
      if (options.min) error += " [" + std::to_string(static_cast<long long>(*options.min));
      else error += " (-inf";
      if (options.max) error += ", " + std::to_string(static_cast<long long>(*options.max)) + "]";
      else error += ", +inf)";
      ok = false;
    }
  });
  return ok;
}

template <class T>
class Data final : public BaseData {
 public:
  using Value = T;
  using Traits = DataTraits<T>;

  Data(Base* owner, std::string name, T defaultValue, std::string help, DataOptions options = {})
      : BaseData(owner, std::move(name), std::move(help), std::move(options)),
        m_default(defaultValue),
        m_value(std::move(defaultValue)) {}

  /// The current value, pulled from the parent or the engine first when they changed.
  const T& value() const {
    update();
    return m_value;
  }
  const T& defaultValue() const { return m_default; }

  void setValue(T value) {
    m_value = std::move(value);
    markChanged();
  }
  /// Mutable access for an in-place change; counts as a change.
  T& edit() {
    update();
    markChanged();
    return m_value;
  }

  std::string typeName() const override { return Traits::typeName(); }
  std::string defaultText() const override {
    std::string text;
    Traits::print(text, m_default);
    return text;
  }

 protected:
  void printValue(std::string& out) const override { Traits::print(out, m_value); }
  bool parseValue(std::string_view text, std::string& error) override {
    T parsed{};
    if (!Traits::parse(text, parsed, error)) return false;
    if (!checkDataValue(parsed, options(), error)) return false;
    m_value = std::move(parsed);
    return true;
  }
  bool copyFrom(const BaseData& other, std::string& error) override {
    if (auto* same = dynamic_cast<const Data<T>*>(&other)) {
      if (!checkDataValue(same->m_value, options(), error)) return false;
      m_value = same->m_value;
      return true;
    }
    std::string text;
    other.printValue(text);
    return parseValue(text, error);
  }

 private:
  T m_default;
  T m_value;
};

/// A component that computes output Data from input Data on demand (a loader, BoxROI).
/// Reading an output after an input changed calls doUpdate() once.
class DataEngine {
 public:
  virtual ~DataEngine() = default;
  void addInput(BaseData* data) { m_inputs.push_back({data, 0}); }
  void addOutput(BaseData* data) { data->setEngine(this); }
  /// Recomputes the outputs when an input changed since the last computation.
  void updateIfDirty();
  /// Forces the next read of an output to recompute.
  void setDirty() { m_forceUpdate = true; }

 protected:
  virtual void doUpdate() = 0;

 private:
  struct Input {
    BaseData* data;
    std::uint64_t versionSeen;
  };
  std::vector<Input> m_inputs;
  bool m_forceUpdate = true;
  bool m_running = false;
};

}  // namespace stroma
