#include "lingering_close.hpp"

#include <fcntl.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <stdexcept>
#include <vector>

namespace rigdesign::studio {
namespace {

using Clock = std::chrono::steady_clock;
// How often deadlines are looked at when no byte arrives [ms].
constexpr int kTickMs = 100;

}  // namespace

LingeringClose::LingeringClose(LingerParams params)
    : params_(params),
      epoll_(::epoll_create1(EPOLL_CLOEXEC)),
      wake_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  if (epoll_ < 0 || wake_ < 0) {
    if (epoll_ >= 0) ::close(epoll_);
    if (wake_ >= 0) ::close(wake_);
    throw std::runtime_error("cannot create the studio's closing loop (epoll, eventfd)");
  }
  epoll_event event{};
  event.events = EPOLLIN;
  event.data.fd = wake_;
  ::epoll_ctl(epoll_, EPOLL_CTL_ADD, wake_, &event);
  thread_ = std::thread([this] { run(); });
}

LingeringClose::~LingeringClose() {
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t written = ::write(wake_, &one, sizeof one);
  thread_.join();
  for (const auto& [fd, held] : held_) ::close(fd);
  ::close(wake_);
  ::close(epoll_);
}

void LingeringClose::close_later(int fd) {
  const std::lock_guard<std::mutex> guard(lock_);
  if (held_.size() >= params_.max_sockets) return;  // the owner's close is the only one
  const int copy = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
  if (copy < 0) return;
  // The answer is out (or abandoned): end the stream after it, keep reading what comes.
  ::shutdown(copy, SHUT_WR);
  const int flags = ::fcntl(copy, F_GETFL);
  if (flags >= 0) ::fcntl(copy, F_SETFL, flags | O_NONBLOCK);
  epoll_event event{};
  event.events = EPOLLIN | EPOLLRDHUP;
  event.data.fd = copy;
  if (::epoll_ctl(epoll_, EPOLL_CTL_ADD, copy, &event) != 0) {
    ::close(copy);
    return;
  }
  const Clock::time_point now = Clock::now();
  held_[copy] = {now, now};
}

void LingeringClose::drain(int fd, Held& held) {
  std::array<char, 64 * 1024> sink;
  for (;;) {
    const ssize_t n = ::recv(fd, sink.data(), sink.size(), 0);
    if (n > 0) {
      held.last_byte = Clock::now();
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
    if (n < 0 && errno == EINTR) continue;
    held.since = Clock::time_point::min();  // the end of stream, or an error: done
    return;
  }
}

void LingeringClose::run() {
  std::array<epoll_event, 32> events;
  for (;;) {
    const int ready = ::epoll_wait(epoll_, events.data(), static_cast<int>(events.size()), kTickMs);
    const std::lock_guard<std::mutex> guard(lock_);
    for (int i = 0; i < ready; ++i) {
      const int fd = events[static_cast<std::size_t>(i)].data.fd;
      if (fd == wake_) return;
      const auto found = held_.find(fd);
      if (found != held_.end()) drain(fd, found->second);
    }
    const Clock::time_point now = Clock::now();
    for (auto it = held_.begin(); it != held_.end();) {
      const Held& held = it->second;
      if (held.since == Clock::time_point::min() || now - held.last_byte >= params_.quiet ||
          now - held.since >= params_.longest) {
        ::close(it->first);  // also leaves the epoll set
        it = held_.erase(it);
      } else {
        ++it;
      }
    }
  }
}

}  // namespace rigdesign::studio
