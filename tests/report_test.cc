// report.html in a real browser (headless Chromium): fit_sequence on the bundled barrel, then the
// page loads with no console messages, has one card per step of sequence.json, each with a drawn
// rendering inside the page, and a full-page screenshot is taken (kept for the closing note).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ops/params.h"
#include "tests/blender_runner.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

// Appended by the test only (the page itself has no script): what the browser laid out.
constexpr const char* kProbe = R"JS(<script>
const cards = [...document.querySelectorAll('.card.step')];
const height = document.documentElement.scrollHeight;
const drawn = cards.filter(c => {
  const r = c.getBoundingClientRect();
  const svg = c.querySelector('svg');
  return r.width > 100 && r.bottom <= height && svg && svg.getBoundingClientRect().height > 100 &&
         svg.querySelectorAll('polygon').length > 0;
}).length;
document.title = 'probe ' + JSON.stringify({cards: cards.length, drawn: drawn, height: height});
</script>)JS";

TEST(Report, ChromiumShowsEveryStepCard) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_report_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "barrel").string();
  const std::string fit = std::string(OPGRAPH_FIT_SEQUENCE) + " --input '" + OPGRAPH_SOURCE_DIR +
                          "/examples/barrel.obj' --out '" + out + "' --work-budget 3000 --quiet > /dev/null";
  ASSERT_EQ(std::system(fit.c_str()), 0) << fit;
  const Json sequence = Json::parse(std::ifstream(out + "/sequence.json"));
  std::string page = ReadText(out + "/report.html");
  ASSERT_NE(page.find("</body>"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos) << "the report needs no script";
  page.insert(page.find("</body>"), kProbe);
  std::ofstream(dir / "probed.html") << page;

  const std::string chromium = "chromium --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0 ";
  const std::string dump = chromium + "--dump-dom 'file://" + (dir / "probed.html").string() + "' > '" +
                           (dir / "dom.html").string() + "' 2> '" + (dir / "console.log").string() + "'";
  ASSERT_EQ(std::system(dump.c_str()), 0) << dump;
  EXPECT_EQ(ReadText((dir / "console.log").string()).find("CONSOLE"), std::string::npos) << ReadText((dir / "console.log").string());
  const std::string dom = ReadText((dir / "dom.html").string());
  const size_t start = dom.find("<title>probe ");
  ASSERT_NE(start, std::string::npos) << "the probe did not run";
  const size_t json_start = start + std::string("<title>probe ").size();
  const Json probe = Json::parse(dom.substr(json_start, dom.find("</title>", json_start) - json_start));
  EXPECT_EQ(probe["cards"], sequence["operations"].size());
  EXPECT_EQ(probe["drawn"], sequence["operations"].size());

  // The whole page in one screenshot.
  const std::string shot = chromium + "--screenshot='" + out + "/report.png' --window-size=1200," +
                           std::to_string(probe["height"].get<int>()) + " 'file://" + out + "/report.html' > /dev/null 2>&1";
  ASSERT_EQ(std::system(shot.c_str()), 0) << shot;
  EXPECT_GT(fs::file_size(out + "/report.png"), 10000u);
  if (const char* keep = std::getenv("OPGRAPH_KEEP_REPORT")) fs::copy_file(out + "/report.png", keep, fs::copy_options::overwrite_existing);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
