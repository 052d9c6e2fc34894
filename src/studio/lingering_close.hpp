#pragma once
// Closing in stages (RFC 9112, section 9.6), for the studio's server. A client may still be
// sending when the server has answered and closes: a head refused with 431, a body refused
// with 413. Closing a socket that holds unread bytes makes the kernel send a reset, and the
// reset drops the answer from the client's queue before the client reads it. So a closing
// connection's socket is kept (a duplicate of its descriptor, taken before the HTTP library
// closes its own), half-closed (the answer is followed by the end of stream) and read and
// discarded until the client ends, stays quiet, or its time is up; then it is closed.
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <thread>

namespace rigdesign::studio {

struct LingerParams {
  std::size_t max_sockets = 64;             ///< lingering at once; beyond, closed at once
  std::chrono::milliseconds quiet{1000};    ///< closed after this long without a byte
  std::chrono::milliseconds longest{5000};  ///< closed after this long in any case
};

class LingeringClose {
 public:
  explicit LingeringClose(LingerParams params);
  ~LingeringClose();  ///< closes every socket still held
  LingeringClose(const LingeringClose&) = delete;
  LingeringClose& operator=(const LingeringClose&) = delete;

  /// Takes a duplicate of `fd` (which its owner closes as it likes) and closes it in stages.
  void close_later(int fd);

 private:
  struct Held {
    std::chrono::steady_clock::time_point since, last_byte;
  };
  void run();
  void drain(int fd, Held& held);

  LingerParams params_;
  int epoll_ = -1;
  int wake_ = -1;  // an eventfd: stop
  std::mutex lock_;
  std::map<int, Held> held_;
  std::thread thread_;
};

}  // namespace rigdesign::studio
