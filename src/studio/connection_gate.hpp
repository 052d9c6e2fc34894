#pragma once
// The studio's bound on strangers (issue 53, item 2): the connections that have not yet shown
// the token, oldest first. When a new one would pass the cap the oldest is closed, so the
// newest (a browser asking now) always gets in; one open longer than its allowance (idle, or
// trickling a request head a byte at a time) is closed by a watcher thread. Closing is
// shutdown(2): the server's event loop sees the end and releases the connection itself, so
// the gate never closes a descriptor it does not own.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <list>
#include <mutex>
#include <string>
#include <thread>

namespace rigdesign::studio {

struct GateParams {
  std::size_t max_unproven = 256;  ///< connections without the token held at once
  std::chrono::milliseconds unproven_allowance{10000};  ///< how long one may stay open
};

/// One TCP connection. The request fields are the server's, touched only by the thread that
/// serves the connection; the rest is the gate's, under its lock.
struct Peer {
  int fd = -1;
  std::chrono::steady_clock::time_point since;
  bool proven = false;               ///< one of its requests carried the token
  std::list<Peer*>::iterator place;  ///< in the gate's unproven list, while there
  bool listed = false;

  std::string target;  ///< the request's raw target (path and query)
  std::string body;    ///< at most kMaxRequestBytes + 1: one byte tells it is over
};

class ConnectionGate {
 public:
  explicit ConnectionGate(GateParams params);
  ~ConnectionGate();
  ConnectionGate(const ConnectionGate&) = delete;
  ConnectionGate& operator=(const ConnectionGate&) = delete;

  /// A connection was accepted on `fd`; the record lives until closed(). Shuts the oldest
  /// unproven one down when this one makes more than the cap.
  Peer* opened(int fd);
  /// One of its requests showed the token: no longer counted, never shut by the gate.
  void proven(Peer& peer);
  /// The server released the connection (before it closes the descriptor).
  void closed(Peer* peer);
  /// Unproven connections held now.
  std::size_t unproven() const;

 private:
  void shut_locked(Peer& peer);
  void watch();

  GateParams params_;
  mutable std::mutex lock_;
  std::list<Peer> peers_;
  std::list<Peer*> unproven_;  // oldest first
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread watcher_;
};

}  // namespace rigdesign::studio
