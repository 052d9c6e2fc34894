// The studio's server on GNU libmicrohttpd (issue 53, item 2; docs/studio.md says why this
// library): an event loop per address (epoll) with a few threads, so an idle or slow
// connection costs a record and a buffer, never a thread; the request head bounded by the
// connection's memory (431 beyond); the listening sockets made here (loopback_socket.hpp);
// the connections without the token capped and timed out by the gate (connection_gate.hpp).
#include "rigdesign/studio/studio_server.hpp"

#include <microhttpd.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>

#include "connection_gate.hpp"
#include "lingering_close.hpp"
#include "loopback_socket.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/studio/request_guard.hpp"

namespace rigdesign::studio {

struct ServerState {
  explicit ServerState(const StudioLimits& limits)
      : gate(GateParams{
            limits.max_unproven_connections,
            std::chrono::milliseconds(static_cast<long long>(limits.unproven_seconds * 1000.0))}) {}
  std::unique_ptr<StudioRouter> router;
  ConnectionGate gate;
  LingeringClose closing{LingerParams{}};
  MHD_Daemon* v4 = nullptr;
  MHD_Daemon* v6 = nullptr;
  int port = 0;
  bool has_v6 = false;

  std::mutex lock;
  std::condition_variable stopped_signal;
  bool stopped = false;
};

namespace {

// Headers every reply carries: nothing from elsewhere may run or be fetched (the page works
// offline by design), the token in the URL does not leave in a Referer, nothing is cached.
constexpr std::array<std::pair<const char*, const char*>, 4> kSecurityHeaders = {{
    {"Content-Security-Policy",
     "default-src 'self'; connect-src 'self' data: blob:; img-src 'self' data: blob:; "
     "style-src 'self'; frame-ancestors 'none'"},
    {"Referrer-Policy", "no-referrer"},
    {"X-Content-Type-Options", "nosniff"},
    {"Cache-Control", "no-store"},
}};

using State = ServerState;

Peer* peer_of(MHD_Connection* connection) {
  const MHD_ConnectionInfo* info =
      MHD_get_connection_info(connection, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
  return info == nullptr ? nullptr : static_cast<Peer*>(info->socket_context);
}

std::optional<std::string> header(MHD_Connection* connection, const char* name) {
  const char* value = MHD_lookup_connection_value(connection, MHD_HEADER_KIND, name);
  if (value == nullptr) return std::nullopt;
  return std::string(value);
}

MHD_Result send_reply(MHD_Connection* connection, const Reply& reply) {
  MHD_Response* response = MHD_create_response_from_buffer(
      reply.body.size(), const_cast<char*>(reply.body.data()), MHD_RESPMEM_MUST_COPY);
  if (response == nullptr) return MHD_NO;
  MHD_add_response_header(response, MHD_HTTP_HEADER_CONTENT_TYPE, reply.content_type.c_str());
  for (const auto& [name, value] : kSecurityHeaders) MHD_add_response_header(response, name, value);
  const MHD_Result queued =
      MHD_queue_response(connection, static_cast<unsigned>(reply.status), response);
  MHD_destroy_response(response);
  return queued;
}

// A connection opened or closed: the gate keeps its record. Replies go out at once, not held
// for the browser's delayed acknowledgement of the segment before (Nagle's algorithm;
// measured with cpp-httplib: 200 ms a pose update).
void on_connection(void* cls, MHD_Connection* connection, void** socket_context,
                   MHD_ConnectionNotificationCode event) {
  State& state = *static_cast<State*>(cls);
  if (event == MHD_CONNECTION_NOTIFY_STARTED) {
    const MHD_ConnectionInfo* info =
        MHD_get_connection_info(connection, MHD_CONNECTION_INFO_CONNECTION_FD);
    if (info == nullptr) return;
    const int on = 1;
    ::setsockopt(info->connect_fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    *socket_context = state.gate.opened(info->connect_fd);
  } else {
    auto* peer = static_cast<Peer*>(*socket_context);
    if (peer != nullptr) state.closing.close_later(peer->fd);
    state.gate.closed(peer);
    *socket_context = nullptr;
  }
}

// The raw target, before the library decodes the path and splits the query: the router reads
// both as sent. Kept in the connection's record (a request left unanswered, a 431, frees
// nothing, so nothing is allocated per request).
void* on_target(void*, const char* target, MHD_Connection* connection) {
  if (Peer* peer = peer_of(connection)) peer->target = target;
  return nullptr;
}

Reply route(const State& state, const IncomingRequest& request) {
  try {
    return state.router->handle(request);
  } catch (const std::exception& error) {
    return {500, "text/plain; charset=utf-8", std::string(error.what()) + "\n"};
  }
}

// Called with the head, then with each piece of the body, then once more at its end.
MHD_Result on_request(void* cls, MHD_Connection* connection, const char*, const char* method,
                      const char*, const char* upload_data, std::size_t* upload_size,
                      void** request_context) {
  State& state = *static_cast<State*>(cls);
  Peer* peer = peer_of(connection);
  if (peer == nullptr) return MHD_NO;
  if (*request_context == nullptr) {  // the head
    *request_context = peer;
    peer->body.clear();
    return MHD_YES;
  }
  if (*upload_size > 0) {
    // Kept up to one byte over the limit: the router refuses it (413), nothing more is held.
    const std::size_t room =
        kMaxRequestBytes + 1 - std::min(peer->body.size(), kMaxRequestBytes + 1);
    peer->body.append(upload_data, std::min(room, *upload_size));
    *upload_size = 0;
    return MHD_YES;
  }
  IncomingRequest request;
  request.method = method;
  const std::size_t query = peer->target.find('?');
  request.path = peer->target.substr(0, query);
  if (query != std::string::npos) request.query = peer->target.substr(query + 1);
  request.host = header(connection, MHD_HTTP_HEADER_HOST).value_or("");
  request.origin = header(connection, "Origin");
  request.token_header = header(connection, kTokenHeader);
  request.body = std::move(peer->body);
  peer->body.clear();
  if (state.router->shows_token(request)) state.gate.proven(*peer);
  return send_reply(connection, route(state, request));
}

MHD_Daemon* start_daemon(State& state, int socket, bool ipv6, const StudioLimits& limits) {
  const unsigned flags = MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_EPOLL |
                         (ipv6 ? static_cast<unsigned>(MHD_USE_IPv6) : 0U);
  // The library closes `socket` when it stops (and when it fails to start).
  return MHD_start_daemon(
      flags, 0, nullptr, nullptr, &on_request, &state, MHD_OPTION_LISTEN_SOCKET, socket,
      MHD_OPTION_THREAD_POOL_SIZE, limits.threads, MHD_OPTION_CONNECTION_LIMIT,
      limits.max_connections, MHD_OPTION_CONNECTION_MEMORY_LIMIT, limits.connection_memory_bytes,
      MHD_OPTION_CONNECTION_TIMEOUT, limits.idle_seconds, MHD_OPTION_NOTIFY_CONNECTION,
      &on_connection, &state, MHD_OPTION_URI_LOG_CALLBACK, &on_target, &state, MHD_OPTION_END);
}

[[noreturn]] void refuse_port(int port, int error) {
  const std::string where = "127.0.0.1:" + std::to_string(port);
  if (error == EADDRINUSE || error == EACCES) {
    throw model::InputError(model::Diagnostic{
        {"(command line)", 0, 0},
        "--port",
        "cannot listen on " + where + ": " + std::strerror(error) +
            (error == EADDRINUSE ? " (in use? try another --port, or 0 for any free one)"
                                 : " (ports under 1024 need privileges)"),
        "a port no other program listens on, or 0 for any free one"});
  }
  throw std::runtime_error("cannot listen on " + where + ": " + std::strerror(error));
}

}  // namespace

StudioServer::StudioServer(const std::string& token, int port, ApiHandler api, StudioLimits limits)
    : state_(std::make_unique<ServerState>(limits)), token_(token) {
  State& s = *state_;
  const int v4 = listen_on_loopback(AF_INET, port);
  if (v4 < 0) refuse_port(port, errno);
  s.port = bound_port(v4);
  s.router = std::make_unique<StudioRouter>(token, s.port, std::move(api));
  // ::1 when the system has it and the port is free there too; 127.0.0.1 alone otherwise.
  const int v6 = listen_on_loopback(AF_INET6, s.port);
  s.v4 = start_daemon(s, v4, false, limits);
  if (s.v4 == nullptr) {
    if (v6 >= 0) ::close(v6);
    throw std::runtime_error("cannot start the studio's HTTP server on 127.0.0.1:" +
                             std::to_string(s.port));
  }
  if (v6 >= 0) s.v6 = start_daemon(s, v6, true, limits);
  s.has_v6 = s.v6 != nullptr;
}

StudioServer::~StudioServer() {
  stop();
}

int StudioServer::port() const {
  return state_->port;
}

bool StudioServer::ipv6() const {
  return state_->has_v6;
}

std::string StudioServer::url() const {
  return "http://127.0.0.1:" + std::to_string(state_->port) + "/?token=" + token_;
}

void StudioServer::run() {
  std::unique_lock<std::mutex> guard(state_->lock);
  state_->stopped_signal.wait(guard, [this] { return state_->stopped; });
}

void StudioServer::stop() {
  MHD_Daemon* v4 = nullptr;
  MHD_Daemon* v6 = nullptr;
  {
    const std::lock_guard<std::mutex> guard(state_->lock);
    if (state_->stopped) return;
    state_->stopped = true;
    std::swap(v4, state_->v4);
    std::swap(v6, state_->v6);
  }
  // Outside the lock: stopping waits for a request being answered.
  if (v6 != nullptr) MHD_stop_daemon(v6);
  if (v4 != nullptr) MHD_stop_daemon(v4);
  state_->stopped_signal.notify_all();
}

}  // namespace rigdesign::studio
