#pragma once
/// The studio's request router (issue 37): the request guard applied to every request, the
/// page's assets from a table and the API behind /api/, as a pure function of the request, so
/// every rule is tested (and fuzzed) without a socket. The server (studio_server.hpp) only
/// moves bytes between a socket and this.
#include <functional>
#include <optional>
#include <string>

namespace rigdesign::studio {

struct Reply {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
};

struct IncomingRequest {
  std::string method;                       ///< "GET", "POST", ...
  std::string path;                         ///< without the query, undecoded
  std::string query;                        ///< after '?', undecoded
  std::string host;                         ///< the Host header
  std::optional<std::string> origin;        ///< the Origin header, when sent
  std::optional<std::string> token_header;  ///< X-Studio-Token, when sent
  std::string body;
};

/// The API behind /api/: the command wires it to its session. Gets the method, the path
/// after "/api/", the query and the body; its reply is sent as it is. Called from several
/// server threads at once: it serialises what it shares.
using ApiHandler = std::function<Reply(const std::string& method, const std::string& name,
                                       const std::string& query, const std::string& body)>;

/// The header API calls carry the token in (the page reads the token from its own URL).
inline constexpr const char* kTokenHeader = "X-Studio-Token";

class StudioRouter {
 public:
  StudioRouter(std::string token, int port, ApiHandler api);
  /// Host and Origin are checked first (403), then the body size (413), then the token: in the
  /// query for the page itself, in kTokenHeader for /api/ (401). Assets need no token (they
  /// hold no data); any path not in the asset table is 404.
  Reply handle(const IncomingRequest& request) const;
  /// The request carries the session's token (in kTokenHeader or as the query's `token`): its
  /// connection is the user's, not a stranger's (the server's cap on unproven connections).
  bool shows_token(const IncomingRequest& request) const;

 private:
  std::string token_;
  int port_;
  ApiHandler api_;
};

}  // namespace rigdesign::studio
