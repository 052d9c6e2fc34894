#pragma once
// A raw HTTP/1.1 client for the studio's socket tests: every byte sent is the test's own (a
// complete request, half a request line, a header flood), and the reply is read back as the
// kernel hands it over, so nothing of the server's library judges what the test sees.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rigdesign::test {

/// A connected TCP socket to 127.0.0.1:port (or [::1]:port), with send and receive timeouts;
/// -1 when it cannot connect.
inline int connect_loopback(int port, bool ipv6 = false, double timeout_seconds = 5.0) {
  const int fd = ::socket(ipv6 ? AF_INET6 : AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  timeval timeout{};
  timeout.tv_sec = static_cast<time_t>(timeout_seconds);
  timeout.tv_usec =
      static_cast<suseconds_t>((timeout_seconds - static_cast<double>(timeout.tv_sec)) * 1e6);
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
  int connected = -1;
  if (ipv6) {
    sockaddr_in6 address{};
    address.sin6_family = AF_INET6;
    address.sin6_port = htons(static_cast<std::uint16_t>(port));
    address.sin6_addr = in6addr_loopback;
    connected = ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  } else {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected = ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  }
  if (connected != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

/// Sends all of `bytes`; false when the peer closed or the send timed out.
inline bool send_all(int fd, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

/// The server has closed this connection (end of stream or reset), looked at without waiting.
inline bool closed_by_peer(int fd) {
  pollfd watch{fd, POLLIN, 0};
  if (::poll(&watch, 1, 0) <= 0) return false;
  if ((watch.revents & (POLLHUP | POLLERR)) != 0) return true;
  char byte = 0;
  const ssize_t n = ::recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
  return n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK);
}

struct HttpAnswer {
  int status = 0;    ///< 0: no status line came back
  std::string head;  ///< status line and headers
  std::string body;
  double seconds = 0.0;  ///< from the connect to the last byte
};

/// The value of header `name` (case-insensitive) in `head`, when present.
inline std::optional<std::string> header_value(const std::string& head, const std::string& name) {
  std::size_t start = head.find("\r\n");
  while (start != std::string::npos && start + 2 < head.size()) {
    const std::size_t end = head.find("\r\n", start + 2);
    const std::string line = head.substr(start + 2, end - start - 2);
    const std::size_t colon = line.find(':');
    if (colon == name.size() &&
        std::equal(name.begin(), name.end(), line.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) ==
                 std::tolower(static_cast<unsigned char>(b));
        })) {
      const std::size_t value = line.find_first_not_of(' ', colon + 1);
      return value == std::string::npos ? std::string() : line.substr(value);
    }
    start = end;
  }
  return std::nullopt;
}

/// Reads until the server closes the connection (the requests say Connection: close).
inline HttpAnswer read_answer(int fd, std::chrono::steady_clock::time_point since) {
  std::string reply;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    reply.append(buffer, static_cast<std::size_t>(n));
  }
  HttpAnswer answer;
  answer.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
  const std::size_t head_end = reply.find("\r\n\r\n");
  answer.head = reply.substr(0, head_end);
  if (head_end != std::string::npos) answer.body = reply.substr(head_end + 4);
  if (reply.starts_with("HTTP/1.") && reply.size() >= 12)
    answer.status = std::stoi(reply.substr(9, 3));
  return answer;
}

/// `method target` with the Host of the studio on `port`, Connection: close, the given headers
/// and a body with its Content-Length.
inline std::string request_text(
    const std::string& method, const std::string& target, int port,
    const std::vector<std::pair<std::string, std::string>>& headers = {},
    const std::optional<std::string>& body = std::nullopt) {
  std::string text = method + " " + target + " HTTP/1.1\r\n";
  bool has_host = false;
  for (const auto& [name, value] : headers) has_host = has_host || name == "Host";
  if (!has_host) text += "Host: 127.0.0.1:" + std::to_string(port) + "\r\n";
  for (const auto& [name, value] : headers) text += name + ": " + value + "\r\n";
  text += "Connection: close\r\n";
  if (body) text += "Content-Length: " + std::to_string(body->size()) + "\r\n";
  text += "\r\n";
  if (body) text += *body;
  return text;
}

/// One request on a new connection; status 0 when it could not connect or nothing came back.
inline HttpAnswer ask(int port, const std::string& request, bool ipv6 = false) {
  const auto since = std::chrono::steady_clock::now();
  const int fd = connect_loopback(port, ipv6);
  if (fd < 0) return {};
  send_all(fd, request);
  HttpAnswer answer = read_answer(fd, since);
  ::close(fd);
  return answer;
}

}  // namespace rigdesign::test
