// Fuzz target: the studio's request router (issue 53, item 7): any method, path, query, Host,
// Origin, token header and body, on a router with a fixed token. Beyond crashes, leaks and
// undefined behaviour, a finding is the API reached by a request the guard refuses or without
// the token, the API not reached by one that passes, the page served without the token, or a
// status the router does not give.
#include "rigdesign/studio/studio_router.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdlib>
#include <string>

#include "rigdesign/studio/request_guard.hpp"

namespace {

// In http.dict too, so mutations can carry it.
const std::string kToken = "5f0c1e2d3b4a69788796a5b4c3d2e1f00f1e2d3c4b5a69788796a5b4c3d2e1f0";
constexpr int kPort = 8765;

bool status_known(int status) {
  for (int known : {200, 401, 403, 404, 405, 413}) {
    if (status == known) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rigdesign::studio;
  FuzzedDataProvider input(data, size);
  IncomingRequest request;
  request.method = input.ConsumeRandomLengthString(16);
  request.path = input.ConsumeRandomLengthString(256);
  request.query = input.ConsumeRandomLengthString(512);
  request.host = input.ConsumeRandomLengthString(64);
  if (input.ConsumeBool()) request.origin = input.ConsumeRandomLengthString(64);
  if (input.ConsumeBool()) request.token_header = input.ConsumeRandomLengthString(128);
  const bool oversized = input.ConsumeBool();
  request.body = input.ConsumeRemainingBytesAsString();
  // Over the limit by a few bytes: the 413 branch without megabyte inputs.
  if (oversized) request.body.resize(kMaxRequestBytes + 1 + request.body.size() % 7, 'x');

  bool called = false;
  const StudioRouter router(
      kToken, kPort,
      [&called](const std::string&, const std::string&, const std::string&, const std::string&) {
        called = true;
        return Reply{200, "application/json", "{}"};
      });
  const Reply reply = router.handle(request);

  const bool guard_passes = host_allowed(request.host, kPort) &&
                            origin_allowed(request.origin, kPort) &&
                            request.body.size() <= kMaxRequestBytes;
  const bool api_call = request.path.size() >= 5 && request.path.compare(0, 5, "/api/") == 0;
  const bool header_token = request.token_header && *request.token_header == kToken;
  if (called != (guard_passes && api_call && header_token)) std::abort();
  const bool page = request.path == "/" || request.path == "/index.html";
  // The token is 64 characters; the query must hold at least that many to carry it.
  if (page && reply.status == 200 &&
      (!router.shows_token(request) || request.query.size() < kToken.size()))
    std::abort();
  if (!status_known(reply.status)) std::abort();
  return 0;
}
