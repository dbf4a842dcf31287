// SPDX-License-Identifier: MIT
// Error-against-run-time charts (issues 6 and 7): a CSV for the numbers and a PNG drawn by
// gnuplot (Debian's gnuplot-nox), so that every report of Stroma plots the same way. The CSV is
// always written; the PNG needs gnuplot on the PATH, and its absence is reported, not fatal.
#pragma once

#include <string>
#include <vector>

namespace stroma::report {

/// One curve: a name for the legend and its points (x[i], y[i]).
struct ChartSeries {
  std::string name;
  std::vector<double> x;
  std::vector<double> y;
};

struct ChartAxes {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = false;
  bool logY = false;
};

/// Writes `csvPath` with the columns series,x,y (one row per point, headed by the axis labels
/// in a comment line). Returns an empty string, or what went wrong (file not writable).
std::string writeChartCsv(const std::string& csvPath, const ChartAxes& axes,
                          const std::vector<ChartSeries>& series);

/// Draws the series into `pngPath` with gnuplot (lines and points, one colour per series, log
/// scales as asked; points with y <= 0 are left out of a log axis, as gnuplot would refuse
/// them). The gnuplot script and its data are written beside the PNG as `<png>.gp` and
/// `<png>.dat`, so that a user can restyle the plot. Returns an empty string, or what went
/// wrong ("gnuplot not found: install the Debian package gnuplot-nox", gnuplot's exit code).
std::string writeChartPng(const std::string& pngPath, const ChartAxes& axes,
                          const std::vector<ChartSeries>& series);

/// True when a `gnuplot` executable is on the PATH.
bool gnuplotAvailable();

}  // namespace stroma::report
