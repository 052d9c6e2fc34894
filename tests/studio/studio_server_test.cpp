// Issue 37 item 6: what the studio's server lets through. The rules are tested on the router
// (no socket), then on a real server over loopback with a raw client (loopback_http.hpp), and
// where it listens is read from the kernel's own socket table (/proc/net/tcp and tcp6).
#include "rigdesign/studio/studio_server.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "rigdesign/studio/request_guard.hpp"
#include "studio/loopback_http.hpp"

using namespace rigdesign;

namespace {

const std::string kToken = "0123456789abcdef0123456789abcdef";

struct CountingApi {
  int calls = 0;
  studio::ApiHandler handler() {
    return [this](const std::string&, const std::string& name, const std::string&,
                  const std::string&) {
      ++calls;
      return studio::Reply{200, "application/json", "{\"called\": \"" + name + "\"}"};
    };
  }
};

studio::IncomingRequest get(const std::string& path, const std::string& query = "") {
  studio::IncomingRequest request;
  request.method = "GET";
  request.path = path;
  request.query = query;
  request.host = "127.0.0.1:8765";
  return request;
}

// Local addresses (hex, as the kernel writes them) of the sockets listening on `port`.
std::set<std::string> listening_addresses(int port) {
  std::set<std::string> addresses;
  for (const char* table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
    std::ifstream in(table);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::istringstream fields(line);
      std::string slot, local, remote, state;
      fields >> slot >> local >> remote >> state;
      const std::size_t colon = local.find(':');
      if (state != "0A" || colon == std::string::npos) continue;  // 0A: LISTEN
      if (std::stoi(local.substr(colon + 1), nullptr, 16) == port)
        addresses.insert(local.substr(0, colon));
    }
  }
  return addresses;
}

}  // namespace

TEST_CASE("request guard: host, origin and token rules", "[studio]") {
  CHECK(studio::host_allowed("127.0.0.1:8765", 8765));
  CHECK(studio::host_allowed("[::1]:8765", 8765));
  CHECK(studio::host_allowed("LocalHost:8765", 8765));
  CHECK_FALSE(studio::host_allowed("127.0.0.1:8766", 8765));
  CHECK_FALSE(studio::host_allowed("evil.example:8765", 8765));  // DNS rebinding
  CHECK_FALSE(studio::host_allowed("127.0.0.1.evil.example:8765", 8765));
  CHECK_FALSE(studio::host_allowed("", 8765));
  CHECK(studio::origin_allowed(std::nullopt, 8765));
  CHECK(studio::origin_allowed("http://127.0.0.1:8765", 8765));
  CHECK_FALSE(studio::origin_allowed("http://evil.example:8765", 8765));
  CHECK_FALSE(studio::origin_allowed("https://127.0.0.1:8765", 8765));
  CHECK_FALSE(studio::origin_allowed("null", 8765));
  CHECK(studio::token_matches(kToken, kToken));
  CHECK_FALSE(studio::token_matches(kToken.substr(0, 31), kToken));
  CHECK_FALSE(studio::token_matches(kToken + "0", kToken));
  CHECK_FALSE(studio::token_matches("", ""));
  CHECK(studio::query_parameter("a=1&token=abc&b=2", "token") == std::optional<std::string>("abc"));
  CHECK_FALSE(studio::query_parameter("xtoken=abc", "token"));
  const std::string a = studio::new_token(), b = studio::new_token();
  CHECK(a.size() == 64);
  CHECK(a != b);
}

