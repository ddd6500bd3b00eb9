// The running service on real loopback sockets, against the test double: NNG's own REQ client
// over WebSocket (the framing holoplay-core speaks), cpp-httplib's client for Bridge's API and
// an NNG WebSocket stream for the events; foreign Origins and rebinding Hosts refused.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nng/nng.h>
#include <nng/protocol/reqrep0/req.h>

#include "serve/cbor_json.hpp"
#include "serve/service.hpp"
#include "tests/serve/fake_display_service.hpp"
#include "tests/serve/serve_test_support.hpp"

namespace lfd::serve {
namespace {

using json = nlohmann::json;

using test::free_port;

struct ServiceSocketsTest : ::testing::Test {
  test::FakeDisplayService fake{{test::fixture_display()}};
  ServeOptions options;
  std::unique_ptr<Service> service;

  void SetUp() override {
    options.listen = {"127.0.0.1", free_port(), free_port(), free_port()};
    service = std::make_unique<Service>(fake, options);
    service->start();
  }

  // One HoloPlay request through NNG's REQ socket; `origin` empty: no Origin header.
  std::optional<json> holoplay(const json& cmd, const std::string& origin = "") {
    nng_socket s;
    EXPECT_EQ(nng_req0_open(&s), 0);
    nng_socket_set_ms(s, NNG_OPT_RECVTIMEO, 1500);
    nng_socket_set_ms(s, NNG_OPT_SENDTIMEO, 1500);
    nng_dialer d;
    const std::string url = "ws://localhost:" + std::to_string(options.listen.holoplay_port) + "/driver";
    EXPECT_EQ(nng_dialer_create(&d, s, url.c_str()), 0);
    if (!origin.empty()) nng_dialer_set_string(d, NNG_OPT_WS_REQUEST_HEADERS, ("Origin: " + origin + "\r\n").c_str());
    std::optional<json> reply;
    if (nng_dialer_start(d, 0) == 0) {
      const auto bytes = encode_cbor({{"cmd", cmd}, {"bin", nullptr}});
      nng_msg* m = nullptr;
      nng_msg_alloc(&m, 0);
      nng_msg_append(m, bytes.data(), bytes.size());
      if (nng_sendmsg(s, m, 0) == 0 && nng_recvmsg(s, &m, 0) == 0) {
        reply = decode_cbor({static_cast<const std::uint8_t*>(nng_msg_body(m)), nng_msg_len(m)}, {});
        nng_msg_free(m);
      }
    }
    nng_close(s);
    return reply;
  }

