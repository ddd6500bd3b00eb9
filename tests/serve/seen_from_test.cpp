// The console's "Seen from" (serve/seen_from.hpp) against the test double: a panel whose
// subpixels carry their own view fraction (display/fraction_panel.hpp) seen from the first view's
// angle is bright at the centre and from the middle view's dark, so the angle rule, the optics
// and the picture meet; the bounds (one at a time, the budget, bad input, no picture) answer as
// docs/console.md says, through the route too.
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <future>
#include <mutex>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "display/fraction_panel.hpp"
#include "serve/seen_from.hpp"
#include "serve/service.hpp"
#include "tests/serve/fake_display_service.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/error.hpp"
#include "util/png_codec.hpp"

namespace lfd::serve {
namespace {

Image8 decoded_png(const std::string& bytes) {
  std::FILE* f = fmemopen(const_cast<char*>(bytes.data()), bytes.size(), "rb");
  EXPECT_TRUE(f && png::has_png_signature(f));
  Image8 image = png::decode(f, "seen from", 3);
  std::fclose(f);
  return image;
}

// The mean grey (0..255) of the central tenth of a picture each way.
double central_mean(const Image8& image) {
  double sum = 0;
  int n = 0;
  const int w = std::max(1, image.width / 10), h = std::max(1, image.height / 10);
  for (int y = (image.height - h) / 2; y < (image.height + h) / 2; ++y)
    for (int x = (image.width - w) / 2; x < (image.width + w) / 2; ++x, ++n)
      for (int ch = 0; ch < 3; ++ch) sum += image.pixels[(std::size_t(y) * image.width + x) * 3 + ch] / 3.0;
  return sum / n;
}

struct SeenFromTest : ::testing::Test {
  ServedDisplay served = test::fixture_display();
  test::FakeDisplayService fake{{served}};
  MemoryBudget budget{512u << 20};
  SeenFromRenderer renderer{fake, budget};

