// The Gen1 EEPROM reader against a fake HoloPlay serving the real calibrations of
// tests/data/calibrations: the text read equals the visual.json served byte for byte, through
// stale button reports, replies to other pages and commands, split and truncated reports and
// lost requests; erased, damaged and non-calibration EEPROMs, a disconnect and a silent device
// end in a one-line error naming the device, within the deadlines of the fake clock.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "device/device_error.hpp"
#include "device/gen1_eeprom.hpp"
#include "display/visual_json.hpp"
#include "tests/device/fake_holoplay.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::device {
namespace {

using namespace std::chrono_literals;
using test::FakeClock;
using test::FakeHoloPlay;

std::string fixture_text(const std::string& name = "gen1-hid-00297.visual.json") {
  return read_text_file(test::fixture_calibration(name));
}

Gen1ReadOptions fake_options(FakeClock& clock) {
  Gen1ReadOptions o;
  o.clock = clock.fn();
  return o;
}

// Runs `read` and returns its error message; fails the test when it succeeds or throws another type.
template <typename Error>
std::string error_of(FakeHoloPlay& device, FakeClock& clock, const Gen1ReadOptions& options) {
  try {
    read_gen1_calibration(device, options);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an error";
  return {};
}

TEST(Gen1Eeprom, ReadsEveryRealCalibrationByteForByte) {
  for (const auto& path : test::fixture_calibrations()) {
    const std::string text = read_text_file(path);
    FakeClock clock;
    FakeHoloPlay device(test::eeprom_image(text, 64 * 1024), clock);
    Gen1ReadStats stats;
    EXPECT_EQ(read_gen1_calibration(device, fake_options(clock), &stats), text) << path;
    EXPECT_EQ(stats.pages, int((text.size() + 4 + 63) / 64)) << path;
  }
}

TEST(Gen1Eeprom, SkipsStaleButtonReportsQueuedBeforeAndBetweenReplies) {
  const std::string text = fixture_text();
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text), clock);
  device.pending_at_open = 40;
  device.stale_reports_before_reply = 3;
  Gen1ReadStats stats;
  EXPECT_EQ(read_gen1_calibration(device, fake_options(clock), &stats), text);
  EXPECT_GT(stats.skipped_reports, 3 * stats.pages);
}

TEST(Gen1Eeprom, SkipsRepliesToOtherPagesAndCommands) {
  const std::string text = fixture_text();
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text), clock);
  device.wrong_page_first = true;
  device.wrong_command_first = true;
  EXPECT_EQ(read_gen1_calibration(device, fake_options(clock)), text);
}

TEST(Gen1Eeprom, JoinsReportsThatArriveAs64Plus4Bytes) {
  const std::string text = fixture_text("LKG-2K-04409.visual.json");
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text), clock);
  device.split_replies = true;
  device.stale_reports_before_reply = 1;
  EXPECT_EQ(read_gen1_calibration(device, fake_options(clock)), text);
}

TEST(Gen1Eeprom, DropsATruncatedReplyAndAsksAgain) {
  const std::string text = fixture_text();
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text), clock);
  device.truncate_first_replies = 2;
  Gen1ReadStats stats;
  EXPECT_EQ(read_gen1_calibration(device, fake_options(clock), &stats), text);
  EXPECT_EQ(stats.dropped_fragments, 2);
  EXPECT_GT(stats.requests, stats.pages);
}

TEST(Gen1Eeprom, AsksAgainForAPageWhoseRequestWasLost) {
  const std::string text = fixture_text();
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text), clock);
  device.ignore_first_requests = 2;
  EXPECT_EQ(read_gen1_calibration(device, fake_options(clock)), text);
}

TEST(Gen1Eeprom, ErasedEepromIsAnInputErrorSayingSo) {
  FakeClock clock;
  FakeHoloPlay device(std::vector<uint8_t>(4096, 0xff), clock);
  const std::string message = error_of<InputError>(device, clock, fake_options(clock));
  EXPECT_NE(message.find("erased"), std::string::npos) << message;
  EXPECT_NE(message.find("/dev/hidraw-fake"), std::string::npos) << message;
}

TEST(Gen1Eeprom, LengthPrefixBeyondTheBoundIsRefusedWithoutReadingOn) {
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(fixture_text(), 4096, 0x00100000, true), clock);
  const std::string message = error_of<InputError>(device, clock, fake_options(clock));
  EXPECT_NE(message.find("1048576 bytes"), std::string::npos) << message;
  EXPECT_EQ(device.requests, 1);  // only page 0
}

