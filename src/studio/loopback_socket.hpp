#pragma once
// The studio's listening sockets, made here rather than by the HTTP library so that what they
// allow is ours to say (issue 53, item 2): SO_REUSEADDR (a studio restarted at once binds
// while the last one's connections wait out TIME_WAIT) and never SO_REUSEPORT, under which a
// second `serve` on the same port would start and take every other request of the first.

namespace rigdesign::studio {

/// A non-blocking socket listening on the loopback address of `family` (AF_INET: 127.0.0.1,
/// AF_INET6: ::1 alone) at `port` (0: one the system picks). -1 with errno set when it cannot.
int listen_on_loopback(int family, int port);

/// The port a bound socket has (the one the system picked for port 0); -1 on failure.
int bound_port(int fd);

}  // namespace rigdesign::studio
