#include "connection_gate.hpp"

#include <sys/socket.h>

#include <algorithm>

namespace rigdesign::studio {
namespace {

// The watcher looks a few times per allowance, at least once a second: a connection is shut
// at most a quarter allowance (or a second) after its time is up.
std::chrono::milliseconds watch_period(std::chrono::milliseconds allowance) {
  return std::clamp(allowance / 4, std::chrono::milliseconds(10), std::chrono::milliseconds(1000));
}

}  // namespace

ConnectionGate::ConnectionGate(GateParams params)
    : params_(params), watcher_([this] { watch(); }) {}

ConnectionGate::~ConnectionGate() {
  {
    const std::lock_guard<std::mutex> guard(lock_);
    stopping_ = true;
  }
  wake_.notify_all();
  watcher_.join();
}

Peer* ConnectionGate::opened(int fd) {
  const std::lock_guard<std::mutex> guard(lock_);
  Peer& peer = peers_.emplace_back();
  peer.fd = fd;
  peer.since = std::chrono::steady_clock::now();
  peer.place = unproven_.insert(unproven_.end(), &peer);
  peer.listed = true;
  while (unproven_.size() > params_.max_unproven) shut_locked(*unproven_.front());
  return &peer;
}

void ConnectionGate::proven(Peer& peer) {
  const std::lock_guard<std::mutex> guard(lock_);
  peer.proven = true;
  if (peer.listed) {
    unproven_.erase(peer.place);
    peer.listed = false;
  }
}

void ConnectionGate::closed(Peer* peer) {
  if (peer == nullptr) return;
  const std::lock_guard<std::mutex> guard(lock_);
  if (peer->listed) unproven_.erase(peer->place);
  peers_.remove_if([peer](const Peer& held) { return &held == peer; });
}

std::size_t ConnectionGate::unproven() const {
  const std::lock_guard<std::mutex> guard(lock_);
  return unproven_.size();
}

void ConnectionGate::shut_locked(Peer& peer) {
  // The descriptor is still open: the server calls closed() (which waits for this lock)
  // before it closes it.
  ::shutdown(peer.fd, SHUT_RDWR);
  unproven_.erase(peer.place);
  peer.listed = false;
}

void ConnectionGate::watch() {
  const std::chrono::milliseconds period = watch_period(params_.unproven_allowance);
  std::unique_lock<std::mutex> guard(lock_);
  while (!stopping_) {
    wake_.wait_for(guard, period);
    const auto now = std::chrono::steady_clock::now();
    while (!unproven_.empty() && now - unproven_.front()->since >= params_.unproven_allowance)
      shut_locked(*unproven_.front());
  }
}

}  // namespace rigdesign::studio