TEST(Gen1Eeprom, EmptyEepromIsAnInputError) {
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image("", 4096), clock);
  EXPECT_NE(error_of<InputError>(device, clock, fake_options(clock)).find("empty"), std::string::npos);
}

TEST(Gen1Eeprom, LengthPrefixBeyondTheTextReadsPaddingAndFailsAsJson) {
  // A length within the bound but longer than the text: the 0xFF padding is no JSON.
  const std::string text = fixture_text();
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text, 8192, uint32_t(text.size() + 500), true), clock);
  const std::string message = error_of<InputError>(device, clock, fake_options(clock));
  EXPECT_NE(message.find("EEPROM calibration"), std::string::npos) << message;
}

TEST(Gen1Eeprom, TextThatIsNotAVisualJsonIsAnInputError) {
  for (const std::string bad : {"{\"pitch\": {\"value\": 4", "hello, world", "[1, 2, 3]",
                                "{\"pitch\":{\"value\":-3}}"}) {
    FakeClock clock;
    FakeHoloPlay device(test::eeprom_image(bad), clock);
    const std::string message = error_of<InputError>(device, clock, fake_options(clock));
    EXPECT_NE(message.find("HoloPlay FAKE0001 (/dev/hidraw-fake)"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Gen1Eeprom, DisconnectMidReadIsADeviceError) {
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(fixture_text()), clock);
  device.disconnect_at_page = 5;
  const std::string message = error_of<DeviceError>(device, clock, fake_options(clock));
  EXPECT_NE(message.find("gone"), std::string::npos) << message;
}

TEST(Gen1Eeprom, RefusedRequestIsADeviceErrorNamingThePage) {
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(fixture_text()), clock);
  device.send_fails = true;
  const std::string message = error_of<DeviceError>(device, clock, fake_options(clock));
  EXPECT_NE(message.find("page 0"), std::string::npos) << message;
}

TEST(Gen1Eeprom, SilentDeviceTimesOutAfterTheRequestsForOnePage) {
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(fixture_text()), clock);
  device.never_reply = true;
  const Gen1ReadOptions options = fake_options(clock);
  const auto start = clock.now;
  const std::string message = error_of<DeviceError>(device, clock, options);
  EXPECT_NE(message.find("no reply"), std::string::npos) << message;
  EXPECT_EQ(device.requests, options.requests_per_page);
  EXPECT_LE(clock.now - start, options.overall_timeout);
}

TEST(Gen1Eeprom, EndlessButtonReportsEndAtTheDeadlines) {
  // The device chatters but never answers: no read ever times out, the page deadlines end it.
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(fixture_text()), clock);
  device.never_reply = true;
  device.endless_buttons = true;
  const std::string message = error_of<DeviceError>(device, clock, fake_options(clock));
  EXPECT_NE(message.find("reports skipped"), std::string::npos) << message;
}

TEST(Gen1Eeprom, OverallDeadlineEndsASlowRead) {
  // Every page needs all its requests: the overall deadline stops the read part way.
  const std::string text = fixture_text();
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text), clock);
  device.endless_buttons = true;
  device.stale_reports_before_reply = 2000;  // replies lie behind more reports than a deadline allows
  Gen1ReadOptions options = fake_options(clock);
  options.overall_timeout = 2000ms;
  const std::string message = error_of<DeviceError>(device, clock, options);
  EXPECT_FALSE(message.empty());
}

TEST(Gen1Eeprom, RequestsAreWellFormedFeatureReports) {
  // The fake refuses anything but [0, 0, page hi, page lo, 64 x 0]; a read succeeding shows the
  // requests were that; a page number above 255 checks the byte order.
  std::string text = fixture_text();
  text.insert(text.size() - 1, std::string(20000 - text.size(), ' '));  // > 256 pages
  FakeClock clock;
  FakeHoloPlay device(test::eeprom_image(text, 32768), clock);
  Gen1ReadOptions options = fake_options(clock);
  options.max_json_bytes = 32768;
  EXPECT_EQ(read_gen1_calibration(device, options), text);
}

TEST(Gen1Eeprom, OptionsCheckThemselves) {
  Gen1ReadOptions o;
  o.requests_per_page = 0;
  EXPECT_THROW(o.check(), InputError);
  o = {};
  o.page_timeout = 1ms;
  EXPECT_THROW(o.check(), InputError);
}

}  // namespace
}  // namespace lfd::device
