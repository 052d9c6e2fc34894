#pragma once
/// What the studio's server lets through (issue 37, item 6), as pure functions so each rule
/// is tested without a socket. The server listens on loopback only; a request must name the
/// loopback host it was sent to (a DNS-rebinding page names its own domain), come from no
/// origin or the studio's own, carry the session's token, and stay under the size limit.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rigdesign::studio {

/// The largest request body accepted [bytes]: an edit is a few hundred.
inline constexpr std::size_t kMaxRequestBytes = 64 * 1024;

/// 32 bytes from the operating system's random source (std::random_device) as 64 hex digits.
/// The one random choice that takes no --seed: a token that can be reproduced guards nothing.
std::string new_token();

/// `given` equals `expected`, compared in time that does not depend on where they differ.
bool token_matches(std::string_view given, std::string_view expected);

/// The Host header names the loopback address and port the server listens on:
/// 127.0.0.1:PORT, [::1]:PORT or localhost:PORT (case-insensitive name).
bool host_allowed(std::string_view host, int port);

/// No Origin header (a page load, a command-line client), or the studio's own origin:
/// http://127.0.0.1:PORT, http://[::1]:PORT or http://localhost:PORT.
bool origin_allowed(std::optional<std::string_view> origin, int port);

/// The value of `key` in a URL query (`key=value` among `&`-separated pairs), with its %XX
/// escapes and '+' decoded (the page encodes with encodeURIComponent); nothing when absent.
std::optional<std::string> query_parameter(std::string_view query, std::string_view key);

}  // namespace rigdesign::studio