  void SetUp() override {
    const display::LensModel lens(served.calibration.display, served.calibration.correction);
    fake.panel = to_uint8(display::view_fraction_panel(lens, false));  // 1/2 + 1/2 cos(2 pi f)
  }
};

TEST_F(SeenFromTest, TheFirstViewsAngleSeesItsFractionAndTheMiddleViewsTheOpposite) {
  const SeenFromRange range = renderer.range(0);
  EXPECT_EQ(range.views, served.default_quilt.views);
  EXPECT_LT(range.first_view_deg, 0);
  EXPECT_NEAR(range.first_view_deg, -range.last_view_deg, 1e-9);  // the cone is symmetric
  EXPECT_LT(range.last_view_deg, range.cone_deg / 2);
  EXPECT_DOUBLE_EQ(renderer.angle_of_view(0, 0), range.first_view_deg);
  // View 0's middle is fraction 1/(2 views): cos near 1, bright. The middle view's is 1/2: dark.
  const Image8 first = decoded_png(renderer.png(0, range.first_view_deg, 64));
  const Image8 middle = decoded_png(renderer.png(0, renderer.angle_of_view(0, (range.views - 1) / 2.0), 64));
  EXPECT_EQ(first.height, 64);
  const auto& c = served.calibration.display;
  EXPECT_NEAR(double(first.width) / first.height, c.width_m() / c.height_m(), 0.03);
  EXPECT_GT(central_mean(first), 200) << "seen from the first view the centre shows fraction 1/(2 views)";
  EXPECT_LT(central_mean(middle), 40) << "seen from the middle view the centre shows fraction 1/2";
}

TEST_F(SeenFromTest, BadRequestsAreInputErrorsAndNothingShownIsBusy) {
  EXPECT_THROW(renderer.png(1, 0, 64), InputError);
  EXPECT_THROW(renderer.png(0, 95, 64), InputError);
  EXPECT_THROW(renderer.png(0, std::nan(""), 64), InputError);
  EXPECT_THROW(renderer.png(0, 0, kSeenFromMaxHeightPx + 1), InputError);
  EXPECT_THROW(renderer.png(0, 0, kSeenFromMinHeightPx - 1), InputError);
  EXPECT_THROW(renderer.angle_of_view(0, -0.5), InputError);
  EXPECT_THROW(renderer.angle_of_view(0, served.default_quilt.views), InputError);
  fake.panel.reset();  // the display gave no picture in time
  EXPECT_THROW(renderer.png(0, 0, 64), BusyError);
  EXPECT_EQ(budget.used(), 0u) << "the panel's reservation went with the refusal";
}

TEST_F(SeenFromTest, APanelTheBudgetCannotHoldNowIsBusy) {
  // Room for the panel, but not while something else holds a little of it.
  MemoryBudget small{std::size_t(served.calibration.display.screen_w) * served.calibration.display.screen_h * 3 * 5 + 10};
  const auto held = small.reserve_or_busy(20, "something else");
  SeenFromRenderer tight{fake, small};
  EXPECT_THROW(tight.png(0, 0, 64), BusyError);
}

// A display whose read-back waits until the test lets it go: a second picture asked meanwhile
// is busy at once, not queued.
struct HeldDisplay : test::FakeDisplayService {
  using FakeDisplayService::FakeDisplayService;
  std::mutex gate;
  std::condition_variable opened;
  bool asked = false, released = false;
  std::optional<Image8> panel_picture(int display, std::chrono::milliseconds wait) override {
    std::unique_lock lock(gate);
    asked = true;
    opened.notify_all();
    opened.wait(lock, [&] { return released; });
    return FakeDisplayService::panel_picture(display, wait);
  }
};

TEST(SeenFromBounds, OneAtATimeTheNextIsBusyAtOnce) {
  HeldDisplay held{{test::fixture_display()}};
  const ServedDisplay d = test::fixture_display();
  held.panel = Image8(d.calibration.display.screen_w, d.calibration.display.screen_h, 3);
  MemoryBudget budget{512u << 20};
  SeenFromRenderer renderer{held, budget};
  auto first = std::async(std::launch::async, [&] { return renderer.png(0, 0, 32); });
  {
    std::unique_lock lock(held.gate);
    held.opened.wait(lock, [&] { return held.asked; });
  }
  EXPECT_THROW(renderer.png(0, 0, 32), BusyError);
  {
    std::lock_guard lock(held.gate);
    held.released = true;
  }
  held.opened.notify_all();
  EXPECT_EQ(decoded_png(first.get()).height, 32);
  EXPECT_NO_THROW(renderer.png(0, 0, 32)) << "free again once the first is done";
}

TEST(SeenFromRoute, AnswersAPictureByAngleOrViewAndRefusesInOneLine) {
  test::TempDir dir;
  test::FakeDisplayService fake{{test::fixture_display()}};
  const ServedDisplay d = test::fixture_display();
  fake.panel = Image8(d.calibration.display.screen_w, d.calibration.display.screen_h, 3);
  ServeOptions options;
  options.listen = {"127.0.0.1", test::free_port(), test::free_port(), test::free_port()};
  options.content_folder = dir.path / "content";
  Service service(fake, options);
  service.start();
  httplib::Client client("127.0.0.1", options.listen.bridge_port);
  const auto by_angle = client.Get("/seen_from?angle=-10.5&height=40");
  ASSERT_TRUE(by_angle);
  EXPECT_EQ(by_angle->status, 200);
  EXPECT_EQ(by_angle->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(by_angle->get_header_value("X-Seen-From-Angle"), "-10.50");
  EXPECT_EQ(decoded_png(by_angle->body).height, 40);
  const auto by_view = client.Get("/seen_from?display=0&view=0");
  ASSERT_TRUE(by_view);
  EXPECT_EQ(by_view->status, 200);
  const auto range = client.Get("/seen_from/range");
  ASSERT_TRUE(range);
  const auto r = nlohmann::json::parse(range->body);
  EXPECT_EQ(by_view->get_header_value("X-Seen-From-Angle"), fmt::format("{:.2f}", r.at("first_view_deg").get<double>()));
  for (const char* bad : {"/seen_from", "/seen_from?angle=1&view=1", "/seen_from?angle=abc", "/seen_from?angle=1&height=2x",
                          "/seen_from?angle=1&display=3", "/seen_from?angle=1e400"}) {
    const auto refused = client.Get(bad);
    ASSERT_TRUE(refused) << bad;
    EXPECT_EQ(refused->status, 400) << bad;
    const std::string error = nlohmann::json::parse(refused->body).at("error");
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  fake.panel.reset();
  const auto busy = client.Get("/seen_from?angle=0");
  ASSERT_TRUE(busy);
  EXPECT_EQ(busy->status, 503);
  EXPECT_EQ(busy->get_header_value("Retry-After"), "1");
  service.stop();
}

}  // namespace
}  // namespace lfd::serve