  httplib::Result put(const std::string& endpoint, const json& body, httplib::Headers headers = {}) {
    httplib::Client c("127.0.0.1", options.listen.bridge_port);
    c.set_read_timeout(5, 0);
    return c.Put(("/" + endpoint).c_str(), headers, body.dump(), "application/json");
  }
};

TEST_F(ServiceSocketsTest, TheAutostartPlaylistPlaysAfterARestart) {
  test::TempDir tmp;
  const auto state_file = tmp.path / "playlists.json";
  ServeOptions kept = options;
  kept.state_file = state_file;
  service->stop();
  service = std::make_unique<Service>(fake, kept);
  service->start();
  const auto token = json::parse(put("enter_orchestration", json::object())->body)["payload"]["value"];
  ASSERT_EQ(put("instance_playlist", {{"orchestration", token}, {"name", "lobby"}, {"loop", true}})->status, 200);
  ASSERT_EQ(put("set_named_autostart_playlist", {{"orchestration", token}, {"playlist_name", "lobby"}, {"head_index", 0}})->status,
            200);
  EXPECT_TRUE(fake.recorded().empty());  // chosen, not played now
  service->stop();
  service.reset();
  service = std::make_unique<Service>(fake, kept);  // lfd serve restarted (systemd), same state file
  service->start();
  ASSERT_FALSE(fake.recorded().empty());
  EXPECT_EQ(fake.recorded().back(), "play_playlist 0 lobby 0");
}

TEST_F(ServiceSocketsTest, BridgeAnswersPostAsPut) {
  httplib::Client c("127.0.0.1", options.listen.bridge_port);
  c.set_read_timeout(5, 0);
  const auto entered = c.Post("/enter_orchestration", "{}", "application/json");
  ASSERT_TRUE(entered);
  EXPECT_EQ(entered->status, 200);
  const auto token = json::parse(entered->body)["payload"]["value"];
  const auto played = c.Post("/transport_control_play", json{{"orchestration", token}}.dump(), "application/json");
  ASSERT_TRUE(played);
  EXPECT_EQ(played->status, 200);
  EXPECT_EQ(fake.recorded().size(), 1u);
  const auto evil = c.Post("/transport_control_play", httplib::Headers{{"Origin", "https://evil.example"}},
                           json{{"orchestration", token}}.dump(), "application/json");
  ASSERT_TRUE(evil);
  EXPECT_EQ(evil->status, 403);
  EXPECT_EQ(fake.recorded().size(), 1u);
  const auto preflight = c.Options("/transport_control_play");
  ASSERT_TRUE(preflight);
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Methods").find("POST"), std::string::npos);
}

TEST_F(ServiceSocketsTest, HoloPlayInfoOverNngWebSocket) {
  const auto reply = holoplay({{"info", json::object()}});
  ASSERT_TRUE(reply);
  EXPECT_EQ((*reply)["error"], 0);
  EXPECT_EQ((*reply)["devices"].size(), 1u);
  EXPECT_TRUE(holoplay({{"info", json::object()}}, "http://localhost:8080"));
}

TEST_F(ServiceSocketsTest, HoloPlayRefusesAForeignOrigin) {
  EXPECT_FALSE(holoplay({{"wipe", json::object()}}, "https://evil.example"));
  EXPECT_TRUE(fake.recorded().empty());
  EXPECT_GE(service->refused(), 1u);
}

TEST_F(ServiceSocketsTest, BridgeRefusesAForeignOriginAndARebindingHost) {
  const auto token = json::parse(put("enter_orchestration", json::object())->body)["payload"]["value"];
  const auto evil = put("transport_control_play", {{"orchestration", token}}, {{"Origin", "https://evil.example"}});
  ASSERT_TRUE(evil);
  EXPECT_EQ(evil->status, 403);
  const auto rebound = put("transport_control_play", {{"orchestration", token}}, {{"Host", "evil.example:33334"}});
  ASSERT_TRUE(rebound);
  EXPECT_EQ(rebound->status, 403);
  EXPECT_TRUE(fake.recorded().empty());
  const auto ok = put("transport_control_play", {{"orchestration", token}}, {{"Origin", "http://localhost:5173"}});
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->status, 200);
  EXPECT_EQ(ok->get_header_value("Access-Control-Allow-Origin"), "http://localhost:5173");
  EXPECT_EQ(fake.recorded().size(), 1u);
}

TEST_F(ServiceSocketsTest, BridgeRefusesAnOversizedBody) {
  httplib::Client c("127.0.0.1", options.listen.bridge_port);
  const auto r = c.Put("/instance_playlist", std::string(options.limits.max_body_bytes + 10, ' '), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
}

TEST_F(ServiceSocketsTest, EventsReachAWebSocketClient) {
  nng_stream_dialer* d = nullptr;
  const std::string url = "ws://localhost:" + std::to_string(options.listen.events_port) + "/event_source";
  ASSERT_EQ(nng_stream_dialer_alloc(&d, url.c_str()), 0);
  nng_stream_dialer_set_bool(d, NNG_OPT_WS_RECV_TEXT, true);
  nng_stream_dialer_set_bool(d, NNG_OPT_WS_SEND_TEXT, true);
  nng_aio* aio = nullptr;
  nng_aio_alloc(&aio, nullptr, nullptr);
  nng_aio_set_timeout(aio, 3000);
  nng_stream_dialer_dial(d, aio);
  nng_aio_wait(aio);
  ASSERT_EQ(nng_aio_result(aio), 0);
  auto* stream = static_cast<nng_stream*>(nng_aio_get_output(aio, 0));
  for (int i = 0; i < 50 && service->events().published() == 0; ++i) {
    const auto token = json::parse(put("enter_orchestration", json::object())->body)["payload"]["value"];
    put("transport_control_next", {{"orchestration", token}});
    usleep(20000);
  }
  std::array<char, 8192> buffer{};
  nng_iov iov{buffer.data(), buffer.size()};
  nng_aio_set_iov(aio, 1, &iov);
  nng_stream_recv(stream, aio);
  nng_aio_wait(aio);
  ASSERT_EQ(nng_aio_result(aio), 0);
  const json event = json::parse(std::string(buffer.data(), nng_aio_count(aio)));
  EXPECT_EQ(event["payload"]["value"]["event"]["value"], "Transport Control Next");
  nng_stream_free(stream);
  nng_aio_free(aio);
  nng_stream_dialer_free(d);
}

}  // namespace
}  // namespace lfd::serve
