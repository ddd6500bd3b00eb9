// CBOR through libcbor: round trips and the refusals that keep a hostile message small.
#include <gtest/gtest.h>

#include "serve/cbor_json.hpp"
#include "util/error.hpp"

namespace lfd::serve {
namespace {

using json = nlohmann::json;
const CborLimits kLimits{16, 1u << 20};

TEST(CborJson, RoundTripsWhatHoloPlayCoreSends) {
  const json request = {{"cmd", {{"show", {{"source", "bindata"}, {"quilt", {{"type", "image"},
      {"settings", {{"vx", 5}, {"vy", 9}, {"aspect", 0.75}}}}}, {"targetDisplay", -0}}}}},
      {"bin", json::binary({1, 2, 3, 255})}};
  const auto bytes = encode_cbor(request);
  EXPECT_EQ(decode_cbor(bytes, kLimits), request);
}

TEST(CborJson, MatchesAnIndependentEncoder) {
  // nlohmann's own CBOR writer is the independent truth for the bytes libcbor reads.
  const json value = {{"a", -17}, {"b", 1.5}, {"c", json::array({true, false, nullptr, "x"})},
                      {"d", json::binary({9, 8})}, {"e", 4294967296ull}};
  EXPECT_EQ(decode_cbor(json::to_cbor(value), kLimits), value);
  EXPECT_EQ(json::from_cbor(encode_cbor(value)), value);
}

TEST(CborJson, RefusesAnArrayClaimingMoreItemsThanBytes) {
  // 0x9b: an array with a 64-bit count, 2^40 items, in 9 bytes.
  const std::vector<std::uint8_t> lying = {0x9b, 0, 0, 1, 0, 0, 0, 0, 0};
  EXPECT_THROW(decode_cbor(lying, kLimits), InputError);
}

TEST(CborJson, RefusesNestingDeeperThanTheLimit) {
  std::vector<std::uint8_t> deep(1000, 0x81);  // [[[[...
  deep.push_back(0x00);
  EXPECT_THROW(decode_cbor(deep, kLimits), InputError);
  std::vector<std::uint8_t> indefinite(1000, 0x9f);  // indefinite arrays, never closed
  EXPECT_THROW(decode_cbor(indefinite, kLimits), InputError);
}

TEST(CborJson, RefusesTruncatedTrailingAndNonTextKeys) {
  auto bytes = encode_cbor(json{{"cmd", "x"}});
  EXPECT_THROW(decode_cbor(std::span(bytes).first(bytes.size() - 1), kLimits), InputError);
  bytes.push_back(0);
  EXPECT_THROW(decode_cbor(bytes, kLimits), InputError);
  const std::vector<std::uint8_t> int_key = {0xa1, 0x01, 0x02};  // {1: 2}
  EXPECT_THROW(decode_cbor(int_key, kLimits), InputError);
  EXPECT_THROW(decode_cbor({}, kLimits), InputError);
}

TEST(CborJson, CountsItemsAgainstTheLimit) {
  const json many = json::array();
  json big = json::array();
  for (int i = 0; i < 100; ++i) big.push_back(i);
  EXPECT_NO_THROW(decode_cbor(encode_cbor(big), {16, 101}));
  EXPECT_THROW(decode_cbor(encode_cbor(big), {16, 50}), InputError);
}

}  // namespace
}  // namespace lfd::serve
