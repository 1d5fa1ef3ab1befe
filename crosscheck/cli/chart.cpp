// crosscheck chart BENCH.json [-o chart.svg]: the speed-vs-accuracy chart of a bench run (see
// commands.hpp) as a standalone SVG (output/chart_svg.hpp). Default output: the JSON's path with
// .svg in place of .json. An unreadable or malformed JSON, or an unwritable output, is one error
// line naming the file and exit status 2.
// Deliberately no rendering: the chart draws what the bench measured.
#include "cli/commands.hpp"

#include "output/chart_svg.hpp"
#include "output/markup.hpp"
#include "scene/input_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace crosscheck::cli {

int chartCommand(const ChartCommand& command) {
  const std::filesystem::path input(command.benchJson);
  if (const softraster::Status readable = checkInputFile(input); !readable) {
    return failWith(command.benchJson + ": " + readable.message());
  }
  std::ifstream file(input, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  if (!file && !file.eof()) return failWith(command.benchJson + ": cannot read this file");
  const auto set = chartFromBenchJson(text.str(), command.benchJson);
  if (!set) return failWith(set.error());
  std::filesystem::path output(command.output);
  if (output.empty()) output = std::filesystem::path(input).replace_extension(".svg");
  const softraster::Status written = writeDocument(output, chartDocument(*set), "the chart");
  if (!written) return failWith(written);
  std::size_t points = 0;
  for (const ChartScene& scene : set->scenes) points += scene.points.size();
  std::printf("chart: %zu scenes, %zu points: %s\n", set->scenes.size(), points, output.string().c_str());
  return 0;
}

}  // namespace crosscheck::cli
