// The Origin allow-list and the Host check.
#include <gtest/gtest.h>

#include "serve/origin_policy.hpp"

namespace lfd::serve {
namespace {

TEST(OriginPolicy, AllowsLoopbackPagesFilesAndNonBrowsers) {
  const OriginPolicy p;
  for (const char* o : {"", "http://localhost", "http://localhost:5173", "https://127.0.0.1:8443",
                        "http://[::1]:3000", "file://", "HTTP://LOCALHOST:80"})
    EXPECT_TRUE(p.allows(o)) << o;
}

TEST(OriginPolicy, RefusesOtherSitesAndLookalikes) {
  const OriginPolicy p;
  for (const char* o : {"https://evil.example", "http://localhost.evil.example", "http://127.0.0.1.nip.io",
                        "http://localhost:80abc", "null", "ws://localhost", "http://localhost@evil.example"})
    EXPECT_FALSE(p.allows(o)) << o;
}

TEST(OriginPolicy, AddsExactOrigins) {
  const OriginPolicy p({"https://app.example/"});
  EXPECT_TRUE(p.allows("https://app.example"));
  EXPECT_FALSE(p.allows("https://app.example.evil"));
}

TEST(OriginPolicy, HostMustBeLoopback) {
  EXPECT_TRUE(OriginPolicy::is_loopback_host("localhost:33334"));
  EXPECT_TRUE(OriginPolicy::is_loopback_host("127.0.0.1:33334"));
  EXPECT_FALSE(OriginPolicy::is_loopback_host("rebind.evil.example:33334"));
  EXPECT_FALSE(OriginPolicy::is_loopback_host(""));
}

}  // namespace
}  // namespace lfd::serve
