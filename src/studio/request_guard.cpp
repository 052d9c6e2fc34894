#include "rigdesign/studio/request_guard.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <random>
#include <string>

namespace rigdesign::studio {
namespace {

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// host:port with host one of the loopback names.
bool loopback_authority(std::string_view authority, int port) {
  const std::string suffix = ":" + std::to_string(port);
  if (authority.size() <= suffix.size() || !authority.ends_with(suffix)) return false;
  const std::string_view host = authority.substr(0, authority.size() - suffix.size());
  return host == "127.0.0.1" || host == "[::1]" || equal_ignoring_case(host, "localhost");
}

std::string percent_decoded(std::string_view value) {
  std::string text;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (value[i] == '%' && i + 2 < value.size() &&
        std::isxdigit(static_cast<unsigned char>(value[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(value[i + 2]))) {
      text += static_cast<char>(std::stoi(std::string(value.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      text += value[i] == '+' ? ' ' : value[i];
    }
  }
  return text;
}

}  // namespace

std::string new_token() {
  std::random_device source;
  std::array<unsigned, 8> words{};
  for (unsigned& word : words) word = source();
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  for (unsigned word : words) {
    for (int nibble = 7; nibble >= 0; --nibble) token += kHex[(word >> (4 * nibble)) & 0xfU];
  }
  return token;
}

bool token_matches(std::string_view given, std::string_view expected) {
  // Every byte of the expected token is compared whatever the given one holds.
  unsigned difference = given.size() == expected.size() ? 0U : 1U;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const char g = i < given.size() ? given[i] : '\0';
    difference |= static_cast<unsigned>(static_cast<unsigned char>(g) ^
                                        static_cast<unsigned char>(expected[i]));
  }
  return difference == 0 && !expected.empty();
}

bool host_allowed(std::string_view host, int port) {
  return loopback_authority(host, port);
}

bool origin_allowed(std::optional<std::string_view> origin, int port) {
  if (!origin) return true;
  constexpr std::string_view kScheme = "http://";
  return origin->starts_with(kScheme) && loopback_authority(origin->substr(kScheme.size()), port);
}

std::optional<std::string> query_parameter(std::string_view query, std::string_view key) {
  while (!query.empty()) {
    const std::size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    if (pair.size() > key.size() && pair.starts_with(key) && pair[key.size()] == '=')
      return percent_decoded(pair.substr(key.size() + 1));
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return std::nullopt;
}

}  // namespace rigdesign::studio