TEST_CASE("studio router: refusals before the API is reached", "[studio]") {
  CountingApi api;
  const studio::StudioRouter router(kToken, 8765, api.handler());
  // The page needs the token in its address.
  CHECK(router.handle(get("/")).status == 401);
  CHECK(router.handle(get("/", "token=wrong")).status == 401);
  const studio::Reply page = router.handle(get("/", "token=" + kToken));
  CHECK(page.status == 200);
  CHECK(page.body.find("<title>rigdesign studio</title>") != std::string::npos);
  // Its assets, and nothing else: a path is looked up, never opened.
  CHECK(router.handle(get("/studio.js")).status == 200);
  CHECK(router.handle(get("/three/three.min.js")).body.find("REVISION") != std::string::npos);
  for (const char* path : {"/three/../../../etc/passwd", "/../etc/passwd", "/%2e%2e/etc/passwd",
                           "/usr/share/javascript/three/three.min.js", "/studio.js/",
                           "/three/examples/js/controls/OrbitControls.js"}) {
    INFO(path);
    CHECK(router.handle(get(path)).status == 404);
  }
  // The API needs the token in its header.
  studio::IncomingRequest call = get("/api/state");
  CHECK(router.handle(call).status == 401);
  call.token_header = "wrong";
  CHECK(router.handle(call).status == 401);
  CHECK(api.calls == 0);
  call.token_header = kToken;
  CHECK(router.handle(call).status == 200);
  CHECK(api.calls == 1);
  // DNS rebinding (another Host), another origin, an oversized body: refused even with the
  // token.
  studio::IncomingRequest rebound = call;
  rebound.host = "evil.example:8765";
  CHECK(router.handle(rebound).status == 403);
  studio::IncomingRequest cross = call;
  cross.origin = "http://evil.example";
  CHECK(router.handle(cross).status == 403);
  studio::IncomingRequest big = call;
  big.method = "POST";
  big.body.assign(studio::kMaxRequestBytes + 1, 'x');
  CHECK(router.handle(big).status == 413);
  CHECK(api.calls == 1);
}

TEST_CASE("studio server: loopback only, and the rules hold over a real socket", "[studio]") {
  CountingApi api;
  studio::StudioServer server(kToken, 0, api.handler());
  const int port = server.port();
  std::thread serving([&server] { server.run(); });
  using test::ask;
  using test::request_text;
  const test::HttpAnswer page = ask(port, request_text("GET", "/?token=" + kToken, port));
  REQUIRE(page.status == 200);
  CHECK(test::header_value(page.head, "Content-Security-Policy")
            .value_or("")
            .find("default-src 'self'") == 0);
  CHECK(test::header_value(page.head, "Referrer-Policy") ==
        std::optional<std::string>("no-referrer"));
  CHECK(page.body.find("<title>rigdesign studio</title>") != std::string::npos);
  CHECK(ask(port, request_text("GET", "/api/state", port)).status == 401);
  const std::vector<std::pair<std::string, std::string>> token = {{studio::kTokenHeader, kToken}};
  CHECK(ask(port, request_text("GET", "/api/state", port, token)).status == 200);
  const std::vector<std::pair<std::string, std::string>> rebound = {{studio::kTokenHeader, kToken},
                                                                    {"Host", "evil.example"}};
  CHECK(ask(port, request_text("GET", "/api/state", port, rebound)).status == 403);
  // A body over the limit: 413 (or the connection closed), the API not called.
  const std::string big(studio::kMaxRequestBytes + 10, 'x');
  const test::HttpAnswer posted = ask(port, request_text("POST", "/api/pose", port, token, big));
  CHECK((posted.status == 0 || posted.status == 413));
  CHECK(api.calls == 1);

  // Listening on 127.0.0.1 (and ::1) only, never on every interface.
  const std::set<std::string> addresses = listening_addresses(port);
  CHECK(addresses.count("0100007F") == 1);                          // 127.0.0.1, little-endian hex
  CHECK(addresses.count("00000000") == 0);                          // 0.0.0.0
  CHECK(addresses.count("00000000000000000000000000000000") == 0);  // ::
  if (server.ipv6()) {
    CHECK(addresses.count("00000000000000000000000001000000") == 1);  // ::1
    const test::HttpAnswer six = ask(
        port,
        request_text("GET", "/api/state", port,
                     {{studio::kTokenHeader, kToken}, {"Host", "[::1]:" + std::to_string(port)}}),
        true);
    CHECK(six.status == 200);
  }
  server.stop();
  serving.join();
}
