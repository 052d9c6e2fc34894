#pragma once
/// The studio's HTTP side (issue 37): a router that applies the request guard and serves the
/// page's assets and the API, as a pure function of the request (tested without a socket),
/// and a server that listens on loopback only (127.0.0.1, and ::1 on the same port when the
/// system has IPv6) and hands each request to the router.
#include <functional>
#include <memory>
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
  std::string path;                         ///< without the query
  std::string query;                        ///< after '?', undecoded
  std::string host;                         ///< the Host header
  std::optional<std::string> origin;        ///< the Origin header, when sent
  std::optional<std::string> token_header;  ///< X-Studio-Token, when sent
  std::string body;
};

/// The API behind /api/: the command wires it to its session. Gets the method, the path
/// after "/api/", the query and the body; its reply is sent as it is.
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

 private:
  std::string token_;
  int port_;
  ApiHandler api_;
};

class StudioServer {
 public:
  /// Binds 127.0.0.1 on `port` (0: a free port the system picks) and ::1 on the same port.
  /// Throws std::runtime_error when the IPv4 loopback cannot be bound.
  StudioServer(const std::string& token, int port, ApiHandler api);
  ~StudioServer();
  StudioServer(const StudioServer&) = delete;
  StudioServer& operator=(const StudioServer&) = delete;

  int port() const;
  bool ipv6() const;  ///< ::1 is served too
  /// The page's address with its token, to print and open.
  std::string url() const;
  /// Serves until stop() (from another thread or a signal handler's watcher).
  void run();
  void stop();

 private:
  struct Sockets;
  std::unique_ptr<Sockets> sockets_;
  std::string token_;
};

}  // namespace rigdesign::studio
