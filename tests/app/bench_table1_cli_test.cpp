// sculpt-cli bench table1 end to end: the models of assets/table1/ have the paper's control-cell
// counts and are valid, and the benchmark prints one table row per model and its summary line.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_fixture.h"

namespace sculpt {
namespace {

using test::CliResult;
using test::keyValues;
using test::quote;

const std::string kModels = SCULPT_SOURCE_DIR "/assets/table1";

// File and control cells of each model of the paper's Table 1, in its order.
const std::vector<std::pair<std::string, int>> kTable = {
    {"soccer-player.json", 24}, {"sea-monster.json", 38}, {"block3.json", 27},
    {"chair.json", 76},         {"block4.json", 64},      {"head.json", 123},
    {"bridge.json", 150},       {"nozzle.json", 99}};

// The cells of a Markdown table row, trimmed.
std::vector<std::string> cellsOf(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream in(row.substr(1));
  for (std::string cell; std::getline(in, cell, '|');) {
    const size_t first = cell.find_first_not_of(' ');
    const size_t last = cell.find_last_not_of(' ');
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  return cells;
}

double positiveNumber(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  EXPECT_TRUE(!text.empty() && end == text.c_str() + text.size()) << "'" << text << "'";
  EXPECT_TRUE(std::isfinite(value) && value > 0) << text;
  return value;
}

class BenchTable1CliTest : public test::CliFixture {
 protected:
  BenchTable1CliTest() : CliFixture("sculpt_bench_table1_cli_test_") {}
};

TEST_F(BenchTable1CliTest, EachModelHasThePapersCellCountAndIsValid) {
  for (const auto& [file, cells] : kTable) {
    SCOPED_TRACE(file);
    const CliResult result = run("info " + quote(kModels + "/" + file));
    EXPECT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.out.find("\ncells: " + std::to_string(cells) + "\n"), std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("validation: valid\n"), std::string::npos) << result.out;
  }
}

TEST_F(BenchTable1CliTest, PrintsARowPerModelAndTheLeastSpeedups) {
  const CliResult result = run("bench table1 --steps 2 --models " + quote(kModels));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(result.out);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| ", 0) == 0) rows.push_back(cellsOf(line));
  ASSERT_EQ(rows.size(), kTable.size() + 1) << result.out;  // the header, then the models
  const size_t columns = rows[0].size();
  for (size_t m = 0; m < kTable.size(); ++m) {
    const std::vector<std::string>& row = rows[m + 1];
    SCOPED_TRACE(row[0]);
    ASSERT_EQ(row.size(), columns);
    EXPECT_EQ(row[1], std::to_string(kTable[m].second));  // the paper's #CC
    EXPECT_EQ(row[8], row[1]);                            // ours
    positiveNumber(row[9]);                               // our #FE
    for (size_t c = columns - 6; c < columns; ++c) positiveNumber(row[c]);  // ms, FPS, ratio
  }
  const test::KeyValues last = keyValues(result.lastLine());
  ASSERT_EQ(last.size(), 3u) << result.lastLine();
  EXPECT_EQ(last[0], (std::pair<std::string, std::string>("models", "8")));
  EXPECT_EQ(last[1].first, "min_speedup_paper");
  EXPECT_EQ(last[2].first, "min_speedup_implicit");
  positiveNumber(last[1].second);
  positiveNumber(last[2].second);
}

TEST_F(BenchTable1CliTest, BadUsageIsOneErrorLine) {
  expectBadInput("bench table1 --steps 0", "--steps");
  expectBadInput("bench table1 extra.json", "table1");
  expectBadInput("bench table1 --models " + quote(path("none")), "soccer-player.json");
}

}  // namespace
}  // namespace sculpt
