// SPDX-License-Identifier: MIT
#include "report/Chart.h"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace stroma::report {
namespace {

// Gnuplot strings are single-quoted: a quote inside is doubled.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

bool plottable(const ChartAxes& axes, double x, double y) {
  if (axes.logX && !(x > 0)) return false;
  if (axes.logY && !(y > 0)) return false;
  return true;
}

}  // namespace

std::string writeChartCsv(const std::string& csvPath, const ChartAxes& axes,
                          const std::vector<ChartSeries>& series) {
  std::ofstream out(csvPath);
  if (!out) return "cannot write '" + csvPath + "'";
  out << "# " << axes.title << ": x = " << axes.xLabel << ", y = " << axes.yLabel << '\n';
  out << "series,x,y\n" << std::setprecision(10);
  for (const ChartSeries& s : series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      out << s.name << ',' << s.x[i] << ',' << s.y[i] << '\n';
  if (!out) return "cannot write '" + csvPath + "'";
  return {};
}

bool gnuplotAvailable() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

std::string writeChartPng(const std::string& pngPath, const ChartAxes& axes,
                          const std::vector<ChartSeries>& series) {
  if (!gnuplotAvailable())
    return "gnuplot not found on the PATH (Debian package gnuplot-nox): '" + pngPath +
           "' not drawn";
  const std::string dataPath = pngPath + ".dat", scriptPath = pngPath + ".gp";
  {
    // One gnuplot data block per series, separated by two blank lines (gnuplot's "index").
    std::ofstream data(dataPath);
    if (!data) return "cannot write '" + dataPath + "'";
    data << std::setprecision(10);
    for (const ChartSeries& s : series) {
      data << "# " << s.name << '\n';
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
        if (plottable(axes, s.x[i], s.y[i])) data << s.x[i] << ' ' << s.y[i] << '\n';
      data << "\n\n";
    }
  }
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,700 font ',11'\n"
     << "set output " << quoted(pngPath) << '\n'
     << "set title " << quoted(axes.title) << " noenhanced\n"
     << "set xlabel " << quoted(axes.xLabel) << " noenhanced\n"
     << "set ylabel " << quoted(axes.yLabel) << " noenhanced\n"
     << "set key outside right top noenhanced\n"
     << "set grid xtics ytics mxtics mytics\n";
  if (axes.logX) gp << "set logscale x\nset format x '10^{%L}'\n";
  if (axes.logY) gp << "set logscale y\nset format y '10^{%L}'\n";
  gp << "plot ";
  bool first = true;
  for (std::size_t k = 0; k < series.size(); ++k) {
    bool any = false;
    for (std::size_t i = 0; i < series[k].x.size() && i < series[k].y.size(); ++i)
      any = any || plottable(axes, series[k].x[i], series[k].y[i]);
    if (!any) continue;  // gnuplot stops on an empty data block
    gp << (first ? "" : ", \\\n     ") << quoted(dataPath) << " index " << k
       << " using 1:2 with linespoints title " << quoted(series[k].name);
    first = false;
  }
  if (first) return "no point to plot in '" + pngPath + "' (all empty or not positive on a log axis)";
  gp << '\n';
  {
    std::ofstream script(scriptPath);
    if (!script) return "cannot write '" + scriptPath + "'";
    script << gp.str();
  }
  const std::string command = "gnuplot " + shellQuoted(scriptPath) + " 2>&1";
  const int status = std::system(command.c_str());
  if (status != 0)
    return "gnuplot failed on '" + scriptPath + "' (exit status " + std::to_string(status) + ")";
  return {};
}

}  // namespace stroma::report
