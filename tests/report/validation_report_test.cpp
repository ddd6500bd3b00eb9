// The report: JSON with the figures, HTML page, gnuplot figures where gnuplot exists.
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report/validation_report.hpp"

namespace lfd::report {
namespace {

ValidationCase small_case() {
  ValidationCase c;
  c.name = "true";
  c.truth_source = "truth.json";
  c.assumed_source = "truth.json";
  c.profiles.views = 2;
  c.profiles.panel_points = 1;
  c.profiles.theta_deg = {-5, 5};
  c.profiles.view = {{0.9, 0.1}, {0.2, 0.8}};
  c.profiles.black = {0.0, 0.0};
  c.summary = validate::summarise(c.profiles);
  return c;
}

TEST(ValidationReport, WritesJsonHtmlAndFigures) {
  const auto dir = std::filesystem::temp_directory_path() / ("lfd_validate_report_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto index = write_report(dir, {small_case()});
  ASSERT_TRUE(std::filesystem::exists(index));
  std::ifstream f(dir / "validation.json");
  const auto j = nlohmann::json::parse(f);
  ASSERT_EQ(j["cases"].size(), 1u);
  EXPECT_NEAR(j["cases"][0]["per_view"][0]["separation"].get<double>(), 0.9 / 1.1, 1e-9);
  EXPECT_EQ(j["cases"][0]["profiles"]["views"].size(), 2u);
  if (std::system("gnuplot --version > /dev/null 2>&1") == 0) {
    EXPECT_TRUE(std::filesystem::exists(dir / "true_profiles.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "true_views.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "true_views.png.tmp"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lfd::report
