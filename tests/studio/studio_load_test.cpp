// Issue 53 item 2: the studio answers its user while strangers knock. Every stranger here is a
// raw socket of the test's own (idle, sending half a request line a byte at a time, flooding
// header lines); what the server did is read from the sockets (answers, their times, which
// connections it closed) and from this process's own memory in /proc/self/status.
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "rigdesign/model/input_error.hpp"
#include "rigdesign/studio/studio_server.hpp"
#include "studio/connection_gate.hpp"
#include "studio/loopback_http.hpp"

using namespace rigdesign;
using Clock = std::chrono::steady_clock;

namespace {

const std::string kToken = "89abcdef0123456789abcdef01234567";
using Headers = std::vector<std::pair<std::string, std::string>>;

studio::ApiHandler state_api() {
  return [](const std::string& method, const std::string& name, const std::string&,
            const std::string&) {
    return studio::Reply{200, "application/json",
                         "{\"method\": \"" + method + "\", \"name\": \"" + name + "\"}"};
  };
}

// A server on a free port, served from its own thread for the test's length.
struct RunningServer {
  explicit RunningServer(studio::StudioLimits limits = {})
      : server(kToken, 0, state_api(), limits), serving([this] { server.run(); }) {}
  ~RunningServer() {
    server.stop();
    serving.join();
  }
  int port() const { return server.port(); }
  studio::StudioServer server;
  std::thread serving;
};

test::HttpAnswer user_page(int port) {
  return test::ask(port, test::request_text("GET", "/?token=" + kToken, port));
}

test::HttpAnswer user_state(int port) {
  return test::ask(
      port, test::request_text("GET", "/api/state", port, Headers{{studio::kTokenHeader, kToken}}));
}

std::size_t resident_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.starts_with("VmRSS:")) return std::stoul(line.substr(6));
  }
  return 0;
}

std::size_t count_closed(const std::vector<int>& fds) {
  std::size_t closed = 0;
  for (int fd : fds) closed += test::closed_by_peer(fd) ? 1 : 0;
  return closed;
}

void close_all(std::vector<int>& fds) {
  for (int fd : fds) ::close(fd);
  fds.clear();
}

}  // namespace

