// SPDX-License-Identifier: MIT
#include "report/Chart.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace stroma::report {
namespace {

std::filesystem::path scratch(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / "stroma_chart_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::vector<ChartSeries> twoCurves() {
  return {{"cg", {1, 2, 4, 8}, {1.0, 0.5, 0.25, 0.125}},
          {"multigrid", {0.5, 1}, {1e-2, 1e-5}}};
}

TEST(Chart, CsvHoldsEveryPointOfEverySeries) {
  const auto path = scratch("curves.csv");
  ChartAxes axes{"error against time", "time (s)", "error", true, true};
  ASSERT_EQ(writeChartCsv(path.string(), axes, twoCurves()), "");
  std::ifstream in(path);
  std::string comment, header, line;
  std::getline(in, comment);
  std::getline(in, header);
  EXPECT_EQ(header, "series,x,y");
  int rows = 0;
  double lastY = 0;
  while (std::getline(in, line)) {
    ++rows;
    lastY = std::stod(line.substr(line.rfind(',') + 1));
  }
  EXPECT_EQ(rows, 6);
  EXPECT_DOUBLE_EQ(lastY, 1e-5);
}

TEST(Chart, UnwritableCsvIsReported) {
  ChartAxes axes;
  EXPECT_NE(writeChartCsv("/nonexistent-dir/x.csv", axes, twoCurves()), "");
}

TEST(Chart, PngIsDrawnByGnuplot) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  const auto png = scratch("curves.png");
  std::filesystem::remove(png);
  // A non-positive value on a log axis is left out rather than making gnuplot fail.
  auto series = twoCurves();
  series[0].y[0] = 0;
  ChartAxes axes{"error against time", "time (s)", "error", true, true};
  ASSERT_EQ(writeChartPng(png.string(), axes, series), "");
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
}

TEST(Chart, NothingToPlotIsReported) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  ChartAxes axes{"t", "x", "y", false, true};
  EXPECT_NE(writeChartPng(scratch("empty.png").string(), axes, {{"zero", {1, 2}, {0, 0}}}), "");
}

}  // namespace
}  // namespace stroma::report
