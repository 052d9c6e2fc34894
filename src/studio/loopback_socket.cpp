#include "loopback_socket.hpp"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace rigdesign::studio {
namespace {

int fail_closing(int fd) {
  const int error = errno;
  ::close(fd);
  errno = error;
  return -1;
}

}  // namespace

int listen_on_loopback(int family, int port) {
  const int fd = ::socket(family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  const int on = 1;
  if (::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0) return fail_closing(fd);
  sockaddr_storage address{};
  socklen_t length = 0;
  const auto port_bytes = htons(static_cast<std::uint16_t>(port));
  if (family == AF_INET6) {
    // ::1 only, not the IPv4 addresses mapped into IPv6 as well.
    if (::setsockopt(fd, IPPROTO_IPV6, IPV6_V6ONLY, &on, sizeof on) != 0) return fail_closing(fd);
    auto& six = reinterpret_cast<sockaddr_in6&>(address);
    six.sin6_family = AF_INET6;
    six.sin6_port = port_bytes;
    six.sin6_addr = in6addr_loopback;
    length = sizeof six;
  } else {
    auto& four = reinterpret_cast<sockaddr_in&>(address);
    four.sin_family = AF_INET;
    four.sin_port = port_bytes;
    four.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    length = sizeof four;
  }
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), length) != 0) return fail_closing(fd);
  if (::listen(fd, SOMAXCONN) != 0) return fail_closing(fd);
  return fd;
}

int bound_port(int fd) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) return -1;
  if (address.ss_family == AF_INET6)
    return ntohs(reinterpret_cast<sockaddr_in6&>(address).sin6_port);
  return ntohs(reinterpret_cast<sockaddr_in&>(address).sin_port);
}

}  // namespace rigdesign::studio
