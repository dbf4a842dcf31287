// SPDX-License-Identifier: MIT
// SOFA's state file, as its WriteState writes it and its ReadState reads it: records of
//
//   T= 0.02
//     X= x0 y0 z0 x1 y1 z1 ...     (positions, every number of every degree of freedom)
//     X0= ...                      (rest positions)
//     V= ...                       (velocities)
//     F= ...                       (forces)
//
// each vector line optional. A file name ending in ".gz" is gzip-compressed (zlib), as SOFA's.
// Stroma writes the numbers with the shortest text that reads back as the same double (SOFA
// writes 6 significant digits): a replay is then exact.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace stroma {

struct SofaStateRecord {
  double time = 0;
  int line = 0;  ///< line of its "T=" in the file (1-based), for messages
  std::vector<double> positions, restPositions, velocities, forces;
  bool hasPositions = false, hasRestPositions = false, hasVelocities = false, hasForces = false;
};

/// Reads a whole state file. False with `error` naming the line (or why the file cannot be
/// opened) on a missing or malformed file: a vector line before the first "T=", an unknown
/// key, a number that does not read, a time that goes back.
bool readSofaStateFile(const std::filesystem::path& file, std::vector<SofaStateRecord>& records,
                       std::string& error);

/// Writes records one at a time (gzip-compressed when the name ends in ".gz").
class SofaStateWriter {
 public:
  SofaStateWriter();
  ~SofaStateWriter();
  SofaStateWriter(const SofaStateWriter&) = delete;
  SofaStateWriter& operator=(const SofaStateWriter&) = delete;

  /// Creates (truncates) the file. False with `error` when it cannot.
  bool open(const std::filesystem::path& file, std::string& error);
  bool isOpen() const;
  /// Appends the record's time and the vectors it has. False with `error` on a write failure.
  bool write(const SofaStateRecord& record, std::string& error);
  /// Flushes and closes; false with `error` when the last writes failed.
  bool close(std::string& error);

  /// Whether this build reads and writes ".gz" files (zlib found when it was configured).
  static bool supportsGzip();

 private:
  struct Sink;
  std::unique_ptr<Sink> m_sink;
  std::filesystem::path m_file;
};

}  // namespace stroma
