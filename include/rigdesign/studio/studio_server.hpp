#pragma once
/// The studio's HTTP server (issues 37 and 53): listens on loopback only (127.0.0.1, and ::1
/// on the same port when the system has IPv6) and hands each request to the router
/// (studio_router.hpp), within bounds that let no local stranger without the token keep the
/// page from its user: request heads are bounded in bytes (431 beyond), idle connections cost
/// no thread, connections that have not shown the token are capped and timed out, and the
/// port is never shared with another server.
#include <cstddef>
#include <memory>
#include <string>

#include "rigdesign/studio/studio_router.hpp"

namespace rigdesign::studio {

/// What a client can make the server hold. The defaults are the studio's (docs/studio.md has
/// the numbers measured with them); tests pass smaller ones to see each bound act quickly.
struct StudioLimits {
  /// Connections that have not yet shown the token, both addresses together; a new one beyond
  /// this closes the oldest, so the user's newest always gets in. 200 idle strangers fit.
  std::size_t max_unproven_connections = 256;
  /// How long a connection may stay open without showing the token [s]: idle, or sending its
  /// request head a byte at a time. The page's own requests take milliseconds.
  double unproven_seconds = 10.0;
  /// Every connection, per address: a bound on descriptors that the cap above stays under.
  unsigned max_connections = 512;
  /// Memory per connection [bytes]: its request line and headers must fit in about half
  /// (431 or 414 beyond); a browser's head is 0.5-2 kB, with localhost cookies a few kB.
  std::size_t connection_memory_bytes = 32 * 1024;
  /// Silence after which any connection is closed [s] (the user's browser reconnects).
  unsigned idle_seconds = 60;
  /// Threads serving requests per address: a long API call holds one of them.
  unsigned threads = 4;
};

struct ServerState;  // studio_server.cpp: the library's daemons, the gate, the router

class StudioServer {
 public:
  /// Binds 127.0.0.1 on `port` (0: a free port the system picks) and ::1 on the same port, and
  /// starts serving. Throws model::InputError when the port is in use or not permitted (the
  /// user picks another --port), std::runtime_error when the server cannot start otherwise.
  StudioServer(const std::string& token, int port, ApiHandler api, StudioLimits limits = {});
  ~StudioServer();
  StudioServer(const StudioServer&) = delete;
  StudioServer& operator=(const StudioServer&) = delete;

  int port() const;
  bool ipv6() const;  ///< ::1 is served too
  /// The page's address with its token, to print and open.
  std::string url() const;
  /// Waits until stop() (from another thread or a signal handler's watcher).
  void run();
  /// Stops serving (open connections are closed) and lets run() return. Idempotent.
  void stop();

 private:
  std::unique_ptr<ServerState> state_;
  std::string token_;
};

}  // namespace rigdesign::studio
