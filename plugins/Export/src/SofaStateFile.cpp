// SPDX-License-Identifier: MIT
#include "SofaStateFile.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "VtkFiles.h"

#if STROMA_EXPORT_HAS_ZLIB
#include <zlib.h>
#endif

namespace stroma {

namespace fs = std::filesystem;

namespace {

bool isGzipName(const fs::path& file) { return file.string().ends_with(".gz"); }

bool readAll(const fs::path& file, std::string& text, std::string& error) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) {
    error = "cannot open state file '" + file.string() + "' (no such file)";
    return false;
  }
  if (isGzipName(file)) {
#if STROMA_EXPORT_HAS_ZLIB
    gzFile in = gzopen(file.string().c_str(), "rb");
    if (!in) {
      error = "cannot open state file '" + file.string() + "'";
      return false;
    }
    char buffer[1 << 16];
    int n = 0;
    while ((n = gzread(in, buffer, sizeof buffer)) > 0) text.append(buffer, n);
    const bool failed = n < 0;
    gzclose(in);
    if (failed)
      error = std::string("'").append(file.string()).append("' is not a readable gzip file");
    return !failed;
#else
    error = std::string("'").append(file.string()) +
            "': this build reads no .gz files (zlib was not found when "
            "it was configured; install zlib1g-dev and rebuild, or gunzip the file)";
    return false;
#endif
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    error = "cannot open state file '" + file.string() + "'";
    return false;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  return true;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

/// The numbers of `text`, space separated. False with `bad` = the token that does not read.
bool readNumbers(std::string_view text, std::vector<double>& values, std::string& bad) {
  values.clear();
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
    const std::string_view token = text.substr(i, j - i);
    double v = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size()) {
      bad = std::string(token);
      return false;
    }
    values.push_back(v);
    i = j;
  }
  return true;
}

}  // namespace

bool readSofaStateFile(const fs::path& file, std::vector<SofaStateRecord>& records,
                       std::string& error) {
  records.clear();
  std::string text;
  if (!readAll(file, text, error)) return false;
  const std::string where = "state file '" + file.string() + "' line ";
  std::size_t start = 0;
  int lineNumber = 0;
  std::vector<double> values;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view line = trim(std::string_view(text).substr(start, end - start));
    start = end + 1;
    ++lineNumber;
    if (line.empty()) continue;
    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos) {
      error = where + std::to_string(lineNumber) +
              ": expected 'KEY= values' (T=, X=, X0=, V=, "
              "F=), got '" +
              std::string(line.substr(0, 40)) + "'";
      return false;
    }
    const std::string key(trim(line.substr(0, equals)));
    std::string bad;
    if (!readNumbers(line.substr(equals + 1), values, bad)) {
      error = where + std::to_string(lineNumber) + ": '" + bad + "' is not a number (" + key + "=)";
      return false;
    }
    if (key == "T") {
      if (values.size() != 1) {
        error = where + std::to_string(lineNumber) + ": T= takes one time, got " +
                std::to_string(values.size()) + " numbers";
        return false;
      }
      if (!records.empty() && values[0] < records.back().time) {
        error = where + std::to_string(lineNumber) + ": time " + vtk::formatNumber(values[0]) +
                " comes after time " + vtk::formatNumber(records.back().time) +
                " (times must not decrease)";
        return false;
      }
      SofaStateRecord r;
      r.time = values[0];
      r.line = lineNumber;
      records.push_back(std::move(r));
      continue;
    }
    if (records.empty()) {
      error = where + std::to_string(lineNumber) + ": " + key + "= before the first T= line";
      return false;
    }
    SofaStateRecord& r = records.back();
    if (key == "X")
      r.positions = values, r.hasPositions = true;
    else if (key == "X0")
      r.restPositions = values, r.hasRestPositions = true;
    else if (key == "V")
      r.velocities = values, r.hasVelocities = true;
    else if (key == "F")
      r.forces = values, r.hasForces = true;
    else {
      error = where + std::to_string(lineNumber) + ": unknown key '" + key +
              "=' (expected T=, X=, X0=, V= or F=)";
      return false;
    }
  }
  return true;
}

// One of a plain file or a gzip stream.
struct SofaStateWriter::Sink {
  std::ofstream plain;
#if STROMA_EXPORT_HAS_ZLIB
  gzFile gz = nullptr;
#endif
  bool failed = false;
  void put(const std::string& text) {
#if STROMA_EXPORT_HAS_ZLIB
    if (gz) {
      if (gzwrite(gz, text.data(), static_cast<unsigned>(text.size())) !=
          static_cast<int>(text.size()))
        failed = true;
      return;
    }
#endif
    plain << text;
    if (!plain) failed = true;
  }
};

SofaStateWriter::SofaStateWriter() = default;
SofaStateWriter::~SofaStateWriter() {
  std::string ignored;
  close(ignored);
}

bool SofaStateWriter::supportsGzip() { return STROMA_EXPORT_HAS_ZLIB != 0; }

bool SofaStateWriter::open(const fs::path& file, std::string& error) {
  std::string ignored;
  close(ignored);
  m_file = file;
  auto sink = std::make_unique<Sink>();
  if (isGzipName(file)) {
#if STROMA_EXPORT_HAS_ZLIB
    sink->gz = gzopen(file.string().c_str(), "wb");
    if (!sink->gz) {
      error = "cannot write '" + file.string() + "'";
      return false;
    }
#else
    error = std::string("'").append(file.string()) +
            "': this build writes no .gz files (zlib was not found when "
            "it was configured); name the file without .gz";
    return false;
#endif
  } else {
    sink->plain.open(file, std::ios::binary | std::ios::trunc);
    if (!sink->plain) {
      error = "cannot write '" + file.string() + "'";
      return false;
    }
  }
  m_sink = std::move(sink);
  return true;
}

bool SofaStateWriter::isOpen() const { return m_sink != nullptr; }

bool SofaStateWriter::write(const SofaStateRecord& record, std::string& error) {
  if (!m_sink) {
    error = "the state file is not open";
    return false;
  }
  std::string text = "T= " + vtk::formatNumber(record.time) + "\n";
  auto vector = [&](const char* key, bool has, const std::vector<double>& values) {
    if (!has) return;
    text += "  ";
    text += key;
    text += "=";
    for (double v : values) {
      text += ' ';
      text += vtk::formatNumber(v);
    }
    text += "\n";
  };
  vector("X", record.hasPositions, record.positions);
  vector("X0", record.hasRestPositions, record.restPositions);
  vector("V", record.hasVelocities, record.velocities);
  vector("F", record.hasForces, record.forces);
  m_sink->put(text);
  if (m_sink->failed) {
    error = "writing '" + m_file.string() + "' failed (disk full?)";
    return false;
  }
  return true;
}

bool SofaStateWriter::close(std::string& error) {
  if (!m_sink) return true;
  bool ok = !m_sink->failed;
#if STROMA_EXPORT_HAS_ZLIB
  if (m_sink->gz) ok = gzclose(m_sink->gz) == Z_OK && ok;
#endif
  if (m_sink->plain.is_open()) {
    m_sink->plain.flush();
    ok = ok && static_cast<bool>(m_sink->plain);
  }
  m_sink.reset();
  if (!ok) error = "writing '" + m_file.string() + "' failed (disk full?)";
  return ok;
}

}  // namespace stroma