TEST_CASE(
    "studio load: the user's page and /api/state answer within 1 s while 200 strangers "
    "hold connections",
    "[studio][load]") {
  RunningServer running;  // the studio's own limits
  const int port = running.port();
  constexpr int kIdle = 100;
  constexpr int kSlow = 100;
  std::vector<int> strangers;
  for (int i = 0; i < kIdle + kSlow; ++i) {
    const int fd = test::connect_loopback(port);
    REQUIRE(fd >= 0);
    strangers.push_back(fd);
  }
  // Half a request line from the slow ones, then a byte a second from each, no token ever.
  for (int i = kIdle; i < kIdle + kSlow; ++i) REQUIRE(test::send_all(strangers[i], "GET /?tok"));
  std::atomic<bool> done{false};
  std::thread trickle([&] {
    while (!done) {
      for (int i = kIdle; i < kIdle + kSlow; ++i) test::send_all(strangers[i], "e");
      for (int tick = 0; tick < 10 && !done; ++tick)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // all accepted by now

  double slowest = 0.0;
  for (int round = 0; round < 5; ++round) {
    const test::HttpAnswer page = user_page(port);
    const test::HttpAnswer state = user_state(port);
    CHECK(page.status == 200);
    CHECK(page.body.find("<title>rigdesign studio</title>") != std::string::npos);
    CHECK(state.status == 200);
    CHECK(state.body == "{\"method\": \"GET\", \"name\": \"state\"}");
    slowest = std::max({slowest, page.seconds, state.seconds});
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
  INFO("slowest answer " << slowest << " s");
  CHECK(slowest < 1.0);
  // The strangers were held all along (200 is under the cap, and 2 s under their allowance):
  // the user was answered beside them, not after the server dropped them.
  CHECK(count_closed(strangers) == 0);
  done = true;
  trickle.join();
  close_all(strangers);
}

TEST_CASE("studio load: a stranger trickling a request head is closed after its allowance",
          "[studio][load]") {
  studio::StudioLimits limits;
  limits.unproven_seconds = 1.0;
  RunningServer running(limits);
  const int port = running.port();
  const int slow = test::connect_loopback(port);
  const int idle = test::connect_loopback(port);
  REQUIRE(slow >= 0);
  REQUIRE(idle >= 0);
  const auto since = Clock::now();
  double slow_closed_after = -1.0, idle_closed_after = -1.0;
  // A byte every 100 ms keeps any inactivity timeout from firing; the allowance still does.
  while (Clock::now() - since < std::chrono::seconds(4) &&
         (slow_closed_after < 0 || idle_closed_after < 0)) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - since).count();
    if (slow_closed_after < 0 && !test::send_all(slow, "G")) slow_closed_after = elapsed;
    if (slow_closed_after < 0 && test::closed_by_peer(slow)) slow_closed_after = elapsed;
    if (idle_closed_after < 0 && test::closed_by_peer(idle)) idle_closed_after = elapsed;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  CHECK(slow_closed_after >= 0.9);
  CHECK(slow_closed_after < 2.5);
  CHECK(idle_closed_after >= 0.9);
  CHECK(idle_closed_after < 2.5);
  // The user is answered, and their connection is not the strangers'.
  CHECK(user_state(port).status == 200);
  ::close(slow);
  ::close(idle);
}

TEST_CASE("studio load: a header flood is refused with 431 while memory stays put",
          "[studio][load]") {
  RunningServer running;
  const int port = running.port();
  // A browser's head with a few kB of localhost cookies is still served.
  const test::HttpAnswer cookies =
      test::ask(port, test::request_text("GET", "/?token=" + kToken, port,
                                         Headers{{"Cookie", "session=" + std::string(6000, 'c')}}));
  CHECK(cookies.status == 200);

  std::string block;
  for (int i = 0; block.size() < 64 * 1024; ++i)
    block += "X-H" + std::to_string(i) + ": " + std::string(90, 'h') + "\r\n";
  const std::size_t before_kib = resident_kib();
  const int fd = test::connect_loopback(port);
  REQUIRE(fd >= 0);
  REQUIRE(
      test::send_all(fd, "GET /x HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n"));
  // 32 MiB of header lines, no token. The refusal comes after the first few dozen kB: it is
  // waiting to be read after the first MiB. The server reads and drops the rest (so that the
  // answer is not lost to a reset) and holds none of it.
  constexpr std::size_t kFloodBytes = 32u << 20;
  std::size_t sent = 0;
  std::string early(12, '\0');
  ssize_t early_bytes = -1;
  while (sent < kFloodBytes && test::send_all(fd, block)) {
    sent += block.size();
    if (early_bytes < 0 && sent >= (1u << 20)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      early_bytes = ::recv(fd, early.data(), early.size(), MSG_PEEK | MSG_DONTWAIT);
    }
  }
  const std::size_t peak_kib = resident_kib();
  test::send_all(fd, "\r\n");
  const test::HttpAnswer answer = test::read_answer(fd, Clock::now());
  ::close(fd);
  INFO("sent " << (sent >> 10) << " KiB; RSS " << before_kib << " -> " << peak_kib << " KiB");
  CHECK(early_bytes == 12);
  CHECK(early == "HTTP/1.1 431");
  CHECK(answer.status == 431);
  CHECK(sent >= kFloodBytes);
  CHECK(peak_kib < before_kib + 16 * 1024);
  CHECK(user_page(port).status == 200);
}

TEST_CASE("studio load: a second server on a port in use is refused", "[studio][load]") {
  RunningServer first;
  const int port = first.port();
  try {
    studio::StudioServer second("f" + kToken.substr(1), port, state_api());
    FAIL("a second server started on port " << port);
  } catch (const model::InputError& error) {
    const std::string message = error.what();
    CHECK(message.find("--port") != std::string::npos);
    CHECK(message.find("in use") != std::string::npos);
    CHECK(message.find(std::to_string(port)) != std::string::npos);
  }
  // Every request with the first server's token still reaches the first server.
  for (int i = 0; i < 20; ++i) CHECK(user_state(port).status == 200);

  // A socket that set SO_REUSEPORT (as cpp-httplib's did) holds a port: the studio does not
  // set it, so the kernel refuses it the port instead of dealing the requests out.
  const int holder = ::socket(AF_INET, SOCK_STREAM, 0);
  REQUIRE(holder >= 0);
  const int on = 1;
  ::setsockopt(holder, SOL_SOCKET, SO_REUSEPORT, &on, sizeof on);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(::bind(holder, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
  REQUIRE(::listen(holder, 4) == 0);
  socklen_t length = sizeof address;
  ::getsockname(holder, reinterpret_cast<sockaddr*>(&address), &length);
  CHECK_THROWS_AS(studio::StudioServer(kToken, ntohs(address.sin_port), state_api()),
                  model::InputError);
  ::close(holder);
}

TEST_CASE("connection gate: the oldest unproven connection makes room, the proven stay",
          "[studio][load]") {
  // Socket pairs stand in for connections: the gate shuts the server's end, the test reads
  // the end of stream on the other.
  struct Pair {
    int server = -1, client = -1;
  };
  std::vector<Pair> pairs(5);
  for (Pair& pair : pairs) {
    int fds[2];
    REQUIRE(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) == 0);
    pair = {fds[0], fds[1]};
  }
  const auto shut = [&](std::size_t i) { return test::closed_by_peer(pairs[i].client); };
  std::vector<studio::Peer*> peers;
  {
    studio::ConnectionGate gate({2, std::chrono::milliseconds(60000)});
    peers.push_back(gate.opened(pairs[0].server));
    gate.proven(*peers[0]);
    peers.push_back(gate.opened(pairs[1].server));
    peers.push_back(gate.opened(pairs[2].server));
    CHECK(gate.unproven() == 2);
    CHECK_FALSE(shut(0));
    CHECK_FALSE(shut(1));
    CHECK_FALSE(shut(2));
    peers.push_back(gate.opened(pairs[3].server));  // a third unproven one: the oldest goes
    CHECK(shut(1));
    CHECK_FALSE(shut(0));  // proven: never counted, never shut
    CHECK_FALSE(shut(2));
    CHECK_FALSE(shut(3));
    CHECK(gate.unproven() == 2);
    gate.closed(peers[2]);  // released by the server: room for one more
    peers.push_back(gate.opened(pairs[4].server));
    CHECK_FALSE(shut(3));
    CHECK_FALSE(shut(4));
    for (studio::Peer* peer : {peers[0], peers[1], peers[3], peers[4]}) gate.closed(peer);
    CHECK(gate.unproven() == 0);
  }
  {
    // The allowance: an unproven connection is shut once it is over, a proven one is not.
    studio::ConnectionGate gate({8, std::chrono::milliseconds(300)});
    int fresh[2], user[2];
    REQUIRE(::socketpair(AF_UNIX, SOCK_STREAM, 0, fresh) == 0);
    REQUIRE(::socketpair(AF_UNIX, SOCK_STREAM, 0, user) == 0);
    studio::Peer* stranger = gate.opened(fresh[0]);
    studio::Peer* owner = gate.opened(user[0]);
    gate.proven(*owner);
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    CHECK_FALSE(test::closed_by_peer(fresh[1]));
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    CHECK(test::closed_by_peer(fresh[1]));
    CHECK_FALSE(test::closed_by_peer(user[1]));
    gate.closed(stranger);
    gate.closed(owner);
    for (int fd : {fresh[0], fresh[1], user[0], user[1]}) ::close(fd);
  }
  for (const Pair& pair : pairs) {
    ::close(pair.server);
    ::close(pair.client);
  }
}
