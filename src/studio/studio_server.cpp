#include "rigdesign/studio/studio_server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <stdexcept>
#include <thread>

#include "rigdesign/studio/request_guard.hpp"
#include "rigdesign/studio/studio_assets.hpp"

namespace rigdesign::studio {
namespace {

Reply refusal(int status, const std::string& why) {
  return {status, "text/plain; charset=utf-8", why + "\n"};
}

// Headers every reply carries: nothing from elsewhere may run or be fetched (the page works
// offline by design), the token in the URL does not leave in a Referer, nothing is cached.
void secure(httplib::Response& response) {
  response.set_header("Content-Security-Policy",
                      "default-src 'self'; connect-src 'self' data: blob:; img-src 'self' data: "
                      "blob:; style-src 'self'; frame-ancestors 'none'");
  response.set_header("Referrer-Policy", "no-referrer");
  response.set_header("X-Content-Type-Options", "nosniff");
  response.set_header("Cache-Control", "no-store");
}

}  // namespace

StudioRouter::StudioRouter(std::string token, int port, ApiHandler api)
    : token_(std::move(token)), port_(port), api_(std::move(api)) {}

Reply StudioRouter::handle(const IncomingRequest& request) const {
  if (!host_allowed(request.host, port_))
    return refusal(403, "Host '" + request.host + "' is not the studio's loopback address");
  if (!origin_allowed(request.origin, port_))
    return refusal(403,
                   "requests from origin '" + request.origin.value_or("") + "' are not accepted");
  if (request.body.size() > kMaxRequestBytes)
    return refusal(413, "request body over " + std::to_string(kMaxRequestBytes) + " bytes");
  if (request.path.starts_with("/api/")) {
    if (!request.token_header || !token_matches(*request.token_header, token_))
      return refusal(401, "missing or wrong " + std::string(kTokenHeader));
    return api_(request.method, request.path.substr(5), request.query, request.body);
  }
  if (request.method != "GET") return refusal(405, "only GET outside /api/");
  if (request.path == "/" || request.path == "/index.html") {
    const std::optional<std::string> token = query_parameter(request.query, "token");
    if (!token || !token_matches(*token, token_))
      return refusal(401, "open the address `rigdesign serve` printed (it carries the token)");
  }
  std::optional<Asset> asset = asset_at(request.path);
  if (!asset) return refusal(404, "no such file in the studio");
  return {200, asset->content_type, std::move(asset->body)};
}

struct StudioServer::Sockets {
  httplib::Server v4;
  httplib::Server v6;
  bool has_v6 = false;
  int port = 0;
  std::unique_ptr<StudioRouter> router;
};

namespace {

void route_all(httplib::Server& server, const StudioRouter& router) {
  const auto handler = [&router](const httplib::Request& in, httplib::Response& out) {
    IncomingRequest request;
    request.method = in.method;
    request.path = in.path;
    const std::size_t query = in.target.find('?');
    if (query != std::string::npos) request.query = in.target.substr(query + 1);
    request.host = in.get_header_value("Host");
    if (in.has_header("Origin")) request.origin = in.get_header_value("Origin");
    if (in.has_header(kTokenHeader)) request.token_header = in.get_header_value(kTokenHeader);
    request.body = in.body;
    Reply reply;
    try {
      reply = router.handle(request);
    } catch (const std::exception& error) {
      reply = refusal(500, error.what());
    }
    out.status = reply.status;
    secure(out);
    out.set_content(reply.body, reply.content_type.c_str());
  };
  server.Get(".*", handler);
  server.Post(".*", handler);
  server.Put(".*", handler);
  server.Delete(".*", handler);
  server.set_payload_max_length(kMaxRequestBytes);
}

}  // namespace

StudioServer::StudioServer(const std::string& token, int port, ApiHandler api)
    : sockets_(std::make_unique<Sockets>()), token_(token) {
  Sockets& s = *sockets_;
  // A large reply's last segment would wait for the browser's delayed acknowledgement of the
  // one before (Nagle's algorithm; measured: 200 ms a pose update). Set before binding: the
  // option is taken from the listening socket.
  s.v4.set_tcp_nodelay(true);
  s.v6.set_tcp_nodelay(true);
  s.port = port == 0 ? s.v4.bind_to_any_port("127.0.0.1")
                     : (s.v4.bind_to_port("127.0.0.1", port) ? port : -1);
  if (s.port <= 0)
    throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) +
                             " (in use? try another --port, or 0 for any free one)");
  s.router = std::make_unique<StudioRouter>(token, s.port, std::move(api));
  route_all(s.v4, *s.router);
  s.v6.set_address_family(AF_INET6);
  s.has_v6 = s.v6.bind_to_port("::1", s.port);
  if (s.has_v6) route_all(s.v6, *s.router);
}

StudioServer::~StudioServer() {
  stop();
}

int StudioServer::port() const {
  return sockets_->port;
}

bool StudioServer::ipv6() const {
  return sockets_->has_v6;
}

std::string StudioServer::url() const {
  return "http://127.0.0.1:" + std::to_string(sockets_->port) + "/?token=" + token_;
}

void StudioServer::run() {
  std::thread v6;
  if (sockets_->has_v6) v6 = std::thread([this] { sockets_->v6.listen_after_bind(); });
  sockets_->v4.listen_after_bind();
  if (v6.joinable()) {
    sockets_->v6.stop();
    v6.join();
  }
}

void StudioServer::stop() {
  sockets_->v4.stop();
  sockets_->v6.stop();
}

}  // namespace rigdesign::studio
