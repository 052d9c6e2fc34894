#include "rigdesign/studio/studio_router.hpp"

#include "rigdesign/studio/request_guard.hpp"
#include "rigdesign/studio/studio_assets.hpp"

namespace rigdesign::studio {
namespace {

Reply refusal(int status, const std::string& why) {
  return {status, "text/plain; charset=utf-8", why + "\n"};
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

bool StudioRouter::shows_token(const IncomingRequest& request) const {
  if (request.token_header && token_matches(*request.token_header, token_)) return true;
  const std::optional<std::string> token = query_parameter(request.query, "token");
  return token && token_matches(*token, token_);
}

}  // namespace rigdesign::studio
